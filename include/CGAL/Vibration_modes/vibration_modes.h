// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_VIBRATION_MODES_VIBRATION_MODES_H
#define CGAL_VIBRATION_MODES_VIBRATION_MODES_H

/// \file vibration_modes.h
/// Vibration modes of a CGAL triangle mesh as an elastic shell, ordinary or compressed,
/// and the modes as per-vertex `Vector_3` property maps:
/// \code
/// namespace VM = CGAL::Vibration_modes;
/// VM::Modes modes = VM::compressed_vibration_modes(mesh, 20, VM::parameters::sparsity_weight(2.0)
///                                                      .bending_stiffness(1e-3).pinned_vertices(feet));
/// auto u = mesh.add_property_map<vertex_descriptor, Vector_3>("v:mode").first;
/// VM::copy_mode_to_vertex_map(mesh, modes, 0, u);
/// \endcode

#include <CGAL/Discrete_shells/make_shell_energy.h>
#include <CGAL/Vibration_modes/compressed_modes.h>
#include <CGAL/Vibration_modes/errors.h>
#include <CGAL/Vibration_modes/lowest_vibration_modes.h>
#include <CGAL/Vibration_modes/named_function_parameters.h>

#include <functional>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Vibration_modes {

namespace internal {

template <class TriangleMesh, class NamedParameters>
Mode_problem shell_problem_of_mesh(const TriangleMesh& mesh, const NamedParameters& np)
{
  std::vector<int> pinned;
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::pinned_vertices_t>::value)
  {
    const auto vim = CGAL::get_initialized_vertex_index_map(mesh, np);
    for(const auto& v : parameters::get_parameter_reference(np, internal_np::pinned_vertices))
      pinned.push_back(int(get(vim, v)));
  }
  return shell_mode_problem(Discrete_shells::make_shell_energy(mesh, np), pinned);
}

template <class NamedParameters>
Model_reduction::Eigensolver_options eigensolver_options(const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Model_reduction::Eigensolver_options o;
  o.tolerance = choose_parameter(get_parameter(np, internal_np::eigensolver_tolerance), o.tolerance);
  o.seed = choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), o.seed);
  return o;
}

} // namespace internal

/// The matrices `vibration_modes` solves for `mesh` as a discrete shell: the rest Hessian and
/// lumped mass over the vertices not pinned, and the rigid motions the pins leave free; what
/// the uses of modes (`linear_simulation.h`, `Elastic_deformer.h`) work on.
/// Named parameters: the shell's stiffnesses, `pinned_vertices`, `vertex_point_map`, `vertex_index_map`.
template <class TriangleMesh, class NamedParameters = parameters::Default_named_parameters>
Mode_problem mesh_mode_problem(const TriangleMesh& mesh, const NamedParameters& np = parameters::default_values())
{
  return internal::shell_problem_of_mesh(mesh, np);
}

/// The `count` lowest vibration modes of `mesh` as a discrete shell (SPEC 13.2), after the
/// rigid motions left free by the pins.
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{stretching_stiffness, area_stiffness, bending_stiffness} the shell's
///     stiffnesses (`Discrete_shells::make_shell_energy`) \cgalParamNEnd
///   \cgalParamNBegin{pinned_vertices} a range of vertex descriptors held in place; default none \cgalParamNEnd
///   \cgalParamNBegin{eigensolver_tolerance} relative residual of every mode; default 1e-10 \cgalParamNEnd
///   \cgalParamNBegin{random_seed} the eigensolver's start vectors; default 1 \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map, vertex_index_map} as in CGAL \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns modes over `3 * num_vertices(mesh)` unknowns in the vertex index map's order.
/// \throws Invalid_mesh for a face that is not a triangle or is degenerate; Invalid_input as
///         `lowest_vibration_modes` (too many modes, a mechanism) or for a pinned vertex
///         outside the mesh.
template <class TriangleMesh, class NamedParameters = parameters::Default_named_parameters>
Modes vibration_modes(const TriangleMesh& mesh, int count, const NamedParameters& np = parameters::default_values())
{
  return lowest_vibration_modes(internal::shell_problem_of_mesh(mesh, np), count, internal::eigensolver_options(np));
}

/// `count` compressed vibration modes of `mesh` as a discrete shell (SPEC 13.3).
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{sparsity_weight} `mu >= 0`; `double`; default 0 (the ordinary modes) \cgalParamNEnd
///   \cgalParamNBegin{l1_budget} instead of `sparsity_weight`: `|u|_{1,M} <= l1_budget` (> 0); `double`; default infinity (none) \cgalParamNEnd
///   \cgalParamNBegin{progress_callback} `bool(const Compressed_mode_progress&)`, false cancels \cgalParamNEnd
///   \cgalParamNBegin{...} and those of `vibration_modes` \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws as `vibration_modes`, and Cancelled.
template <class TriangleMesh, class NamedParameters = parameters::Default_named_parameters>
Modes compressed_vibration_modes(const TriangleMesh& mesh, int count,
                                 const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Compressed_mode_options o;
  o.sparsity_weight = choose_parameter(get_parameter(np, internal_np::sparsity_weight), 0.0);
  o.l1_budget = choose_parameter(get_parameter(np, internal_np::l1_budget), o.l1_budget);
  o.eigensolver = internal::eigensolver_options(np);
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::progress_callback_t>::value)
    o.progress = get_parameter(np, internal_np::progress_callback);
  return compressed_modes(internal::shell_problem_of_mesh(mesh, np), count, o);
}

/// Writes a displacement over all `3 * num_vertices(mesh)` unknowns (a mode, a frame of a
/// `Linear_trajectory`, an elastic deformer's displacement) into `vector_map` (vertex descriptor
/// -> `Vector_3`), in the vertex index map's order.
/// \throws Invalid_input if `u` does not have 3 entries per vertex; nothing is written then.
template <class TriangleMesh, class VectorMap, class NamedParameters = parameters::Default_named_parameters>
void copy_displacement_to_vertex_map(const TriangleMesh& mesh, const Eigen::VectorXd& u, VectorMap vector_map,
                                     const NamedParameters& np = parameters::default_values())
{
  typedef typename boost::property_traits<VectorMap>::value_type Vector_3;
  if(u.size() != 3 * Eigen::Index(num_vertices(mesh)))
    throw Invalid_input("a displacement of " + std::to_string(u.size()) + " entries, not 3 per vertex of the mesh");
  const auto vim = CGAL::get_initialized_vertex_index_map(mesh, np);
  for(auto v : vertices(mesh))
  {
    const Eigen::Index k = 3 * Eigen::Index(get(vim, v));
    put(vector_map, v, Vector_3(u[k], u[k + 1], u[k + 2]));
  }
}

/// The values of a per-vertex `Vector_3` map stacked as the unknowns are (3 per vertex, in the
/// vertex index map's order): forces and initial states of a `Linear_simulation_options`.
/// \throws Invalid_input naming the vertex for a non-finite value.
template <class TriangleMesh, class VectorMap, class NamedParameters = parameters::Default_named_parameters>
Eigen::VectorXd stacked_vertex_vectors(const TriangleMesh& mesh, VectorMap vector_map,
                                       const NamedParameters& np = parameters::default_values())
{
  const auto vim = CGAL::get_initialized_vertex_index_map(mesh, np);
  Eigen::VectorXd u(3 * Eigen::Index(num_vertices(mesh)));
  for(auto v : vertices(mesh))
  {
    const auto& value = get(vector_map, v);
    const Eigen::Index k = 3 * Eigen::Index(get(vim, v));
    u[k] = CGAL::to_double(value.x()), u[k + 1] = CGAL::to_double(value.y()), u[k + 2] = CGAL::to_double(value.z());
    if(!u.segment<3>(k).allFinite())
      throw Invalid_input("the vector of vertex " + std::to_string(get(vim, v)) + " is not finite");
  }
  return u;
}

/// Writes mode `i` of `modes` into `vector_map` (vertex descriptor -> `Vector_3`).
template <class TriangleMesh, class VectorMap, class NamedParameters = parameters::Default_named_parameters>
void copy_mode_to_vertex_map(const TriangleMesh& mesh, const Modes& modes, int i, VectorMap vector_map,
                             const NamedParameters& np = parameters::default_values())
{
  if(i < 0 || i >= modes.vectors.cols())
    throw Invalid_input("mode " + std::to_string(i) + " asked for, " + std::to_string(modes.vectors.cols()) +
                        " computed");
  if(modes.vectors.rows() != 3 * Eigen::Index(num_vertices(mesh)))
    throw Invalid_input("the modes have " + std::to_string(modes.vectors.rows()) + " entries, not 3 per vertex of the mesh");
  copy_displacement_to_vertex_map(mesh, modes.vectors.col(i), vector_map, np);
}

} // namespace Vibration_modes
} // namespace CGAL

#endif
