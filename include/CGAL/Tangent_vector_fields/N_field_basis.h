// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_N_FIELD_BASIS_H
#define CGAL_TANGENT_VECTOR_FIELDS_N_FIELD_BASIS_H

/// \file N_field_basis.h
/// The spectral basis of n-fields: the lowest eigenpairs of `L_n = MX^-1 S_n` (SPEC 10),
/// computed by the package's eigensolver (spectrum slicing, inertia-checked), kept in
/// pairs `(phi, J phi)`, saved and loaded with the mesh's fingerprint and n.

#include <CGAL/Tangent_vector_fields/Eigenfield_basis.h>
#include <CGAL/Tangent_vector_fields/N_field_operators.h>

#include <Eigen/Core>

#include <memory>
#include <string>

namespace CGAL {
namespace Tangent_vector_fields {

/// What the computation of an n-field basis measured.
struct N_field_basis_report
{
  double max_residual = 0;   ///< largest relative residual of an eigenpair (unit-area problem)
  double complete_below = 0; ///< no eigenvalue below this is missing (mesh as given)
  int inertia = 0, expected = 0; ///< the completeness check: both count the eigenvalues below its shift
  double seconds = 0;
};

/// \brief An `MX`-orthonormal basis of n-fields: the parallel fields (kernel of `S_n`),
/// then the lowest eigenfields of `L_n` in ascending order.
///
/// Multiplication by `i` (`J`) commutes with `S_n` and `MX`, so every eigenspace is
/// `J`-invariant: elements come in pairs, column `2j + 1` is `J` times column `2j`, both
/// with the same eigenvalue.  A truncation to an even size is therefore closed under
/// rotating the field (reduced designs turn with their constraints).
class N_field_basis
{
public:
  typedef Eigen::VectorXd Vector;
  typedef Eigen::MatrixXd Matrix;

  /// The lowest `count` elements (rounded up to an even number), kernel included.
  /// \throws Invalid_input if the space has fewer.
  /// \throws Numerical_failure if an eigenpair misses the tolerance or the completeness check fails.
  N_field_basis(std::shared_ptr<const N_field_operators> operators, int count,
                const Basis_options& options = Basis_options());

  /// Reads a basis saved by `save`.
  /// \throws Invalid_input if the file is unreadable, of another version or of another n,
  ///         boundary condition or mesh, or corrupt: an odd number of elements, an element
  ///         whose norm is not 1.
  static N_field_basis load(std::shared_ptr<const N_field_operators> operators, const std::string& path);
  /// Writes the basis to a binary file (format in `doc/tangent_vector_fields/manual.md`).
  void save(const std::string& path) const;

  const N_field_operators& operators() const { return *operators_; }
  std::shared_ptr<const N_field_operators> shared_operators() const { return operators_; }
  int n() const { return operators_->n(); }
  int size() const { return static_cast<int>(values_.size()); }
  /// Parallel fields at the front (eigenvalue 0).
  int kernel_dimension() const { return kernel_dimension_; }
  double eigenvalue(int k) const { return values_[k]; }
  const Vector& eigenvalues() const { return values_; }
  /// `2nf x size()`, `MX`-orthonormal.
  const Matrix& fields() const { return fields_; }
  const N_field_basis_report& report() const { return report_; }

  /// `a_k = <z, Phi_k>_MX`.
  Vector coefficients(const Vector& z) const;
  /// `sum_k a_k Phi_k` over the first `a.size()` elements.
  Vector field(const Vector& a) const;
  /// `sum_k lambda_k^m a_k^2`: the m-harmonic energy of the field with coefficients `a`.
  double energy(const Vector& a, int m) const;

private:
  explicit N_field_basis(std::shared_ptr<const N_field_operators> operators);

  std::shared_ptr<const N_field_operators> operators_;
  Matrix fields_;
  Vector values_;
  int kernel_dimension_ = 0;
  N_field_basis_report report_;
};

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
