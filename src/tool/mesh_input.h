// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reading a mesh file as CGAL reads it, a polygon soup (before any repair), with the face
// fields a PLY file stores as face properties.  No Surface_mesh here: tool_mesh.cpp makes
// the mesh (Model_reduction::polygon_soup_to_mesh).

#ifndef TVF_TOOL_MESH_INPUT_H
#define TVF_TOOL_MESH_INPUT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <string>
#include <utility>
#include <vector>

namespace tvf_tool {

/// The contents of a mesh file.
struct Mesh_file
{
  std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  /// The `double` and `float` face properties of a PLY file, one value per polygon in the
  /// file's order (what `--field-ply NAME` reads as `NAME_x`, `NAME_y`, `NAME_z`).
  std::vector<std::pair<std::string, std::vector<double>>> face_properties;

  /// The names NAME of the face fields, those with properties NAME_x, NAME_y and NAME_z.
  std::vector<std::string> face_field_names() const;
  /// The vectors of face field `name`, one per polygon; empty if there is no such field.
  std::vector<std::array<double, 3>> face_field(const std::string& name) const;
};

/// Reads `path` by its extension (.off, .obj, .ply, .stl, .ts, in any case).
/// \throws Tool_error if the file cannot be opened, has an unknown extension, or CGAL
///         cannot read it.  A file without polygons is returned as such.
Mesh_file read_mesh_file(const std::string& path);

} // namespace tvf_tool

#endif
