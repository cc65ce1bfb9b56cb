// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_MODEL_REDUCTION_MESH_ARRAYS_H
#define CGAL_MODEL_REDUCTION_MESH_ARRAYS_H

/// \file mesh_arrays.h
/// A triangle mesh (any CGAL `FaceListGraph`, e.g. `Surface_mesh`) as the plain arrays the
/// packages compute on: its points and its faces as index triples, both in the order of the
/// vertex index map, so that row `i` of a result is the vertex of index `i`.

#include <CGAL/Model_reduction/errors.h>
#include <CGAL/Model_reduction/named_function_parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <array>
#include <string>
#include <vector>

namespace CGAL {
namespace Model_reduction {

/// The points of `mesh`, the `i`-th that of the vertex of index `i`.
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map, vertex_index_map} as in CGAL \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws Invalid_mesh (`garbage`) if a vertex index lies outside `[0, num_vertices)` (a
///         `Surface_mesh` with removed elements not collected).
template <class TriangleMesh, class NamedParameters = parameters::Default_named_parameters>
std::vector<std::array<double, 3>> mesh_points(const TriangleMesh& mesh, const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, mesh));
  const auto vim = CGAL::get_initialized_vertex_index_map(mesh, np);
  std::vector<std::array<double, 3>> points(num_vertices(mesh));
  for(auto v : vertices(mesh))
  {
    const auto& p = get(vpm, v);
    const std::size_t i = std::size_t(get(vim, v));
    if(i >= points.size())
      throw Invalid_mesh(Mesh_defect::garbage, "vertex index " + std::to_string(i) + " outside [0, " +
                                                   std::to_string(points.size()) + "): removed elements still stored?");
    points[i] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
  }
  return points;
}

/// The faces of `mesh` as vertex index triples (the vertex index map's indices), in the
/// order of `faces(mesh)`.
/// \throws Invalid_mesh (`non_triangle_face`) naming the face for a face that is not a triangle.
template <class TriangleMesh, class NamedParameters = parameters::Default_named_parameters>
std::vector<std::array<int, 3>> mesh_triangles(const TriangleMesh& mesh, const NamedParameters& np = parameters::default_values())
{
  const auto vim = CGAL::get_initialized_vertex_index_map(mesh, np);
  std::vector<std::array<int, 3>> triangles;
  triangles.reserve(num_faces(mesh));
  for(auto f : faces(mesh))
  {
    std::array<int, 3> t{};
    int k = 0;
    for(auto v : vertices_around_face(halfedge(f, mesh), mesh))
    {
      if(k < 3) t[std::size_t(k)] = int(get(vim, v));
      ++k;
    }
    if(k != 3)
      throw Invalid_mesh(Mesh_defect::non_triangle_face,
                         "face " + std::to_string(triangles.size()) + " has " + std::to_string(k) + " vertices, not 3");
    triangles.push_back(t);
  }
  return triangles;
}

} // namespace Model_reduction
} // namespace CGAL

#endif
