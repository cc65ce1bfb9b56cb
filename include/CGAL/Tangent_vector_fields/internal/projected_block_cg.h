// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_INTERNAL_PROJECTED_BLOCK_CG_H
#define CGAL_TANGENT_VECTOR_FIELDS_INTERNAL_PROJECTED_BLOCK_CG_H

/// \file projected_block_cg.h
/// Preconditioned conjugate gradients on a subspace, several right-hand sides at once.

#include <Eigen/Core>

#include <functional>

namespace CGAL {
namespace Tangent_vector_fields {

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
