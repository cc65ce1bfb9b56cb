// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The reduced simulator's floor: the smallest change of the reduced coordinates that lifts the
// collision vertices onto a floor, as a quadratic program whose size is the number of basis
// columns near the contact, not the number of vertices in contact.

#ifndef CGAL_PROJECTIVE_DYNAMICS_INTERNAL_FLOOR_PUSH_H
#define CGAL_PROJECTIVE_DYNAMICS_INTERNAL_FLOOR_PUSH_H

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include <vector>

namespace CGAL {
namespace Projective_dynamics {
namespace internal {

/// What a floor push did (for tests and benchmarks).
struct Floor_push_report
{
  int columns = 0;             ///< basis columns the contact rows touch (the problem's size)
  int constraints = 0;         ///< collision vertices in the problem (penetrating, or pushed below by the push)
  int factorizations = 0;      ///< dense factorizations of the columns x columns Newton matrix
  int updates = 0;             ///< multiplier updates of the augmented Lagrangian
  double largest_violation = 0; ///< the most any constraint is violated after the push
};

/// The push `delta` (k values, one per basis column, along the floor's normal) that minimises
/// `delta^T Mr delta` (Mr = U^T M U, the kinetic metric) subject to
/// `U_i delta >= need_i` for the vertices `rows` (the lift each needs) and `U_j delta = 0` for
/// the vertices `held` (pinned or grabbed: their height is kept), to `tolerance` (in lengths).
///
/// Only the columns C that those rows touch enter the constraints, so the optimum is
/// `delta = Minv(:, C) P y` with `P = Minv(C, C)^-1` and `y = delta_C` the minimiser of
/// `y^T P y` under the constraints restricted to C: a problem of |C| unknowns, solved by an
/// augmented Lagrangian with semismooth Newton steps (each a |C| x |C| Cholesky factorization;
/// the active set of a resting body repeats, so a few per push).  `multipliers`, if given,
/// holds one multiplier per row to start from (a resting body's contact forces change little
/// from step to step; any other size starts from zero) and returns those found.
Eigen::VectorXd smallest_floor_push(const Eigen::SparseMatrix<double, Eigen::RowMajor>& U, const Eigen::MatrixXd& Mr_inverse,
                                    const std::vector<int>& rows, const Eigen::VectorXd& need, const std::vector<int>& held,
                                    double tolerance, Floor_push_report* report = nullptr,
                                    Eigen::VectorXd* multipliers = nullptr);

/// The rows of U on the columns `columns` (as columns 0, 1, ...) and the inverse of `Mr` on
/// them: what `smallest_floor_push` needs for pushes within those columns (made once per
/// simulator: O(|T|^3)).
struct Push_subspace
{
  Eigen::SparseMatrix<double, Eigen::RowMajor> U;
  Eigen::MatrixXd Mr_inverse;
  std::vector<int> columns;
};
Push_subspace push_subspace(const Eigen::SparseMatrix<double, Eigen::RowMajor>& U, const Eigen::MatrixXd& Mr,
                            const std::vector<int>& columns);

/// The same push within the span of the basis columns `push_columns` only (the others do not
/// move): `delta_T` minimises `delta_T^T Mr(T, T) delta_T` under the same constraints.  It is
/// `smallest_floor_push` on `push_subspace(U, Mr, T)`: a problem of the columns of T that the
/// contact rows touch (a body resting on its feet: a few of its samples).  For the position
/// subspace's per-sample translations (columns `4 j + 3`, weights summing to one at every
/// vertex) a push always exists: the floor lifts the body by a smooth blend of its samples'
/// translations.
Eigen::VectorXd smallest_floor_push_in(const Eigen::SparseMatrix<double, Eigen::RowMajor>& U, const Eigen::MatrixXd& Mr,
                                       const std::vector<int>& push_columns, const std::vector<int>& rows,
                                       const Eigen::VectorXd& need, const std::vector<int>& held, double tolerance,
                                       Floor_push_report* report = nullptr, Eigen::VectorXd* multipliers = nullptr);

} // namespace internal
} // namespace Projective_dynamics
} // namespace CGAL

#endif
