// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_SPARSE_SPD_SOLVER_H
#define CGAL_TANGENT_VECTOR_FIELDS_SPARSE_SPD_SOLVER_H

/// \file Sparse_spd_solver.h
/// Factorisation of a sparse symmetric positive definite matrix: CHOLMOD's
/// supernodal Cholesky when the package was built with SuiteSparse, Eigen's
/// `SimplicialLDLT` otherwise.

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>
#include <string>

namespace CGAL {
namespace Tangent_vector_fields {

/// Factors once, solves many right-hand sides (one vector or a block of columns).
class Sparse_spd_solver
{
public:
  Sparse_spd_solver();
  ~Sparse_spd_solver();
  Sparse_spd_solver(Sparse_spd_solver&&) noexcept;
  Sparse_spd_solver& operator=(Sparse_spd_solver&&) noexcept;

  /// Factors `A` (only its lower triangle is read).
  /// \throws Numerical_failure if `A` is not numerically positive definite;
  ///         `what` names the matrix in the message.
  void factor(const Eigen::SparseMatrix<double>& A, const std::string& what);
  bool is_factored() const;
  Eigen::Index size() const;

  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const;

  /// "CHOLMOD supernodal" or "Eigen SimplicialLDLT".
  static const char* backend_name();

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
