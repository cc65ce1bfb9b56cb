// Copyright (c) 2026 The Discrete_shells authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISCRETE_SHELLS_MAKE_SHELL_ENERGY_H
#define CGAL_DISCRETE_SHELLS_MAKE_SHELL_ENERGY_H

/// \file make_shell_energy.h
/// The shell energy of a CGAL triangle mesh (any `FaceListGraph`, e.g. `Surface_mesh`),
/// and the conversions between per-vertex `Vector_3`/`Point_3` maps and the stacked
/// vectors the energy works with (three entries per vertex, in the vertex index map's order).

#include <CGAL/Discrete_shells/Shell_energy.h>
#include <CGAL/Discrete_shells/errors.h>
#include <CGAL/Discrete_shells/named_function_parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <string>
#include <vector>

namespace CGAL {
namespace Discrete_shells {

/// The rest positions of `mesh`, stacked in the vertex index map's order.
template <class TriangleMesh, class NamedParameters = parameters::Default_named_parameters>
Eigen::VectorXd stacked_positions(const TriangleMesh& mesh, const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, mesh));
  const auto vim = CGAL::get_initialized_vertex_index_map(mesh, np);
  Eigen::VectorXd x(3 * Eigen::Index(num_vertices(mesh)));
  for(auto v : vertices(mesh))
  {
    const auto& p = get(vpm, v);
    const Eigen::Index i = 3 * Eigen::Index(get(vim, v));
    x[i] = CGAL::to_double(p.x()), x[i + 1] = CGAL::to_double(p.y()), x[i + 2] = CGAL::to_double(p.z());
  }
  return x;
}

/// The faces of `mesh` as vertex index triples (the vertex index map's indices).
/// \throws Invalid_mesh naming the face for a face that is not a triangle.
template <class TriangleMesh, class NamedParameters = parameters::Default_named_parameters>
std::vector<Shell_energy::Triangle> mesh_triangles(const TriangleMesh& mesh,
                                                   const NamedParameters& np = parameters::default_values())
{
  const auto vim = CGAL::get_initialized_vertex_index_map(mesh, np);
  std::vector<Shell_energy::Triangle> triangles;
  triangles.reserve(num_faces(mesh));
  for(auto f : faces(mesh))
  {
    Shell_energy::Triangle t;
    int k = 0;
    for(auto v : vertices_around_face(halfedge(f, mesh), mesh))
    {
      if(k < 3) t[k] = int(get(vim, v));
      ++k;
    }
    if(k != 3)
      throw Invalid_mesh(Mesh_defect::non_triangle_face,
                         "face " + std::to_string(triangles.size()) + " has " + std::to_string(k) + " vertices, not 3");
    triangles.push_back(t);
  }
  return triangles;
}

/// The stiffnesses given as named parameters (defaults 1).
template <class NamedParameters>
Shell_stiffness shell_stiffness(const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Shell_stiffness k;
  k.stretching = choose_parameter(get_parameter(np, internal_np::stretching_stiffness), 1.0);
  k.area = choose_parameter(get_parameter(np, internal_np::area_stiffness), 1.0);
  k.bending = choose_parameter(get_parameter(np, internal_np::bending_stiffness), 1.0);
  return k;
}

/// The shell energy with `mesh` as its rest shape.
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{stretching_stiffness} `k_s >= 0`; `double`; default 1 \cgalParamNEnd
///   \cgalParamNBegin{area_stiffness} `k_a >= 0`; `double`; default 1 \cgalParamNEnd
///   \cgalParamNBegin{bending_stiffness} `k_b >= 0` (a squared length times `k_s`: about
///     `h^2 / 12` for thickness `h`); `double`; default 1 \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map} default `get(CGAL::vertex_point, mesh)` \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map} the order of the stacked unknowns \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws Invalid_mesh naming the face for a face that is not a triangle or is degenerate;
///         Invalid_input for a bad stiffness.
template <class TriangleMesh, class NamedParameters = parameters::Default_named_parameters>
Shell_energy make_shell_energy(const TriangleMesh& mesh, const NamedParameters& np = parameters::default_values())
{
  return Shell_energy(stacked_positions(mesh, np), mesh_triangles(mesh, np), shell_stiffness(np));
}

} // namespace Discrete_shells
} // namespace CGAL

#endif
