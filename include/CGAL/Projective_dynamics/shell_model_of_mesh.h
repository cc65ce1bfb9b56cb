// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PROJECTIVE_DYNAMICS_SHELL_MODEL_OF_MESH_H
#define CGAL_PROJECTIVE_DYNAMICS_SHELL_MODEL_OF_MESH_H

/// \file shell_model_of_mesh.h
/// A thin front for CGAL triangle meshes (any `FaceListGraph`, e.g. `Surface_mesh`): a shell or
/// cloth model of the mesh, and simulated positions written back to its vertices.  Vertices
/// are numbered by the vertex index map, so the simulator's row `i` is the vertex of index `i`.
/// \code
/// namespace PD = CGAL::Projective_dynamics;
/// PD::Simulator sim(PD::make_shell_model_of_mesh(mesh, PD::parameters::bending_stiffness(1e-3)));
/// sim.step();
/// PD::copy_positions_to_mesh(sim.positions(), mesh);
/// \endcode

#include <CGAL/Model_reduction/mesh_arrays.h>
#include <CGAL/Projective_dynamics/errors.h>
#include <CGAL/Projective_dynamics/make_models.h>
#include <CGAL/Projective_dynamics/named_function_parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <string>
#include <vector>

namespace CGAL {
namespace Projective_dynamics {

/// The vertices of `mesh` in the vertex index map's order, and its faces as index triples.
/// \throws Invalid_mesh (`non_triangle_face`) naming the face for a face that is not a triangle.
template <class TriangleMesh, class NamedParameters = parameters::Default_named_parameters>
void mesh_to_arrays(const TriangleMesh& mesh, std::vector<Point>& points, std::vector<Triangle>& triangles,
                    const NamedParameters& np = parameters::default_values())
{
  points = Model_reduction::mesh_points(mesh, np);
  triangles = Model_reduction::mesh_triangles(mesh, np);
}

/// `make_shell_model` of the mesh's vertices and faces (its named parameters, and
/// `vertex_point_map`, `vertex_index_map` as in CGAL).
template <class TriangleMesh, class NamedParameters = parameters::Default_named_parameters>
Elastic_model make_shell_model_of_mesh(const TriangleMesh& mesh, const NamedParameters& np = parameters::default_values())
{
  std::vector<Point> points;
  std::vector<Triangle> triangles;
  mesh_to_arrays(mesh, points, triangles, np);
  return make_shell_model(points, triangles, np);
}

/// Writes row `i` of `q` to the vertex of index `i` (through `vertex_point_map`, which must be writable).
/// \throws Invalid_input if `q` does not have a row per vertex.
template <class TriangleMesh, class NamedParameters = parameters::Default_named_parameters>
void copy_positions_to_mesh(const Positions& q, TriangleMesh& mesh, const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_property_map(CGAL::vertex_point, mesh));
  typedef typename boost::property_traits<std::remove_const_t<decltype(vpm)>>::value_type Point_3;
  const auto vim = CGAL::get_initialized_vertex_index_map(mesh, np);
  if(q.rows() != Eigen::Index(num_vertices(mesh)))
    throw Invalid_input(std::to_string(q.rows()) + " positions for a mesh of " + std::to_string(num_vertices(mesh)) + " vertices");
  for(auto v : vertices(mesh))
  {
    const Eigen::Index i = Eigen::Index(get(vim, v));
    put(vpm, v, Point_3(q(i, 0), q(i, 1), q(i, 2)));
  }
}

} // namespace Projective_dynamics
} // namespace CGAL

#endif
