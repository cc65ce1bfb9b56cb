// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_GENERALIZED_EIGENSOLVER_H
#define CGAL_TANGENT_VECTOR_FIELDS_GENERALIZED_EIGENSOLVER_H

/// \file Generalized_eigensolver.h
/// Lowest eigenpairs of `A x = lambda D x` with `A` sparse symmetric positive
/// semi-definite and `D` diagonal positive: block shift-and-invert Lanczos with full
/// reorthogonalisation, a known kernel deflated, every returned pair checked on its
/// true residual, and a Sylvester inertia count to prove that none was skipped.

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <cstdint>
#include <functional>
#include <string>

namespace CGAL {
namespace Tangent_vector_fields {

/// Reported to the progress callback while the solver runs.
struct Eigensolver_progress
{
  int converged = 0;  ///< wanted pairs converged so far (estimate)
  int wanted = 0;     ///< pairs asked for
  int basis_size = 0; ///< Krylov basis size
};

struct Eigensolver_options
{
  /// Vectors per block (8 to 16 was fastest on this kind of machine).
  int block_size = 16;
  /// Required relative residual `|A x - l D x| / (l |D x|)` of every returned pair.
  double tolerance = 1e-10;
  std::uint64_t seed = 1;
  /// Small problems (up to 1500 unknowns, or asking for a third of the space) are
  /// solved densely (LAPACK) unless this is false.
  bool allow_dense = true;
  /// Called after every Rayleigh-Ritz step.
  std::function<void(const Eigensolver_progress&)> progress;
};

/// Eigenpairs in ascending order; `vectors` are `D`-orthonormal.
struct Eigenpairs
{
  Eigen::VectorXd values;
  Eigen::MatrixXd vectors;
  Eigen::VectorXd residuals;    ///< relative residual of each pair
  int basis_size = 0;           ///< Krylov vectors used
  int operator_applications = 0; ///< columns passed through the shift-invert solve
};

/// The `count` smallest eigenvalues of `A x = lambda D x` on the `D`-orthogonal
/// complement of `kernel` (columns: a basis of the null space of `A`, may be empty).
/// \throws Numerical_failure if the iteration does not reach `tolerance`.
Eigenpairs lowest_eigenpairs(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& D, int count,
                             const Eigen::MatrixXd& kernel, const Eigensolver_options& options = {});

/// Number of eigenvalues of `A x = lambda D x` below `tau` (Sylvester's law of inertia:
/// the negative pivots of an `LDL^T` factorisation of `A - tau D`).
int count_eigenvalues_below(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& D, double tau);

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
