// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_MODEL_REDUCTION_VTK_POLYDATA_H
#define CGAL_MODEL_REDUCTION_VTK_POLYDATA_H

/// \file Vtk_polydata.h
/// VTK XML PolyData (`.vtp`, read by ParaView) on plain arrays: every package writes its
/// meshes, fields, modes and curves through it.  Numbers are written with 17 significant
/// digits, so a write followed by a read gives back the same doubles.

#include <array>
#include <iosfwd>
#include <string>
#include <vector>

namespace CGAL {
namespace Model_reduction {

/// \brief The part of a VTK PolyData data set this package writes and reads: points,
/// polygons, polylines, and named arrays on points and on cells.
///
/// VTK numbers cells lines first, then polygons: a cell array has one tuple per line
/// followed by one per polygon.
struct Vtk_polydata
{
  struct Array
  {
    std::string name;
    int components = 1;
    std::vector<double> values; ///< `components` values per tuple
    std::size_t number_of_tuples() const { return components > 0 ? values.size() / components : 0; }
  };

  std::vector<std::array<double, 3>> points;
  std::vector<std::vector<int>> lines;    ///< polylines, as point indices
  std::vector<std::vector<int>> polygons; ///< polygons, as point indices
  std::vector<Array> point_data;
  std::vector<Array> cell_data;

  std::size_t number_of_cells() const { return lines.size() + polygons.size(); }
  /// The cell (or point) array called `name`, or null.
  const Array* find_cell_array(const std::string& name) const;
  const Array* find_point_array(const std::string& name) const;
};

/// Writes `data` as a VTK XML PolyData file (`<VTKFile type="PolyData">`, ASCII data
/// arrays: `Float64` for points and arrays, `Int64` for connectivity and offsets).
/// The first 3-component cell array is marked as the cells' active vectors.
/// \throws Invalid_input if an index or an array size does not fit, or the stream fails.
void write_vtk_polydata(std::ostream& out, const Vtk_polydata& data);

/// Reads a VTK XML PolyData file with ASCII data arrays (`format="ascii"`; the
/// `binary` and `appended` formats are refused): points, lines, polygons, point and
/// cell data arrays of any numeric type (read as `double`).  Vertices and strips are
/// refused.
/// \throws Invalid_input for anything else or a malformed file.
Vtk_polydata read_vtk_polydata(std::istream& in);

namespace internal {
/// Imbues the classic locale and 17 significant digits (exact doubles in text files).
void prepare_exact_output(std::ostream& out);
/// \throws Invalid_input "writing the <what> failed" if `out` failed.
void check_written(const std::ostream& out, const char* what);
} // namespace internal

} // namespace Model_reduction
} // namespace CGAL

#endif
