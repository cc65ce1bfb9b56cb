// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PROJECTIVE_DYNAMICS_MAKE_MODELS_H
#define CGAL_PROJECTIVE_DYNAMICS_MAKE_MODELS_H

/// \file make_models.h
/// Elastic models of solids (tetrahedra), shells and cloth (triangles) and spring networks,
/// with lumped masses and options as named parameters:
/// \code
/// namespace PD = CGAL::Projective_dynamics;
/// PD::Elastic_model solid = PD::make_solid_model(PD::make_tet_box(10, 4, 4, {0, 0, 0}, {1, .4, .4}),
///                                                PD::parameters::strain_stiffness(1e5).density(1e3));
/// \endcode

#include <CGAL/Projective_dynamics/Elastic_model.h>
#include <CGAL/Projective_dynamics/Tet_mesh.h>
#include <CGAL/Projective_dynamics/named_function_parameters.h>

#include <utility>
#include <vector>

namespace CGAL {
namespace Projective_dynamics {

/// The points as an n x 3 matrix.
Positions to_positions(const std::vector<Point>& points);

/// Lumped masses: each element's measure times `density`, shared equally by its vertices
/// (a quarter of each tetrahedron's volume, a third of each triangle's area, half of each
/// edge's length).  \throws Invalid_input for a density that is not positive.
Eigen::VectorXd lumped_masses(const std::vector<Point>& points, const std::vector<Tetrahedron>& tets, double density);
Eigen::VectorXd lumped_masses(const std::vector<Point>& points, const std::vector<Triangle>& triangles, double density);
Eigen::VectorXd lumped_masses(const std::vector<Point>& points, const std::vector<Edge>& edges, double density);

namespace internal {
struct Model_parameters
{
  double density = 1, spring_stiffness = 1, strain_stiffness = 1, bending_stiffness = 0;
  std::pair<double, double> strain_limits{1, 1};
  bool has_springs = false;
};
template <class NamedParameters>
Model_parameters model_parameters(const NamedParameters& np, double default_strain_stiffness)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Model_parameters p;
  p.density = choose_parameter(get_parameter(np, internal_np::density), p.density);
  p.spring_stiffness = choose_parameter(get_parameter(np, internal_np::spring_stiffness), p.spring_stiffness);
  p.strain_stiffness = choose_parameter(get_parameter(np, internal_np::strain_stiffness), default_strain_stiffness);
  p.bending_stiffness = choose_parameter(get_parameter(np, internal_np::bending_stiffness), p.bending_stiffness);
  p.strain_limits = choose_parameter(get_parameter(np, internal_np::strain_limits), p.strain_limits);
  p.has_springs = !parameters::is_default_parameter<NamedParameters, internal_np::spring_stiffness_t>::value;
  return p;
}
Elastic_model make_solid_model(const Tet_mesh& mesh, const Model_parameters& p);
Elastic_model make_shell_model(const std::vector<Point>& points, const std::vector<Triangle>& triangles,
                               const Model_parameters& p);
Elastic_model make_spring_model(const std::vector<Point>& points, const std::vector<Edge>& edges,
                                const Model_parameters& p);
} // namespace internal

/// A solid: masses from the tetrahedra, group 0 the tetrahedron strain; with `spring_stiffness`
/// given, group 1 springs along the tetrahedra's edges.
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{density} mass per volume; `double`; default 1 \cgalParamNEnd
///   \cgalParamNBegin{strain_stiffness} `k >= 0` of the tetrahedron strain; `double`; default 1 \cgalParamNEnd
///   \cgalParamNBegin{strain_limits} `[rmin, rmax]` of the singular values; `std::pair<double, double>`; default `[1, 1]` \cgalParamNEnd
///   \cgalParamNBegin{spring_stiffness} springs along the edges if given; `double` \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws Invalid_mesh as `check_tet_mesh`; Invalid_input for a bad option.
template <class NamedParameters = parameters::Default_named_parameters>
Elastic_model make_solid_model(const Tet_mesh& mesh, const NamedParameters& np = parameters::default_values())
{
  return internal::make_solid_model(mesh, internal::model_parameters(np, 1.0));
}

/// A shell or cloth: masses from the triangles' areas, group 0 the triangle strain, group 1
/// bending (interior vertices); with `spring_stiffness` given, group 2 springs along the edges.
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{density} mass per area; `double`; default 1 \cgalParamNEnd
///   \cgalParamNBegin{strain_stiffness, strain_limits} of the triangle strain, as for solids \cgalParamNEnd
///   \cgalParamNBegin{bending_stiffness} `>= 0`; `double`; default 0 \cgalParamNEnd
///   \cgalParamNBegin{spring_stiffness} springs along the edges if given; `double` \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws Invalid_mesh for an empty or degenerate input (naming the triangle); Invalid_input for a bad option.
template <class NamedParameters = parameters::Default_named_parameters>
Elastic_model make_shell_model(const std::vector<Point>& points, const std::vector<Triangle>& triangles,
                               const NamedParameters& np = parameters::default_values())
{
  return internal::make_shell_model(points, triangles, internal::model_parameters(np, 1.0));
}

/// A spring network: masses from the edges' lengths (`density` per length), group 0 the springs
/// (`spring_stiffness`, default 1, limits `strain_limits`).
template <class NamedParameters = parameters::Default_named_parameters>
Elastic_model make_spring_model(const std::vector<Point>& points, const std::vector<Edge>& edges,
                                const NamedParameters& np = parameters::default_values())
{
  return internal::make_spring_model(points, edges, internal::model_parameters(np, 1.0));
}

} // namespace Projective_dynamics
} // namespace CGAL

#endif
