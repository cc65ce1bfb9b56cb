// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_MODEL_REDUCTION_MESH_REPAIR_REPORT_H
#define CGAL_MODEL_REDUCTION_MESH_REPAIR_REPORT_H

/// \file Mesh_repair_report.h
/// What `polygon_soup_to_mesh` changed on the way from a polygon soup to a mesh.

#include <cstddef>
#include <ostream>
#include <string>

namespace CGAL {
namespace Model_reduction {

/// \brief The changes `polygon_soup_to_mesh` made, counted; all zero for a soup that
/// was a mesh the package accepts.
struct Mesh_repair_report
{
  std::size_t number_of_points = 0;   ///< points of the soup
  std::size_t number_of_polygons = 0; ///< polygons of the soup
  std::size_t number_of_vertices = 0; ///< vertices of the mesh made (isolated points and copies included)
  std::size_t number_of_faces = 0;    ///< faces (triangles) of the mesh made

  std::size_t simplified_polygons = 0;         ///< polygons that repeated a vertex consecutively (the repeat dropped)
  std::size_t split_polygons = 0;              ///< pinched polygons (visiting a vertex twice) split into simple ones
  std::size_t removed_degenerate_polygons = 0; ///< polygons with fewer than three distinct vertices, removed
  std::size_t removed_duplicate_polygons = 0;  ///< polygons with the vertices of an earlier one, removed
  std::size_t triangulated_polygons = 0;       ///< polygons of more than three vertices ...
  std::size_t triangles_from_polygons = 0;     ///< ... and the triangles they became
  std::size_t reoriented_polygons = 0;         ///< polygons whose orientation was reversed
  std::size_t non_manifold_vertices = 0;       ///< vertices whose faces formed several fans (or on a cut edge)
  std::size_t non_manifold_edges = 0;          ///< edges of more than two polygons, cut apart
  std::size_t duplicated_vertices = 0;         ///< vertex copies added to make the mesh manifold and oriented

  /// True if face `i` of the mesh is polygon `i` of the soup for every `i` (its
  /// orientation may be reversed): no polygon was split, triangulated or removed, so
  /// per-polygon data need no mapping.
  bool faces_match_polygons = true;

  /// True if anything was changed.
  bool changed() const
  {
    return simplified_polygons + split_polygons + removed_degenerate_polygons + removed_duplicate_polygons +
               triangulated_polygons + reoriented_polygons + duplicated_vertices + non_manifold_edges >
           0;
  }

  /// The changes in one line, e.g. "6 polygons triangulated into 12 triangles, 3 polygons
  /// reoriented"; "no repairs" if nothing changed.
  std::string summary() const
  {
    auto count = [](std::size_t n, const std::string& one, const std::string& many) {
      return std::to_string(n) + " " + (n == 1 ? one : many);
    };
    std::string s;
    auto add = [&s](const std::string& part) { s += (s.empty() ? "" : ", ") + part; };
    const std::string polygon = "polygon", polygons = "polygons";
    if(simplified_polygons) add(count(simplified_polygons, polygon, polygons) + " with a repeated vertex simplified");
    if(split_polygons) add(count(split_polygons, "pinched polygon", "pinched polygons") + " split");
    if(removed_degenerate_polygons)
      add(count(removed_degenerate_polygons, "degenerate polygon", "degenerate polygons") + " removed");
    if(removed_duplicate_polygons)
      add(count(removed_duplicate_polygons, "duplicate polygon", "duplicate polygons") + " removed");
    if(triangulated_polygons)
      add(count(triangulated_polygons, polygon, polygons) + " triangulated into " +
          count(triangles_from_polygons, "triangle", "triangles"));
    if(reoriented_polygons) add(count(reoriented_polygons, polygon, polygons) + " reoriented");
    if(non_manifold_edges) add(count(non_manifold_edges, "non-manifold edge", "non-manifold edges") + " cut apart");
    if(duplicated_vertices)
      add(count(non_manifold_vertices, "non-manifold vertex", "non-manifold vertices") + " duplicated (" +
          count(duplicated_vertices, "new vertex", "new vertices") + ")");
    return s.empty() ? "no repairs" : s;
  }
};

inline std::ostream& operator<<(std::ostream& out, const Mesh_repair_report& report)
{
  return out << report.summary();
}

} // namespace Model_reduction
} // namespace CGAL

#endif
