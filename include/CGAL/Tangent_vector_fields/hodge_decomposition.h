// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_HODGE_DECOMPOSITION_H
#define CGAL_TANGENT_VECTOR_FIELDS_HODGE_DECOMPOSITION_H

/// \file hodge_decomposition.h
/// The discrete Hodge decomposition `v = G f + J G* g + h` of a face field
/// (SPEC section 4), as a class that keeps its factorisations and as a function.

#include <CGAL/Tangent_vector_fields/Discrete_operators.h>
#include <CGAL/Tangent_vector_fields/Hodge_solver.h>

namespace CGAL {
namespace Tangent_vector_fields {

/// \brief Hodge decomposition of tangent fields on one mesh, for many fields.
///
/// Like `CGAL::Heat_method_3`, it is built once per mesh; the factorisations of the
/// two Laplacians and the harmonic basis are computed on first need and reused by
/// every later call.  Constructor named parameters: those of `Discrete_operators`.
template <class TriangleMesh>
class Hodge_decomposition
{
public:
  typedef Discrete_operators<TriangleMesh> Operators;

  template <class NamedParameters = parameters::Default_named_parameters>
  explicit Hodge_decomposition(const TriangleMesh& mesh, const NamedParameters& np = parameters::default_values())
    : operators_(mesh, np), solver_(operators_.shared_matrices())
  {}

  const Operators& operators() const { return operators_; }
  const Hodge_solver& solver() const { return solver_; }
  const Mesh_topology& topology() const { return operators_.topology(); }
  /// `dim H` from the topology: `sum(2g + max(b - 1, 0))` over components.
  int harmonic_dimension() const { return solver_.harmonic_dimension(); }

  /// \brief Decomposes `field`, writing only the parts named in `np`.
  ///
  /// Named parameters (all optional; what is not asked for is not computed):
  /// - `exact_part_map`: face map receiving the curl-free part `G f`;
  /// - `coexact_part_map`: face map receiving the divergence-free part `J G* g`;
  /// - `harmonic_part_map`: face map receiving the harmonic part `h` (needs both potentials);
  /// - `potential_map`: vertex map receiving `f` (zero mean per component);
  /// - `copotential_map`: edge map receiving `g` (zero on boundary edges, zero mean
  ///   per closed component).
  ///
  /// \throws Invalid_input if the field has non-finite vectors; no map is written then.
  template <class FaceVectorMap, class NamedParameters = parameters::Default_named_parameters>
  void operator()(const FaceVectorMap& field, const NamedParameters& np = parameters::default_values()) const
  {
    using parameters::get_parameter;
    using parameters::is_default_parameter;
    unsigned outputs = 0;
    if(!is_default_parameter<NamedParameters, internal_np::exact_part_map_t>::value) outputs |= hodge_exact;
    if(!is_default_parameter<NamedParameters, internal_np::coexact_part_map_t>::value) outputs |= hodge_coexact;
    if(!is_default_parameter<NamedParameters, internal_np::harmonic_part_map_t>::value) outputs |= hodge_harmonic;
    if(!is_default_parameter<NamedParameters, internal_np::potential_map_t>::value) outputs |= hodge_potential;
    if(!is_default_parameter<NamedParameters, internal_np::copotential_map_t>::value) outputs |= hodge_copotential;
    if(outputs == 0) return;

    const Hodge_parts parts = solver_.decompose(operators_.to_frame_coordinates(field), outputs);
    write_field(parts.exact, get_parameter(np, internal_np::exact_part_map));
    write_field(parts.coexact, get_parameter(np, internal_np::coexact_part_map));
    write_field(parts.harmonic, get_parameter(np, internal_np::harmonic_part_map));
    write_scalars(operators_.adapter().vertices(), parts.potential, get_parameter(np, internal_np::potential_map));
    write_scalars(operators_.adapter().edges(), parts.copotential, get_parameter(np, internal_np::copotential_map));
  }

  /// Writes the `i`-th field of an `MX`-orthonormal harmonic basis into `field`.
  /// \pre `0 <= i < harmonic_dimension()`
  template <class FaceVectorMap>
  void harmonic_basis_field(int i, FaceVectorMap field) const
  {
    if(i < 0 || i >= harmonic_dimension())
      throw Invalid_input("harmonic basis index " + std::to_string(i) + " outside [0, " +
                          std::to_string(harmonic_dimension()) + ")");
    operators_.from_frame_coordinates(solver_.harmonic_basis().col(i), field);
  }

private:
  void write_field(const Eigen::VectorXd&, CGAL::internal_np::Param_not_found) const {}
  template <class FaceVectorMap>
  void write_field(const Eigen::VectorXd& x, FaceVectorMap map) const
  {
    operators_.from_frame_coordinates(x, map);
  }
  template <class Elements>
  static void write_scalars(const Elements&, const Eigen::VectorXd&, CGAL::internal_np::Param_not_found) {}
  template <class Elements, class ScalarMap>
  static void write_scalars(const Elements& elements, const Eigen::VectorXd& x, ScalarMap map)
  {
    Operators::Adapter::write_values(elements, x, map);
  }

  Operators operators_;
  Hodge_solver solver_;
};

/// \brief Hodge decomposition of one face field: `field = exact + coexact + harmonic`.
///
/// Builds the operators and only the factorisations that the requested outputs need
/// (the potential alone needs one Laplacian, the harmonic part both).  For several
/// fields on one mesh, use the class `Hodge_decomposition`, which keeps them.
///
/// \param mesh a triangle mesh (see `Discrete_operators` for requirements)
/// \param field a readable face property map with `Vector_3` values
/// \param np named parameters: the outputs of `Hodge_decomposition::operator()` and
///        the options of `Discrete_operators` (`vertex_point_map`, index maps,
///        `use_intrinsic_mollification`, ...), in one chain.
template <class TriangleMesh, class FaceVectorMap, class NamedParameters = parameters::Default_named_parameters>
void hodge_decomposition(const TriangleMesh& mesh, const FaceVectorMap& field,
                         const NamedParameters& np = parameters::default_values())
{
  Hodge_decomposition<TriangleMesh> decomposition(mesh, np);
  decomposition(field, np);
}

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
