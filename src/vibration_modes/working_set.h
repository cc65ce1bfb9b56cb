// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_VIBRATION_MODES_SRC_WORKING_SET_H
#define CGAL_VIBRATION_MODES_SRC_WORKING_SET_H

// The working set of a compressed mode.  A mode is sparse: where it is zero, its convex
// problems are those of the vertices near its support with u = 0 elsewhere.  ICCM then runs
// on H, M restricted to a set W of vertices (the support grown by a few rings of H's
// pattern), whose factorisation and solves cost a fraction of the whole mesh's, and whose
// fixed directions are only those not zero on W (an earlier mode elsewhere drops out).
// The restricted answer is the whole problem's if the first-order conditions also hold
// outside W (u_v = 0 there):  |2 (H u)_v - m_v (F nu)_v| <= mu m_v,  with the multipliers
// nu of the constraints F^T M u = 0 (and sigma of u^T M u = 1) fitted on the support.
// Vertices where they fail join W.

#include <CGAL/Vibration_modes/Mode_problem.h>

#include <Eigen/Dense>

#include <vector>

namespace CGAL {
namespace Vibration_modes {
namespace internal {

/// One flag per group (vertex) of the free unknowns.
using Group_set = std::vector<char>;

/// The groups where `u` is not zero.
Group_set support_of(const Mode_problem& p, const Eigen::VectorXd& u);
/// Adds the groups within `rings` steps of the set in the pattern of H.
void grow(const Mode_problem& p, Group_set& set, int rings);
std::size_t size_of(const Group_set& set);

/// H and M on the unknowns of a set of groups (no kernel: the caller's fixed directions,
/// restricted, take its place).
struct Restricted_problem
{
  Mode_problem problem;
  std::vector<Eigen::Index> unknowns; ///< the full free index of each restricted unknown

  Restricted_problem(const Mode_problem& p, const Group_set& set);
  Eigen::MatrixXd restrict(const Eigen::MatrixXd& X) const;
  Eigen::VectorXd expand(const Eigen::VectorXd& x, Eigen::Index full_rows) const;
};

/// Columns made M-orthonormal (modified Gram-Schmidt twice); columns that are dependent on
/// the earlier ones (or zero) are dropped.
Eigen::MatrixXd m_orthonormal(const Eigen::MatrixXd& X, const Eigen::VectorXd& mass);

/// The multipliers (sigma, nu) that best satisfy the first-order conditions on the support
/// of `u` (least squares, each row in the M^-1 norm):
///   2 (H u)_j + mu m_j u_j / |u_v| = 2 sigma m_j u_j + m_j (F nu)_j.
Eigen::VectorXd first_order_multipliers(const Mode_problem& p, const Eigen::MatrixXd& F, const Eigen::VectorXd& u,
                                        double mu);

/// The groups outside `set` where the first-order conditions of
///   min u^T H u + mu sum_v m_v |u_v|  on  u^T M u = 1,  F^T M u = 0
/// fail at `u` (zero outside `set`) by more than `slack` (relative to mu m_v).
std::vector<Eigen::Index> violations_outside(const Mode_problem& p, const Eigen::MatrixXd& F, const Eigen::VectorXd& u,
                                             double mu, const Group_set& set, double slack);

} // namespace internal
} // namespace Vibration_modes
} // namespace CGAL

#endif
