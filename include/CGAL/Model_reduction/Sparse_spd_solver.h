// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_MODEL_REDUCTION_SPARSE_SPD_SOLVER_H
#define CGAL_MODEL_REDUCTION_SPARSE_SPD_SOLVER_H

/// \file Sparse_spd_solver.h
/// Factorisation of a sparse symmetric positive definite matrix: CHOLMOD's
/// supernodal Cholesky when the package was built with SuiteSparse, Eigen's
/// `SimplicialLDLT` otherwise.

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <complex>
#include <memory>
#include <string>

namespace CGAL {
namespace Model_reduction {

/// How a `Basic_sparse_spd_solver` factors (with CHOLMOD; Eigen's fallback is always
/// simplicial).
enum class Spd_factorization {
  /// Supernodal Cholesky (BLAS on dense blocks): the default, fastest for many solves and for
  /// blocks of right-hand sides.
  supernodal,
  /// Simplicial Cholesky, for a factor that serves a few solves of one column each (a lowest
  /// eigenvector): on the 346k-face armadillo's complex S_4 it factored in 1.37 s against
  /// 1.69 s and solved one column in 37 ms against 64 ms (one BLAS thread).
  simplicial
};

/// Factors once, solves many right-hand sides (one vector or a block of columns).
/// `Scalar`: `double` (symmetric) or `std::complex<double>` (Hermitian: a complex system
/// costs half its real 2n x 2n form, 1.9 s against 4.3 s for 346k unknowns).
template <class Scalar>
class Basic_sparse_spd_solver
{
public:
  typedef Eigen::Matrix<Scalar, Eigen::Dynamic, 1> Vector;
  typedef Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> Matrix;

  explicit Basic_sparse_spd_solver(Spd_factorization kind = Spd_factorization::supernodal);
  ~Basic_sparse_spd_solver();
  Basic_sparse_spd_solver(Basic_sparse_spd_solver&&) noexcept;
  Basic_sparse_spd_solver& operator=(Basic_sparse_spd_solver&&) noexcept;

  /// Factors `A` (only its lower triangle is read).
  /// \throws Numerical_failure if `A` is not numerically positive definite;
  ///         `what` names the matrix in the message.
  void factor(const Eigen::SparseMatrix<Scalar>& A, const std::string& what);
  bool is_factored() const;
  Eigen::Index size() const;
  Vector solve(const Vector& b) const;
  Matrix solve(const Matrix& B) const;
  /// "CHOLMOD supernodal" or "Eigen SimplicialLDLT".
  static const char* backend_name();

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

typedef Basic_sparse_spd_solver<double> Sparse_spd_solver;
typedef Basic_sparse_spd_solver<std::complex<double>> Sparse_hermitian_solver;
extern template class Basic_sparse_spd_solver<double>;
extern template class Basic_sparse_spd_solver<std::complex<double>>;

} // namespace Model_reduction
} // namespace CGAL

#endif
