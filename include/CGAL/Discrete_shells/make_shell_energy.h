// Copyright (c) 2026 The Discrete_shells authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISCRETE_SHELLS_MAKE_SHELL_ENERGY_H
#define CGAL_DISCRETE_SHELLS_MAKE_SHELL_ENERGY_H

/// \file make_shell_energy.h
/// The shell energy of a CGAL triangle mesh (any `FaceListGraph`, e.g. `Surface_mesh`),
/// and the conversions between per-vertex `Vector_3`/`Point_3` maps and the stacked
/// vectors the energy works with (three entries per vertex, in the vertex index map's order).

#include <CGAL/Discrete_shells/Shell_energy.h>
#include <CGAL/Model_reduction/mesh_arrays.h>
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
  const std::vector<std::array<double, 3>> points = Model_reduction::mesh_points(mesh, np);
  Eigen::VectorXd x(3 * Eigen::Index(points.size()));
  for(std::size_t v = 0; v < points.size(); ++v)
    for(int c = 0; c < 3; ++c) x[3 * Eigen::Index(v) + c] = points[v][std::size_t(c)];
  return x;
}

/// The faces of `mesh` as vertex index triples (the vertex index map's indices).
/// \throws Invalid_mesh naming the face for a face that is not a triangle.
template <class TriangleMesh, class NamedParameters = parameters::Default_named_parameters>
std::vector<Shell_energy::Triangle> mesh_triangles(const TriangleMesh& mesh,
                                                   const NamedParameters& np = parameters::default_values())
{
  return Model_reduction::mesh_triangles(mesh, np);
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
