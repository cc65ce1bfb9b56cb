// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_MODEL_REDUCTION_INTERNAL_STANDARD_EIGENPROBLEM_H
#define CGAL_MODEL_REDUCTION_INTERNAL_STANDARD_EIGENPROBLEM_H

/// \file Standard_eigenproblem.h
/// Pieces shared by the dense and the sliced eigensolver of `Generalized_eigensolver.h`:
/// `A x = lambda D x` in its symmetric standard form `D^-1/2 A D^-1/2 y = lambda y`, the
/// residuals and tolerances every returned pair is checked against, small dense kernels.
/// Each for `A` real symmetric (`Scalar` double) or complex Hermitian (`std::complex<double>`):
/// inner products are Hermitian (`adjoint`), eigenvalues, masses and residuals real.

#include <CGAL/Model_reduction/Generalized_eigensolver.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <complex>
#include <vector>

namespace CGAL {
namespace Model_reduction {
namespace internal {

/// Eigenvalues (ascending) and eigenvectors (overwriting `A`) of a dense symmetric or
/// Hermitian matrix (its lower triangle).
void symmetric_eigen(Eigen::MatrixXd& A, Eigen::VectorXd& values);
void symmetric_eigen(Eigen::MatrixXcd& A, Eigen::VectorXd& values);

/// Orthonormal basis of the columns of `X` (thin Householder QR).
template <class Scalar>
Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>
orthonormal_columns(const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& X);

/// `Z = next R` with orthonormal `next` and upper triangular `R`.
template <class Scalar>
void block_qr(const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& Z,
              Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& next,
              Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& R);

/// `A x = lambda D x` with `A` symmetric (Hermitian) positive semi-definite, `D` diagonal
/// positive, and a known kernel, seen in its standard form.
template <class Scalar>
struct Basic_standard_eigenproblem
{
  typedef Eigen::SparseMatrix<Scalar> Sparse_matrix;
  typedef Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> Matrix;
  typedef Eigen::Matrix<Scalar, Eigen::Dynamic, 1> Vector;

  const Sparse_matrix& A;
  Eigen::VectorXd d, sqrt_d, inv_sqrt_d;
  Matrix kernel; ///< orthonormal, standard form
  /// Gershgorin bound of the largest eigenvalue of the standard form.
  double largest_eigenvalue_bound = 0;

  Basic_standard_eigenproblem(const Sparse_matrix& A, const Eigen::VectorXd& d, const Matrix& kernel_original);

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
  void residuals_of_standard(const Eigen::VectorXd& values, const Eigen::Ref<const Matrix>& Y, double tolerance,
                             Eigen::VectorXd& residuals, Eigen::VectorXd* tolerances = nullptr) const;

  /// The same for vectors in the original variables.
  Eigen::VectorXd residuals(const Eigen::VectorXd& values, const Matrix& X) const;
  Eigen::VectorXd tolerances_for(const Eigen::VectorXd& values, const Matrix& X, double tolerance) const;

  /// `A - sigma D`, for a factorisation.  Made when needed and not kept: a copy per thread
  /// (31 MB at the armadillo's 519k edges) was held through every window, at the peak too.
  Sparse_matrix shifted(double sigma) const;
  /// `(A - sigma D) X`, without the shifted matrix.
  Matrix shifted_times(double sigma, const Matrix& X) const;

  /// Removes the kernel's component of the standard-form columns `Z`.
  void deflate(Matrix& Z) const
  {
    if(kernel.cols() > 0) Z -= kernel * (kernel.adjoint() * Z);
  }
};

typedef Basic_standard_eigenproblem<double> Standard_eigenproblem;
extern template struct Basic_standard_eigenproblem<double>;
extern template struct Basic_standard_eigenproblem<std::complex<double>>;

/// One problem of a spectrum-slicing solve.
template <class Scalar>
struct Sliced_request
{
  const Basic_standard_eigenproblem<Scalar>& problem;
  int count;
};

/// The `count` lowest pairs of each request by spectrum slicing (`Generalized_eigensolver.h`):
/// each cut into chains of windows, one per core on large requests, and the chains of all
/// the requests run on one pool of threads.
template <class Scalar>
std::vector<Basic_eigenpairs<Scalar>> sliced_eigenpairs(const std::vector<Sliced_request<Scalar>>& requests,
                                                        const Eigensolver_options& options);

} // namespace internal
} // namespace Model_reduction
} // namespace CGAL

#endif
