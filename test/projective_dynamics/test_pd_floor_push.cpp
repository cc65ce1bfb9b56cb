// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// The reduced floor's pushes (smallest_floor_push, smallest_floor_push_in) against brute force: every subset of the
// constraints taken as equalities, its KKT system solved densely in all k coordinates here, and
// the feasible subset with non-negative multipliers is the optimum (unique: the metric is SPD).

#include <CGAL/Projective_dynamics/internal/floor_push.h>

#include <Eigen/LU>
#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace {

namespace PDI = CGAL::Projective_dynamics::internal;
typedef Eigen::SparseMatrix<double, Eigen::RowMajor> Sparse;

// The optimum by enumeration of active sets (constraints `rows` with `need`, equalities `held`).
Eigen::VectorXd brute_force_push(const Eigen::MatrixXd& Mr, const Eigen::MatrixXd& Ud, const std::vector<int>& rows,
                                 const Eigen::VectorXd& need, const std::vector<int>& held)
{
  const int k = int(Mr.rows()), c = int(rows.size()), h = int(held.size());
  Eigen::VectorXd best;
  double best_value = 1e300;
  for(int subset = 0; subset < (1 << c); ++subset)
  {
    std::vector<int> on;
    for(int i = 0; i < c; ++i)
      if(subset >> i & 1) on.push_back(i);
    const int a = int(on.size()) + h;
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(k + a, k + a);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(k + a);
    K.topLeftCorner(k, k) = Mr;
    for(int j = 0; j < a; ++j)
    {
      const bool is_held = j >= int(on.size());
      const Eigen::RowVectorXd u = Ud.row(is_held ? held[std::size_t(j - int(on.size()))] : rows[std::size_t(on[std::size_t(j)])]);
      K.block(k + j, 0, 1, k) = u;
      K.block(0, k + j, k, 1) = -u.transpose();
      rhs[k + j] = is_held ? 0.0 : need[on[std::size_t(j)]];
    }
    Eigen::FullPivLU<Eigen::MatrixXd> lu(K);
    if(lu.rank() < k + a) continue; // dependent rows: another subset has the same optimum
    const Eigen::VectorXd s = lu.solve(rhs);
    const Eigen::VectorXd delta = s.head(k);
    bool valid = true;
    for(std::size_t j = 0; j < on.size(); ++j) valid = valid && s[k + int(j)] >= -1e-12;
    for(int i = 0; i < c; ++i) valid = valid && Ud.row(rows[std::size_t(i)]).dot(delta) >= need[i] - 1e-12;
    const double value = delta.dot(Mr * delta);
    if(valid && value < best_value) best_value = value, best = delta;
  }
  return best;
}

// A random SPD kinetic metric (condition numbers up to about 1e3-1e4).
Eigen::MatrixXd random_metric(int k, std::mt19937& rng)
{
  std::normal_distribution<double> normal;
  Eigen::MatrixXd R(k, k);
  for(int i = 0; i < k; ++i)
    for(int j = 0; j < k; ++j) R(i, j) = normal(rng);
  return R.transpose() * R + 0.1 * Eigen::MatrixXd::Identity(k, k);
}

TEST(ProjectiveDynamicsFloorPush, MatchesTheOptimumFoundByEnumeratingActiveSets)
{
  std::mt19937 rng(7);
  std::normal_distribution<double> normal;
  std::uniform_int_distribution<int> column(0, 11);
  int checked = 0;
  for(int trial = 0; trial < 40; ++trial)
  {
    const int k = 12, n = 20;
    // A skinning-like basis: each vertex on three random columns, positive weights.
    std::vector<Eigen::Triplet<double>> t;
    for(int v = 0; v < n; ++v)
      for(int q = 0; q < 3; ++q) t.emplace_back(v, column(rng), 0.2 + std::abs(normal(rng)));
    Sparse U(n, k);
    U.setFromTriplets(t.begin(), t.end());
    const Eigen::MatrixXd Mr = random_metric(k, rng);
    const Eigen::MatrixXd Minv = Mr.inverse();
    const Eigen::MatrixXd Ud(U);
    // Six constraints (some penetrating, some not), the odd trials with a repeated row (nearly
    // dependent contacts), one held vertex in every third trial.
    std::vector<int> rows = {0, 1, 2, 3, 4, 5};
    if(trial % 2) rows[5] = rows[4];
    Eigen::VectorXd need(6);
    for(int i = 0; i < 6; ++i) need[i] = normal(rng);
    if(trial % 2) need[5] = need[4] - 0.01;
    std::vector<int> held;
    if(trial % 3 == 0) held.push_back(6);

    const Eigen::VectorXd truth = brute_force_push(Mr, Ud, rows, need, held);
    ASSERT_EQ(truth.size(), k) << "trial " << trial << ": no feasible active set";
    PDI::Floor_push_report report;
    const Eigen::VectorXd delta = PDI::smallest_floor_push(U, Minv, rows, need, held, 1e-10, &report);
    // The augmented Lagrangian stops at a violation of 1e-10 (lengths of order 1 here: about
    // what the Newton matrix's condition number, ~1e5-1e6, lets rounding reach, times a
    // hundred); the push is that close to the optimum up to the metric's conditioning.
    EXPECT_LT((delta - truth).norm(), 1e-7 * (1 + truth.norm())) << "trial " << trial << "\n" << delta.transpose() << "\n" << truth.transpose();
    EXPECT_LE(report.largest_violation, 1e-10) << "trial " << trial << " after " << report.updates << " updates";
    EXPECT_LE(report.columns, k);
    ++checked;
  }
  EXPECT_EQ(checked, 40);
}

TEST(ProjectiveDynamicsFloorPush, WithinChosenColumnsMatchesEnumerationOnThoseColumns)
{
  // The push within columns T: the enumeration on U(:, T) with the metric Mr(T, T); the other
  // columns must not move.
  std::mt19937 rng(11);
  std::normal_distribution<double> normal;
  std::uniform_int_distribution<int> column(0, 11);
  for(int trial = 0; trial < 30; ++trial)
  {
    const int k = 12, n = 20;
    std::vector<Eigen::Triplet<double>> t;
    for(int v = 0; v < n; ++v)
    {
      // Skinning-like: positive weights, a column of T of its own for each of the first six.
      t.emplace_back(v, 2 * (v % 6), 0.5 + std::abs(normal(rng)));
      for(int q = 0; q < 2; ++q) t.emplace_back(v, column(rng), 0.1 + 0.5 * std::abs(normal(rng)));
    }
    Sparse U(n, k);
    U.setFromTriplets(t.begin(), t.end());
    const Eigen::MatrixXd Mr = random_metric(k, rng);
    const std::vector<int> T = {0, 2, 4, 6, 8, 10};
    const Eigen::MatrixXd Ud(U);
    Eigen::MatrixXd MrT(6, 6), UdT(n, 6);
    for(int a = 0; a < 6; ++a)
    {
      UdT.col(a) = Ud.col(T[std::size_t(a)]);
      for(int b = 0; b < 6; ++b) MrT(a, b) = Mr(T[std::size_t(a)], T[std::size_t(b)]);
    }
    // Five constraints and, every third trial, a held vertex with a T column of its own (so a
    // push always exists).
    const std::vector<int> rows = {0, 1, 2, 3, 4};
    Eigen::VectorXd need(5);
    for(int i = 0; i < 5; ++i) need[i] = normal(rng);
    std::vector<int> held;
    if(trial % 3 == 0) held.push_back(5);
    const Eigen::VectorXd truth_T = brute_force_push(MrT, UdT, rows, need, held);
    ASSERT_EQ(truth_T.size(), 6) << "trial " << trial;
    const Eigen::VectorXd delta = PDI::smallest_floor_push_in(U, Mr, T, rows, need, held, 1e-10);
    for(int c = 0; c < k; ++c)
    {
      const double expected = c % 2 == 0 ? truth_T[c / 2] : 0.0;
      EXPECT_NEAR(delta[c], expected, 1e-7 * (1 + truth_T.norm())) << "trial " << trial << " column " << c;
    }
  }
}

TEST(ProjectiveDynamicsFloorPush, OneContactIsTheClosedFormPushAndTouchesOnlyItsColumns)
{
  // One vertex, no other constraint: delta = Minv u^T need / (u Minv u^T), exactly.
  const int k = 8;
  Eigen::MatrixXd R = Eigen::MatrixXd::Random(k, k);
  const Eigen::MatrixXd Mr = R.transpose() * R + Eigen::MatrixXd::Identity(k, k);
  const Eigen::MatrixXd Minv = Mr.inverse();
  Sparse U(3, k);
  U.insert(0, 1) = 0.25, U.insert(0, 5) = 0.75, U.insert(1, 0) = 1, U.insert(2, 7) = 1;
  const Eigen::RowVectorXd u = Eigen::MatrixXd(U).row(0);
  const double need = 0.3;
  const Eigen::VectorXd truth = Minv * u.transpose() * (need / u.dot(Minv * u.transpose()));
  PDI::Floor_push_report report;
  const Eigen::VectorXd delta = PDI::smallest_floor_push(U, Minv, {0}, Eigen::VectorXd::Constant(1, need), {}, 1e-13, &report);
  EXPECT_LT((delta - truth).norm(), 1e-10 * truth.norm()) << delta.transpose() << "\n" << truth.transpose();
  EXPECT_EQ(report.columns, 2); // the problem's size is the columns of the contact, not k
  // A constraint already met needs no push at all.
  const Eigen::VectorXd none = PDI::smallest_floor_push(U, Minv, {0}, Eigen::VectorXd::Constant(1, -0.3), {}, 1e-13);
  EXPECT_EQ(none.norm(), 0);
}

} // namespace
