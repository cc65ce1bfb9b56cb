// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_VIBRATION_MODES_SRC_CONSTRAINED_GROUP_LASSO_H
#define CGAL_VIBRATION_MODES_SRC_CONSTRAINED_GROUP_LASSO_H

// The convex problem of one ICCM step (SPEC 13.3):
//   min u^T H u + mu sum_v m_v |u_v|   subject to   F^T M u = 0,  c^T M u = 1,
// F the fixed directions (kernel and earlier modes, M-orthonormal), c the current unit
// iterate.  ADMM on u = z with the penalty (rho / 2) |u - z + w|_M^2:
// - u-step: the KKT system of (2H + rho M) u = rho M (z - w) under the constraints, by
//   one sparse solve and a small Schur complement (A^-1 M F is kept per rho);
// - z-step: a group soft threshold at mu / rho per vertex (the masses cancel);
// - w += u - z.
// rho adapts to balance the primal and dual residuals, refactoring 2H + rho M.

#include <CGAL/Model_reduction/Sparse_spd_solver.h>
#include <CGAL/Vibration_modes/Mode_problem.h>

#include <Eigen/Dense>

namespace CGAL {
namespace Vibration_modes {
namespace internal {

class Constrained_group_lasso
{
public:
  Constrained_group_lasso(const Mode_problem& problem, double mu, double tolerance);
  /// The L1-constrained problem instead: min u^T H u with sum_v m_v |u_v| <= budget (the
  /// z-step projects onto that ball; mu is not used).
  void set_l1_budget(double budget) { budget_ = budget; }

  /// The fixed directions, M-orthonormal.
  void set_fixed(const Eigen::MatrixXd& Q);
  /// One more fixed direction, M-unit and M-orthogonal to the others.
  void add_fixed(const Eigen::VectorXd& v);
  Eigen::VectorXd project_out_fixed(const Eigen::VectorXd& v) const;
  /// The fixed directions (M-orthonormal columns).
  const Eigen::MatrixXd& fixed() const { return F_; }
  double m_norm(const Eigen::VectorXd& v) const;

  /// A new mode: u = z = c, w = 0, and rho at 10x `eigenvalue` (refactors only if rho
  /// changes by more than a factor 4), or at `rho` if given (> 0).
  void start(const Eigen::VectorXd& c, double eigenvalue, double rho = 0);
  /// After `start`, the sparse iterate and the scaled dual (the dual over `rho`) of an
  /// earlier run, another working set's (restricted or extended by zeros): its warm start.
  void set_state(const Eigen::VectorXd& z, const Eigen::VectorXd& w, double rho)
  {
    z_ = z;
    w_ = w * (rho / rho_);
  }
  const Eigen::VectorXd& w() const { return w_; }
  double rho() const { return rho_; }
  /// ADMM on the plane c^T M u = 1 from the current state until both residuals are below
  /// `tolerance` (relative; at least the constructor's) or `max_iterations`; returns the
  /// iterations made.  `converged()` says whether the residuals met the tolerance.
  int solve_on_plane(const Eigen::VectorXd& c, int max_iterations, double tolerance);
  bool converged() const { return converged_; }
  /// The last u-step: feasible (on the plane, M-orthogonal to the fixed directions).
  const Eigen::VectorXd& u() const { return u_; }
  /// The sparse iterate of the last z-step (exact zeros off its support).
  const Eigen::VectorXd& z() const { return z_; }
  /// Scales the state (u, z, w) for the next plane after the iterate is normalised.
  void rescale(double s);
  /// The sparse iterate z made exactly feasible without leaving its support (the smallest
  /// M-norm change that restores M-orthogonality to the fixed directions), M-normalised;
  /// empty if z is zero.
  Eigen::VectorXd feasible_sparse_iterate() const;

private:
  void factor(double rho);

  const Mode_problem& p_;
  // The z-step: group soft threshold at mu / rho, or projection onto the L1 ball.
  void shrink(const Eigen::VectorXd& x);

  double mu_, tolerance_, rho_ = 0, energy_scale_ = 1, budget_ = 0;
  Model_reduction::Sparse_spd_solver A_;
  Eigen::MatrixXd F_, MF_, WF_; // fixed directions, M F, A^-1 M F
  Eigen::VectorXd u_, z_, w_;
  int refactorisations_ = 0;
  bool converged_ = false;
};

} // namespace internal
} // namespace Vibration_modes
} // namespace CGAL

#endif
