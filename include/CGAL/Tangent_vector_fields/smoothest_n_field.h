// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_SMOOTHEST_N_FIELD_H
#define CGAL_TANGENT_VECTOR_FIELDS_SMOOTHEST_N_FIELD_H

/// \file smoothest_n_field.h
/// The smoothest n-direction field of a mesh (Knoeppel et al. 2013, with the weights of
/// SPEC 10), optionally aligned to a guide field, and the singularities of an n-field,
/// on any `TriangleMesh` with face property maps of 3D vectors.

#include <CGAL/Tangent_vector_fields/N_field_singularities.h>
#include <CGAL/Tangent_vector_fields/Smoothest_n_field_solver.h>
#include <CGAL/Tangent_vector_fields/internal/Mesh_adapter.h>
#include <CGAL/Tangent_vector_fields/named_function_parameters.h>

#include <Eigen/Core>

#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {

namespace internal {

template <class TriangleMesh, class NamedParameters>
std::shared_ptr<const N_field_operators> n_field_operators(const Mesh_adapter<TriangleMesh>& adapter, int n,
                                                           const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  N_field_options options;
  options.boundary = choose_parameter(get_parameter(np, internal_np::n_field_boundary), N_field_boundary::free);
  return std::make_shared<const N_field_operators>(std::make_shared<const Operator_matrices>(adapter.intrinsic_mesh()),
                                                   n, options);
}

} // namespace internal

/// \brief Writes the smoothest n-field of `mesh` into `field`: per face the first of its
/// n unit vectors (the others follow counter-clockwise at angles `2 pi j / n`); faces where
/// the field vanishes get the zero vector.
///
/// \param mesh a triangle mesh (see `Discrete_operators` for requirements)
/// \param n the symmetry: 1 vector field, 2 line field, 4 cross field, ... (n >= 1)
/// \param field a writable face property map with `Vector_3` values
/// \param np named parameters:
/// - `alignment_field_map`: a readable face map of `Vector_3`, any one of the n vectors of
///   the guide per face (its length weighs the face; a zero vector leaves the face free);
///   default: none (the smoothest field is an eigenvector).
/// - `alignment_weight` (double, default 1): `s` of `E_D + s |z - guide|^2`, for the mesh
///   scaled to unit area, so the result does not depend on the mesh's scale.
/// - `n_field_boundary` (`N_field_boundary`, default `free`).
/// - `eigensolver_tolerance` (double, default 1e-10).
/// - the options of `Discrete_operators` (`vertex_point_map`, index maps, mollification).
/// \returns the singularities of the field (vertex, k: index k/n), as `n_field_singularities`.
template <class TriangleMesh, class FaceVectorMap, class NamedParameters = parameters::Default_named_parameters>
std::vector<std::pair<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, int>>
smoothest_n_field(const TriangleMesh& mesh, int n, FaceVectorMap field,
                  const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  internal::Mesh_adapter<TriangleMesh> adapter(mesh, np);
  const auto operators = internal::n_field_operators(adapter, n, np);
  Smoothest_n_field_options options;
  options.tolerance = choose_parameter(get_parameter(np, internal_np::eigensolver_tolerance), options.tolerance);
  options.alignment_weight = choose_parameter(get_parameter(np, internal_np::alignment_weight), options.alignment_weight);
  if constexpr(!is_default_parameter<NamedParameters, internal_np::alignment_field_map_t>::value)
    options.alignment = operators->from_vectors(adapter.read_field(get_parameter(np, internal_np::alignment_field_map)));
  const Eigen::VectorXd z = smoothest_n_field(*operators, options);
  adapter.write_field(operators->to_vectors(operators->normalized(z)), field);
  std::vector<std::pair<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, int>> singular;
  for(const N_field_singularity& s : n_field_singularities(*operators, z))
    singular.emplace_back(adapter.vertices()[s.vertex], s.index);
  return singular;
}

/// \brief The index of the n-field `field` at every vertex, written into `index` as the
/// integer `k` (the index is `k / n`; see `n_field_indices` for the definition at interior
/// and boundary vertices).  Their sum is `n` times the Euler characteristic.
///
/// \param field a readable face map of `Vector_3`: any one of the n vectors per face
/// \param index a writable vertex map with integer values
/// \param np the options of `Discrete_operators`
/// \returns the vertices with a non-zero index, with their `k`.
template <class TriangleMesh, class FaceVectorMap, class VertexIndexMap,
          class NamedParameters = parameters::Default_named_parameters>
std::vector<std::pair<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, int>>
n_field_singularities(const TriangleMesh& mesh, int n, const FaceVectorMap& field, VertexIndexMap index,
                      const NamedParameters& np = parameters::default_values())
{
  internal::Mesh_adapter<TriangleMesh> adapter(mesh, np);
  const auto operators = internal::n_field_operators(adapter, n, np);
  const std::vector<int> k = n_field_indices(*operators, operators->from_vectors(adapter.read_field(field)));
  std::vector<std::pair<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, int>> singular;
  for(std::size_t v = 0; v < k.size(); ++v)
  {
    put(index, adapter.vertices()[v], k[v]);
    if(k[v] != 0) singular.emplace_back(adapter.vertices()[v], k[v]);
  }
  return singular;
}

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
