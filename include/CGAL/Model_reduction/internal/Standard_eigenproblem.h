// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_MODEL_REDUCTION_INTERNAL_STANDARD_EIGENPROBLEM_H
#define CGAL_MODEL_REDUCTION_INTERNAL_STANDARD_EIGENPROBLEM_H

/// \file Standard_eigenproblem.h
/// Pieces shared by the dense and the sliced eigensolver of `Generalized_eigensolver.h`:
/// `A x = lambda D x` in its symmetric standard form `D^-1/2 A D^-1/2 y = lambda y`, the
/// residuals and tolerances every returned pair is checked against, small dense kernels.

#include <CGAL/Model_reduction/Generalized_eigensolver.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <vector>

namespace CGAL {
namespace Model_reduction {
namespace internal {

/// Eigenvalues (ascending) and eigenvectors (overwriting `A`) of a dense symmetric matrix.
void symmetric_eigen(Eigen::MatrixXd& A, Eigen::VectorXd& values);

/// Orthonormal basis of the columns of `X` (thin Householder QR).
Eigen::MatrixXd orthonormal_columns(const Eigen::MatrixXd& X);

/// `Z = next R` with orthonormal `next` and upper triangular `R`.
void block_qr(const Eigen::MatrixXd& Z, Eigen::MatrixXd& next, Eigen::MatrixXd& R);

/// `A x = lambda D x` with `A` symmetric positive semi-definite, `D` diagonal positive,
/// and a known kernel, seen in its standard form.
struct Standard_eigenproblem
{
  const Eigen::SparseMatrix<double>& A;
  Eigen::VectorXd d, sqrt_d, inv_sqrt_d;
  Eigen::MatrixXd kernel; ///< orthonormal, standard form
  /// Gershgorin bound of the largest eigenvalue of the standard form.
  double largest_eigenvalue_bound = 0;

  Standard_eigenproblem(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& d,
                        const Eigen::MatrixXd& kernel_original);

  /// The residual a pair with eigenvalue `lambda` can reach in double precision:
  /// roundoff of relative size eps in every direction of the vector, amplified by up
  /// to the largest eigenvalue, bounds `|A x - l D x| / (l |D x|)` below by about
  /// `eps lambda_max / l`; a margin of 64 covers the accumulation over a run.
  double tolerance_for(double lambda, double tolerance) const;

  /// Relative residuals `|D^-1/2 (A x - l D x)| / (|l| |D^1/2 x|)` of pairs whose vectors
  /// are given in standard form (`y = D^1/2 x`): the residual of the symmetric standard
  /// form, which bounds the relative eigenvalue error.  With `tolerances`, also each
  /// pair's reachable residual from its own vector: the roundoff of computing `A x` is
  /// `eps |A| |x|` entry by entry, far below `tolerance_for` where `A`'s large entries sit
  /// away from the vector (a component of the mesh a million times smaller than the one
  /// the vector lives on), which would accept a pair with only a few correct digits.
  /// Column by column, so that no temporary as large as `Y` is made.
  void residuals_of_standard(const Eigen::VectorXd& values, const Eigen::Ref<const Eigen::MatrixXd>& Y, double tolerance,
                             Eigen::VectorXd& residuals, Eigen::VectorXd* tolerances = nullptr) const;

  /// The same for vectors in the original variables.
  Eigen::VectorXd residuals(const Eigen::VectorXd& values, const Eigen::MatrixXd& X) const;
  Eigen::VectorXd tolerances_for(const Eigen::VectorXd& values, const Eigen::MatrixXd& X, double tolerance) const;

  /// `A - sigma D`, for a factorisation.  Made when needed and not kept: a copy per thread
  /// (31 MB at the armadillo's 519k edges) was held through every window, at the peak too.
  Eigen::SparseMatrix<double> shifted(double sigma) const;
  /// `(A - sigma D) X`, without the shifted matrix.
  Eigen::MatrixXd shifted_times(double sigma, const Eigen::MatrixXd& X) const;

  /// Removes the kernel's component of the standard-form columns `Z`.
  void deflate(Eigen::MatrixXd& Z) const
  {
    if(kernel.cols() > 0) Z -= kernel * (kernel.transpose() * Z);
  }
};

/// One problem of a spectrum-slicing solve.
struct Sliced_request
{
  const Standard_eigenproblem& problem;
  int count;
};

/// The `count` lowest pairs of each request by spectrum slicing (`Generalized_eigensolver.h`):
/// each cut into chains of windows, one per core on large requests, and the chains of all
/// the requests run on one pool of threads.
std::vector<Eigenpairs> sliced_eigenpairs(const std::vector<Sliced_request>& requests,
                                          const Eigensolver_options& options);

} // namespace internal
} // namespace Model_reduction
} // namespace CGAL

#endif
