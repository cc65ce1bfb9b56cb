// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The projection subspace V of an element group in factored form, V = D^{-1/2} (Q A + B E):
// Q (rows x z, dense, z <= 3) spans the rest projections, B = D^{1/2} C (rows x 4m, sparse) holds
// the weighted candidates, A (z x l) and E (4m x l) are small.  The hyper-reduction needs V only at
// the sampled rows and through F = U^T S^T D V, both cheap in this form; V itself is rows x l
// dense (206,000 x 120 doubles, 198 MB, for a 68,666-tet armadillo).

#ifndef CGAL_PROJECTIVE_DYNAMICS_INTERNAL_PROJECTION_SUBSPACE_FACTORS_H
#define CGAL_PROJECTIVE_DYNAMICS_INTERNAL_PROJECTION_SUBSPACE_FACTORS_H

#include <CGAL/Projective_dynamics/Elastic_model.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <vector>

namespace CGAL {
namespace Projective_dynamics {
namespace internal {

struct Projection_subspace_factors
{
  Eigen::VectorXd inverse_root;                  // D^{-1/2}, per row of the group
  Eigen::MatrixXd Q;                             // rows x z
  Eigen::SparseMatrix<double, Eigen::RowMajor> B; // rows x 4m
  Eigen::MatrixXd A;                             // z x l
  Eigen::MatrixXd E;                             // 4m x l

  /// The rows `rows` (of the group) of V.
  Eigen::MatrixXd rows_of_V(const std::vector<int>& rows) const;
  /// V, whole (rows x l).
  Eigen::MatrixXd V() const;
  /// `F = U^T S_g^T D V` (k x l) without V: `Sg` the group's rows of the selection matrix
  /// (rows x vertices), `Ut` = U^T (k x vertices).
  Eigen::MatrixXd projected(const Eigen::SparseMatrix<double, Eigen::RowMajor>& Sg,
                            const Eigen::SparseMatrix<double, Eigen::RowMajor>& Ut) const;
};

/// As `projection_subspace` (Projection_subspace.h), factored.
Projection_subspace_factors projection_subspace_factors(const Elastic_model& model, int group, int constraint_samples,
                                                        double radius_multiplier, int l);

} // namespace internal
} // namespace Projective_dynamics
} // namespace CGAL

#endif
