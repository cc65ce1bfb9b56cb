// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_FULL_SPLINE_SOLVER_H
#define CGAL_TANGENT_VECTOR_FIELDS_FULL_SPLINE_SOLVER_H

/// \file Full_spline_solver.h
/// Tangent vector field splines on all `2nf` unknowns (SPEC 7): the yardstick for the
/// reduced solver.

#include <CGAL/Tangent_vector_fields/Hodge_solver.h>
#include <CGAL/Tangent_vector_fields/Spline_solver.h>
#include <CGAL/Tangent_vector_fields/Sparse_spd_solver.h>

#include <memory>

namespace CGAL {
namespace Tangent_vector_fields {

/// How accurately the full solver's pull-backs were computed.
struct Full_solve_statistics
{
  double factor_seconds = 0;    ///< assembling `B + omega S` and factoring it (last time)
  double pull_back_seconds = 0; ///< all pull-backs so far
  int iterations = 0;           ///< largest number of PCG iterations of a pull-back batch
  double residual = 0;          ///< largest final relative residual of a pull-back
};

/// \brief The range-space method on the full field space.
///
/// `Q = B + omega S` is singular on the harmonic fields (and badly conditioned:
/// `cond ~ nf^2`), so pull-backs `y = Q^+ r^T` are computed by conjugate gradients on
/// the fields `MX`-orthogonal to the harmonic ones, preconditioned by a CHOLMOD
/// factorisation of `Q + sigma MX` with a tiny `sigma` (1e-10 of the largest
/// eigenvalue bound, enough to keep the factorisation positive definite).  The
/// preconditioned operator has all but a handful of eigenvalues at 1, so CG reaches a
/// relative residual of 1e-12 in a few iterations: the answer is the exact spline to
/// solver precision, not the spline of a regularised energy.
///
/// `B` is formed explicitly (`S MX^-1 S`); the factorisation is built on the first
/// pull-back and reused for every constraint until `omega` changes.
class Full_spline_solver : public Spline_solver
{
public:
  explicit Full_spline_solver(std::shared_ptr<const Hodge_solver> hodge,
                              const Spline_options& options = Spline_options());
  ~Full_spline_solver();

  Eigen::VectorXd field() const override { return solution(); }
  const Full_solve_statistics& statistics() const { return statistics_; }
  /// Relative residual the pull-backs are iterated to.
  static constexpr double pull_back_tolerance = 1e-12;

protected:
  void pull_back(std::vector<Row>& rows) const override;
  double apply(const Row& row, const Eigen::VectorXd& y) const override { return row.row.dot(y); }
  double energy(const Eigen::VectorXd& x) const override;
  void add_harmonic(const Eigen::VectorXd& z, Eigen::VectorXd& x) const override;
  int space_dimension() const override { return 2 * operators_->mesh().number_of_faces(); }
  void energy_changed() override;

private:
  void factor() const;

  std::shared_ptr<const Hodge_solver> hodge_;
  mutable Eigen::SparseMatrix<double> Q_;
  mutable std::unique_ptr<Sparse_spd_solver> preconditioner_;
  mutable Full_solve_statistics statistics_;
};

namespace internal {
/// Block conjugate gradients (independent columns sharing the products) for
/// `A X = B` on a subspace: `A` symmetric positive semi-definite, positive definite
/// on the subspace; `precondition` an SPD approximation of `A^-1`; `project_primal`
/// and `project_dual` remove the excluded directions from iterates and residuals.
/// Returns the number of iterations; `residual` the largest final relative residual.
Eigen::MatrixXd projected_block_cg(const std::function<Eigen::MatrixXd(const Eigen::MatrixXd&)>& apply_A,
                                   const std::function<Eigen::MatrixXd(const Eigen::MatrixXd&)>& precondition,
                                   const std::function<void(Eigen::MatrixXd&)>& project_primal,
                                   const std::function<void(Eigen::MatrixXd&)>& project_dual,
                                   const Eigen::MatrixXd& B, double tolerance, int max_iterations,
                                   int& iterations, double& residual);
} // namespace internal

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
