// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_FIELD_FILES_H
#define CGAL_TANGENT_VECTOR_FIELDS_FIELD_FILES_H

/// \file field_files.h
/// File formats for looking at fields in other programs, on plain arrays (no mesh
/// type): VTK XML PolyData (`.vtp`, read by ParaView), streamlines as OBJ polylines
/// and as PLY edges, and Directional's `.rawfield`.  `field_export.h` offers the same
/// on property maps of a `TriangleMesh`.
///
/// Every number is written with 17 significant digits, so a write followed by a
/// read gives back the same doubles.

#include <CGAL/Model_reduction/Vtk_polydata.h>
#include <CGAL/Tangent_vector_fields/Streamline_tracer.h>

#include <array>
#include <iosfwd>
#include <utility>
#include <string>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {

// VTK PolyData, shared by every package's exports (Model_reduction/Vtk_polydata.h).
using Model_reduction::Vtk_polydata;
using Model_reduction::read_vtk_polydata;
using Model_reduction::write_vtk_polydata;

/// A mesh with face vector arrays, ready for `write_vtk_polydata`: the triangles are
/// the polygons, each field a 3-component cell array named after it.
Vtk_polydata face_fields_polydata(const std::vector<std::array<double, 3>>& points,
                                  const std::vector<std::array<int, 3>>& triangles,
                                  const std::vector<std::pair<std::string, std::vector<std::array<double, 3>>>>& fields);

/// Streamlines as VTK polylines, with a point array `face` (the face of each point)
/// and cell arrays `closed` (1 for closed loops) and `length`.
Vtk_polydata streamlines_polydata(const std::vector<Streamline>& lines);

/// Writes streamlines as an OBJ file: all points as `v x y z`, then one `l i j k ...`
/// element per streamline (1-based indices).  A closed streamline repeats its first
/// index at the end.
void write_streamlines_obj(std::ostream& out, const std::vector<Streamline>& lines);

/// Writes streamlines as an ASCII PLY file: `element vertex` with `double x, y, z`
/// and `int face`, `int streamline`; `element edge` with `int vertex1, vertex2` (one
/// edge per segment, and the closing edge of a closed streamline).
void write_streamlines_ply(std::ostream& out, const std::vector<Streamline>& lines);

/// \brief A field in Directional's raw format: `degree` vectors per face.
///
/// The file is text: a first line `<degree> <number of faces>`, then one line per
/// face with the `3 * degree` coordinates `x1 y1 z1 x2 y2 z2 ...` of its vectors
/// (Directional's `read_raw_field` and `write_raw_field`).
struct Raw_field
{
  int degree = 1;
  /// `degree` vectors per face, face after face.
  std::vector<std::array<double, 3>> vectors;
  std::size_t number_of_faces() const { return degree > 0 ? vectors.size() / degree : 0; }
};

/// \throws Invalid_input if `degree` is not positive, the vector count is not a
///         multiple of it, or the stream fails.
void write_raw_field(std::ostream& out, const Raw_field& field);
/// \throws Invalid_input for a bad header, missing or non-finite numbers, or extra numbers.
Raw_field read_raw_field(std::istream& in);

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
