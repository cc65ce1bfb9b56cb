// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The exact optima against each other and against the heuristics: brute force over every
// subset of a small candidate set equals the dynamic programming for degree 1 (penalty and
// RMS bound), and no heuristic beats brute force (which would mean brute force is wrong).

#include <CGAL/Spline_approximation/Spline_fit.h>

#include "spline_test_data.h"

#include <gtest/gtest.h>

namespace SA = CGAL::Spline_approximation;

namespace {

SA::Spline_fit fit(const Eigen::MatrixXd& P, int k, SA::Fit_algorithm a, std::size_t grid, double lambda,
                   double rms = 0)
{
  SA::Fit_options o;
  o.degree = k;
  o.algorithm = a;
  o.candidate_grid_size = grid;
  if(rms > 0) o.rms_error = rms;
  else o.penalty = lambda;
  return SA::fit_spline(P, o);
}

} // namespace

TEST(ExactOptimum, BruteForceEqualsDynamicProgrammingForDegreeOne)
{
  for(unsigned seed = 1; seed <= 4; ++seed) {
    const Eigen::MatrixXd P = spline_test::noisy_curve(60, seed, 0.03);
    for(double lambda : {1e-4, 1e-3, 1e-2, 0.1, 1.0}) {
      SCOPED_TRACE("seed " + std::to_string(seed) + ", lambda " + std::to_string(lambda));
      const SA::Spline_fit brute = fit(P, 1, SA::Fit_algorithm::brute_force, 12, lambda);
      const SA::Spline_fit dp = fit(P, 1, SA::Fit_algorithm::dynamic_programming, 12, lambda);
      EXPECT_NEAR(dp.objective, brute.objective, 1e-10 * brute.objective);
      EXPECT_EQ(dp.kept, brute.kept); // generic data: the optimum is unique
    }
    for(double rms : {0.2, 0.1, 0.05, 0.03}) {
      SCOPED_TRACE("seed " + std::to_string(seed) + ", rms " + std::to_string(rms));
      const SA::Spline_fit brute = fit(P, 1, SA::Fit_algorithm::brute_force, 12, 0, rms);
      const SA::Spline_fit dp = fit(P, 1, SA::Fit_algorithm::dynamic_programming, 12, 0, rms);
      EXPECT_EQ(dp.within_bound, brute.within_bound);
      EXPECT_EQ(dp.number_of_knots(), brute.number_of_knots());
      EXPECT_NEAR(dp.squared_error, brute.squared_error, 1e-10 * brute.squared_error);
    }
  }
}

// With every sample a candidate (68 of them), brute force is out of reach but the DP is not:
// the heuristics must not beat it.
TEST(ExactOptimum, DynamicProgrammingBoundsTheHeuristicsOnEverySampleCandidates)
{
  const Eigen::MatrixXd P = spline_test::noisy_curve(70, 9, 0.01);
  for(double lambda : {1e-4, 1e-3, 1e-2}) {
    const SA::Spline_fit dp = fit(P, 1, SA::Fit_algorithm::dynamic_programming, 0, lambda);
    for(SA::Fit_algorithm a : {SA::Fit_algorithm::penalty_decomposition, SA::Fit_algorithm::greedy_removal}) {
      const SA::Spline_fit h = fit(P, 1, a, 0, lambda);
      EXPECT_GE(h.objective, dp.objective * (1 - 1e-10)) << SA::algorithm_name(a) << " lambda " << lambda;
    }
  }
  for(double rms : {0.05, 0.02}) {
    const SA::Spline_fit dp = fit(P, 1, SA::Fit_algorithm::dynamic_programming, 0, 0, rms);
    for(SA::Fit_algorithm a : {SA::Fit_algorithm::penalty_decomposition, SA::Fit_algorithm::greedy_removal})
      EXPECT_GE(fit(P, 1, a, 0, 0, rms).number_of_knots(), dp.number_of_knots()) << SA::algorithm_name(a);
  }
}

TEST(ExactOptimum, BruteForceBoundsTheHeuristicsForEveryDegree)
{
  for(int k = 1; k <= 3; ++k)
    for(unsigned seed = 1; seed <= 3; ++seed) {
      const Eigen::MatrixXd P = spline_test::noisy_curve(80, 20 + seed, 0.02);
      for(double lambda : {1e-3, 1e-2, 0.1}) {
        const SA::Spline_fit brute = fit(P, k, SA::Fit_algorithm::brute_force, 10, lambda);
        for(SA::Fit_algorithm a : {SA::Fit_algorithm::penalty_decomposition, SA::Fit_algorithm::greedy_removal}) {
          const SA::Spline_fit h = fit(P, k, a, 10, lambda);
          EXPECT_GE(h.objective, brute.objective * (1 - 1e-12))
              << SA::algorithm_name(a) << " degree " << k << " seed " << seed << " lambda " << lambda;
        }
      }
    }
}

// The DP in 3D (D = 3 channels), against brute force.
TEST(ExactOptimum, DynamicProgrammingInThreeDimensions)
{
  Eigen::MatrixXd P(50, 3);
  for(Eigen::Index j = 0; j < 50; ++j) {
    const double s = double(j) / 49;
    P.row(j) << std::cos(4 * s), std::sin(4 * s), s * s + 0.01 * std::sin(37 * s);
  }
  const SA::Spline_fit brute = fit(P, 1, SA::Fit_algorithm::brute_force, 14, 1e-3);
  const SA::Spline_fit dp = fit(P, 1, SA::Fit_algorithm::dynamic_programming, 14, 1e-3);
  EXPECT_EQ(dp.kept, brute.kept);
  EXPECT_NEAR(dp.objective, brute.objective, 1e-10 * brute.objective);
}
