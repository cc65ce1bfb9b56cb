// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_SPECTRAL_BASIS_H
#define CGAL_TANGENT_VECTOR_FIELDS_SPECTRAL_BASIS_H

/// \file Spectral_basis.h
/// The Fourier basis of tangent fields on a triangle mesh (SPEC 5 and 6): eigenfields
/// of the Hodge-Laplacian, with transforms, energies, filters and compression of
/// face-field property maps.

#include <CGAL/Tangent_vector_fields/Discrete_operators.h>
#include <CGAL/Tangent_vector_fields/Eigenfield_basis.h>
#include <CGAL/Tangent_vector_fields/Hodge_solver.h>
#include <CGAL/Tangent_vector_fields/Spectral_filter.h>

#include <memory>
#include <string>
#include <utility>

namespace CGAL {
namespace Tangent_vector_fields {

namespace internal {

/// The basis request and options named in `np` (see `Spectral_basis`).
template <class NamedParameters>
std::pair<Basis_request, Basis_options> basis_request(const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  Basis_request request;
  const bool per_type = !is_default_parameter<NamedParameters, internal_np::number_of_exact_eigenfields_t>::value ||
                        !is_default_parameter<NamedParameters, internal_np::number_of_coexact_eigenfields_t>::value;
  if(per_type)
    request = Basis_request::per_type(choose_parameter(get_parameter(np, internal_np::number_of_exact_eigenfields), 0),
                                      choose_parameter(get_parameter(np, internal_np::number_of_coexact_eigenfields), 0));
  else if(!is_default_parameter<NamedParameters, internal_np::maximum_eigenvalue_t>::value)
    request = Basis_request::below(choose_parameter(get_parameter(np, internal_np::maximum_eigenvalue), 0.));
  else
    request = Basis_request::lowest(choose_parameter(get_parameter(np, internal_np::number_of_eigenfields), 100));
  Basis_options options;
  options.tolerance = choose_parameter(get_parameter(np, internal_np::eigensolver_tolerance), options.tolerance);
  options.seed = choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), options.seed);
  options.progress = choose_parameter(get_parameter(np, internal_np::progress_callback),
                                      std::function<void(const Spectral_progress&)>());
  return {request, options};
}

} // namespace internal

/// \brief Eigenfields of the Hodge-Laplacian of a triangle mesh: a Fourier basis for
/// piecewise-constant tangent fields.
///
/// Computed once (the expensive part), then used for any number of transforms,
/// filters and compressions; `save` and `load` keep a basis across runs.  Fields are
/// face property maps with `Vector_3` values (projected onto their faces).
///
/// Named parameters of the constructor (besides those of `Discrete_operators`):
/// - `number_of_eigenfields` (int, default 100): the `d` lowest eigenfields, harmonic
///   ones first;
/// - `number_of_exact_eigenfields`, `number_of_coexact_eigenfields` (int): instead,
///   exactly so many of each type, plus all harmonic fields (the thesis' 500 + 500);
/// - `maximum_eigenvalue` (double): instead, every eigenfield with eigenvalue up to this;
/// - `eigensolver_tolerance` (double, default 1e-10): relative residual required of
///   every eigenpair;
/// - `random_seed` (unsigned, default 1): start vectors and harmonic projections;
/// - `progress_callback` (`std::function<void(const Spectral_progress&)>`).
///
/// \throws Invalid_input if more eigenfields are asked for than the mesh has (`2 nf`).
/// \throws Numerical_failure if an eigenpair misses the tolerance or an eigenvalue
///         was skipped (Sylvester inertia check).
template <class TriangleMesh>
class Spectral_basis
{
public:
  typedef Discrete_operators<TriangleMesh> Operators;

  template <class NamedParameters = parameters::Default_named_parameters>
  explicit Spectral_basis(const TriangleMesh& mesh, const NamedParameters& np = parameters::default_values())
    : operators_(mesh, np)
  {
    const auto request = internal::basis_request(np);
    basis_ = std::make_shared<Eigenfield_basis>(std::make_shared<Hodge_solver>(operators_.shared_matrices()),
                                                request.first, request.second);
  }

  /// Reads a basis saved by `save` for this mesh (`np`: options of `Discrete_operators`).
  /// \throws Invalid_input if the file does not belong to this mesh, or is unreadable.
  template <class NamedParameters = parameters::Default_named_parameters>
  static Spectral_basis load(const TriangleMesh& mesh, const std::string& path,
                             const NamedParameters& np = parameters::default_values())
  {
    Operators operators(mesh, np);
    auto basis = std::make_shared<Eigenfield_basis>(
        Eigenfield_basis::load(std::make_shared<Hodge_solver>(operators.shared_matrices()), path));
    return Spectral_basis(std::move(operators), std::move(basis));
  }

  /// Writes the basis to a versioned binary file that `load` checks against the mesh.
  void save(const std::string& path) const { basis_->save(path); }

  const Operators& operators() const { return operators_; }
  /// The basis on frame coordinates (eigenvalues, eigenfunctions, report).
  const Eigenfield_basis& basis() const { return *basis_; }
  std::shared_ptr<const Eigenfield_basis> shared_basis() const { return basis_; }
  int size() const { return basis_->size(); }
  double eigenvalue(int k) const { return basis_->eigenvalue(k); }
  Eigenfield_type type(int k) const { return basis_->type(k); }

  /// Coefficients `<v, Phi_k>_MX` of a face field, in the order of the basis.
  template <class FaceVectorMap>
  Eigen::VectorXd coefficients(const FaceVectorMap& field) const
  {
    return basis_->coefficients(operators_.to_frame_coordinates(field));
  }
  /// Writes `sum_k a_k Phi_k` (over the first `a.size()` elements) into `field`.
  template <class FaceVectorMap>
  void reconstruct(const Eigen::VectorXd& a, FaceVectorMap field) const
  {
    operators_.from_frame_coordinates(basis_->field(a), field);
  }
  /// Writes eigenfield `k` (unit norm in `MX`) into `field`.
  template <class FaceVectorMap>
  void eigenfield(int k, FaceVectorMap field) const
  {
    operators_.from_frame_coordinates(basis_->eigenfield(k), field);
  }
  /// Filters `input` into `output` (the maps may be the same).
  template <class InputMap, class OutputMap>
  void filter(const InputMap& input, const Spectral_filter& filter, OutputMap output) const
  {
    operators_.from_frame_coordinates(basis_->filter(operators_.to_frame_coordinates(input), filter), output);
  }
  double dirichlet_energy(const Eigen::VectorXd& a) const { return basis_->dirichlet_energy(a); }
  double biharmonic_energy(const Eigen::VectorXd& a) const { return basis_->biharmonic_energy(a); }

private:
  Spectral_basis(Operators operators, std::shared_ptr<const Eigenfield_basis> basis)
    : operators_(std::move(operators)), basis_(std::move(basis))
  {}

  Operators operators_;
  std::shared_ptr<const Eigenfield_basis> basis_; // holds the Hodge solver it was built with
};

/// \brief Filters a face field through the spectral basis of `mesh`.
///
/// Computes a basis as `Spectral_basis` does from `np` (default: 100 eigenfields), so
/// for several fields build a `Spectral_basis` once instead.
template <class TriangleMesh, class InputMap, class OutputMap,
          class NamedParameters = parameters::Default_named_parameters>
void filter_tangent_field(const TriangleMesh& mesh, const InputMap& input, const Spectral_filter& filter,
                          OutputMap output, const NamedParameters& np = parameters::default_values())
{
  Spectral_basis<TriangleMesh>(mesh, np).filter(input, filter, output);
}

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
