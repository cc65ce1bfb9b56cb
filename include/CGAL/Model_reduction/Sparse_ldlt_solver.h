// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_MODEL_REDUCTION_SPARSE_LDLT_SOLVER_H
#define CGAL_MODEL_REDUCTION_SPARSE_LDLT_SOLVER_H

/// \file Sparse_ldlt_solver.h
/// `LDL^T` factorisation of sparse symmetric (or complex Hermitian: `LDL^H`, `D` real),
/// possibly indefinite matrices with one sparsity pattern (shifted matrices `A - sigma D`),
/// giving the inertia: CHOLMOD's simplicial `LDL^T` when built with SuiteSparse, Eigen's
/// `SimplicialLDLT` otherwise.  No pivoting: meant for shifts placed away from
/// eigenvalues, where the pivots stay well away from zero.

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <complex>
#include <memory>
#include <string>

namespace CGAL {
namespace Model_reduction {

/// `Scalar`: `double` (symmetric matrices) or `std::complex<double>` (Hermitian ones, for the
/// complex eigenproblems of `Generalized_eigensolver.h`: half the unknowns of their real form).
template <class Scalar>
class Basic_sparse_ldlt_solver
{
public:
  typedef Eigen::SparseMatrix<Scalar> Sparse_matrix;
  typedef Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> Matrix;

  Basic_sparse_ldlt_solver();
  ~Basic_sparse_ldlt_solver();
  Basic_sparse_ldlt_solver(const Basic_sparse_ldlt_solver&) = delete;
  Basic_sparse_ldlt_solver& operator=(const Basic_sparse_ldlt_solver&) = delete;

  /// Orders and analyses the pattern of `A` (lower triangle); later `factor` calls
  /// must use matrices with this pattern.  The ordering is approximate minimum degree,
  /// or -- with `many_factorizations` on 20,000 unknowns or more, where CHOLMOD has
  /// METIS -- nested dissection, whose analysis costs more (0.5 s against 0.04 s on
  /// 104k Crouzeix-Raviart unknowns) but whose factor has 20% fewer entries, factors
  /// in half the time and solves in two thirds.
  void analyze(const Sparse_matrix& A, bool many_factorizations = false);
  /// Takes the ordering and analysis of `other` (analysed, same pattern), without
  /// analysing again: for factorisations of one pattern on several threads.
  void copy_analysis(const Basic_sparse_ldlt_solver& other);
  /// Factors `A` (analysing it first if `analyze` was not called).
  /// \throws Numerical_failure on a zero or non-finite pivot.
  void factor(const Sparse_matrix& A, const std::string& what);
  /// Number of negative pivots of the last factorisation: by Sylvester's law, the
  /// number of negative eigenvalues of the matrix.
  int negative_pivots() const;
  /// Smallest pivot magnitude relative to the largest (how close to singular).
  double smallest_relative_pivot() const;
  /// Solves with the last factorisation.  Keeps its workspace in the solver: not to be
  /// called on one solver from two threads at once.
  Matrix solve(const Matrix& B) const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// `LDL^T` of real symmetric matrices.
typedef Basic_sparse_ldlt_solver<double> Sparse_ldlt_solver;
/// `L D L^H` of complex Hermitian matrices (`D` real: its signs are the inertia).
typedef Basic_sparse_ldlt_solver<std::complex<double>> Hermitian_ldlt_solver;
extern template class Basic_sparse_ldlt_solver<double>;
extern template class Basic_sparse_ldlt_solver<std::complex<double>>;

} // namespace Model_reduction
} // namespace CGAL

#endif
