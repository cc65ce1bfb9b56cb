// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// The per-group data of the reduced simulator and the hyper-reduction's precomputation: the
// projection subspace V of each group, the sampled elements, the fit's normal matrix and
// F = U^T S^T D V, and the sampled rows of S on the used vertices.

#ifndef CGAL_PROJECTIVE_DYNAMICS_SRC_HYPER_REDUCTION_H
#define CGAL_PROJECTIVE_DYNAMICS_SRC_HYPER_REDUCTION_H

#include <CGAL/Projective_dynamics/Reduced_simulator.h>

#include <Eigen/Cholesky>
#include <Eigen/SparseCore>

#include <functional>
#include <vector>

namespace CGAL {
namespace Projective_dynamics {
namespace internal {

struct Reduced_group
{
  int first_row = 0, rows = 0;
  Eigen::VectorXd measure;   // per row
  Eigen::MatrixXd L;         // U^T S_g^T diag(measure) S_g U (unit stiffness)
  // Hyper-reduction:
  std::vector<int> sampled;  // elements
  int first_sampled = 0;     // its first in Hyper_sampling::sampled_all
  int first_sampled_row = 0; // in the stacked rows of the sampled elements
  int sampled_rows = 0;
  Eigen::MatrixXd JV;        // sampled rows x l
  Eigen::LLT<Eigen::MatrixXd> fit; // (J V)^T (J V)
  Eigen::MatrixXd F;         // U^T S_g^T diag(measure) V (unit stiffness), k x l
  // K^-1 F fit^-1 (k x l), made with each factorisation of K: an iteration's global solve is then
  // a k x l product per group instead of two k x k triangular solves (see Reduced_simulator step).
  Eigen::MatrixXd solved_F;
};

struct Hyper_sampling
{
  std::vector<int> used;        // the sampled elements' vertices, sorted
  std::vector<int> sampled_all; // every group's sampled elements, group by group
  std::vector<int> sampled_row; // the first row of each in the stacked sampled rows
  Eigen::SparseMatrix<double, Eigen::RowMajor> S_used; // sampled rows of S on the used vertices
  Eigen::SparseMatrix<double, Eigen::RowMajor> U_used; // rows of U of the used vertices
};

/// Fills the hyper-reduction members of `groups` (`members[g]`: the elements of group g).
/// `report(stage, fraction)`, if given, is told when the element samples are chosen (0) and
/// after each group (the fraction of groups done).
/// \throws Invalid_input for a group of fewer than l + 20 elements; Numerical_failure for a
///         singular fit.
Hyper_sampling sample_and_fit(const Elastic_model& model, const Reduction_options& r,
                              const Eigen::SparseMatrix<double, Eigen::RowMajor>& U,
                              const Eigen::SparseMatrix<double, Eigen::RowMajor>& Ut,
                              const std::vector<std::vector<int>>& members, std::vector<Reduced_group>& groups,
                              const std::function<void(const char*, double)>& report = {});

/// What `sample_and_fit` derives from the groups' sampled elements (set `sampled`, `JV` and `F`
/// of each group): each group's `first_sampled`, `first_sampled_row`, `sampled_rows` and `fit`,
/// and the used vertices with their rows of S and U (used by a loaded precomputation).
/// \throws Numerical_failure for a singular fit.
Hyper_sampling finish_sampling(const Elastic_model& model, const Eigen::SparseMatrix<double, Eigen::RowMajor>& U,
                               std::vector<Reduced_group>& groups);

} // namespace internal
} // namespace Projective_dynamics
} // namespace CGAL

#endif
