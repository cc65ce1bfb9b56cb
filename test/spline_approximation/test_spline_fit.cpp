// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The fit against independent truth: exact recovery of truncated-power splines, the two
// limits of lambda (every knot; one polynomial piece against a QR polynomial fit), bounds met,
// and every answer finished by the least-squares fit on its knots.

#include <CGAL/Spline_approximation/Spline_fit.h>

#include "spline_test_data.h"

#include <Eigen/QR>
#include <gtest/gtest.h>

namespace SA = CGAL::Spline_approximation;
using spline_test::truncated_power_spline;
using spline_test::uniform_parameters;

namespace {

using spline_test::penalty_options;

std::vector<std::size_t> indices(std::initializer_list<std::size_t> l) { return std::vector<std::size_t>(l); }

} // namespace

// Every sample parameter a candidate; the data a spline on three of them.
TEST(SplineFit, RecoversExactKnotsFromEverySampleCandidates)
{
  const Eigen::VectorXd t = uniform_parameters(201); // t_j = j / 200
  for(int k = 1; k <= 3; ++k) {
    const Eigen::MatrixXd P = truncated_power_spline(t, k, {0.25, 0.45, 0.75});
    for(SA::Fit_algorithm a : {SA::Fit_algorithm::penalty_decomposition, SA::Fit_algorithm::greedy_removal}) {
      SCOPED_TRACE(std::string("degree ") + std::to_string(k) + ", " + SA::algorithm_name(a));
      const SA::Spline_fit fit = SA::fit_spline(P, t, penalty_options(k, a, 1e-8));
      // Candidates are t_1 .. t_199: sample j is candidate j - 1.
      EXPECT_EQ(fit.kept, indices({49, 89, 149}));
      EXPECT_LT(fit.max_error, 1e-11);
      ASSERT_EQ(fit.spline.number_of_interior_knots(), 3u);
      EXPECT_NEAR(fit.spline.interior_knots()[1], 0.45, 1e-15);
      // Between the samples too: the spline is the truth.
      const Eigen::VectorXd between = (t.head(200).array() + 0.0025).matrix();
      const Eigen::MatrixXd truth = truncated_power_spline(between, k, {0.25, 0.45, 0.75});
      EXPECT_LT((fit.spline.evaluate(between) - truth).cwiseAbs().maxCoeff(), 1e-11);
    }
  }
}

TEST(SplineFit, RecoversExactKnotsOnAGridWithEveryAlgorithm)
{
  const Eigen::VectorXd t = uniform_parameters(121);
  for(int k = 1; k <= 3; ++k) {
    const Eigen::MatrixXd P = truncated_power_spline(t, k, {0.25, 0.5, 0.75});
    std::vector<SA::Fit_algorithm> algorithms = {SA::Fit_algorithm::penalty_decomposition,
                                                 SA::Fit_algorithm::greedy_removal, SA::Fit_algorithm::brute_force};
    if(k == 1) algorithms.push_back(SA::Fit_algorithm::dynamic_programming);
    for(SA::Fit_algorithm a : algorithms) {
      SCOPED_TRACE(std::string("degree ") + std::to_string(k) + ", " + SA::algorithm_name(a));
      // Candidates i / 12, i = 1..11: the knots are candidates 2, 5 and 8.
      const SA::Spline_fit fit = SA::fit_spline(P, t, penalty_options(k, a, 1e-8, 11));
      EXPECT_EQ(fit.kept, indices({2, 5, 8}));
      EXPECT_LT(fit.max_error, 1e-11);
      // The same knots found by the error bound: the fewest knots at machine precision.
      SA::Fit_options bound = penalty_options(k, a, 0, 11);
      bound.penalty.reset();
      if(a == SA::Fit_algorithm::dynamic_programming) bound.rms_error = 1e-9;
      else bound.max_error = 1e-9;
      const SA::Spline_fit within = SA::fit_spline(P, t, bound);
      EXPECT_EQ(within.kept, indices({2, 5, 8}));
      EXPECT_TRUE(within.within_bound);
    }
  }
}

// lambda -> 0 keeps every knot, and the answer is the least-squares spline on all of them.
TEST(SplineFit, TinyPenaltyKeepsEveryKnot)
{
  const Eigen::MatrixXd P = spline_test::noisy_curve(300, 7);
  for(int k = 1; k <= 3; ++k)
    for(SA::Fit_algorithm a : {SA::Fit_algorithm::penalty_decomposition, SA::Fit_algorithm::greedy_removal}) {
      SCOPED_TRACE(std::string("degree ") + std::to_string(k) + ", " + SA::algorithm_name(a));
      const SA::Spline_fit fit = SA::fit_spline(P, penalty_options(k, a, 1e-14, 20));
      EXPECT_EQ(fit.number_of_knots(), 20u);
      const SA::Spline_fit ls = SA::least_squares_spline(P, fit.parameters, k, fit.candidates);
      EXPECT_NEAR(fit.squared_error, ls.squared_error, 1e-12 * ls.squared_error);
    }
}

// lambda -> infinity keeps none: one polynomial piece, which a QR fit on monomials gives independently.
TEST(SplineFit, HugePenaltyKeepsNoKnotAndIsThePolynomialFit)
{
  const Eigen::MatrixXd P = spline_test::noisy_curve(300, 11);
  for(int k = 1; k <= 3; ++k)
    for(SA::Fit_algorithm a : {SA::Fit_algorithm::penalty_decomposition, SA::Fit_algorithm::greedy_removal}) {
      SCOPED_TRACE(std::string("degree ") + std::to_string(k) + ", " + SA::algorithm_name(a));
      const SA::Spline_fit fit = SA::fit_spline(P, penalty_options(k, a, 1e12));
      EXPECT_EQ(fit.number_of_knots(), 0u);
      const Eigen::VectorXd& t = fit.parameters;
      Eigen::MatrixXd V(t.size(), k + 1);
      for(int e = 0; e <= k; ++e) V.col(e) = (t.array() - 0.5).pow(e).matrix();
      const Eigen::MatrixXd coef = V.householderQr().solve(P);
      EXPECT_LT((fit.spline.evaluate(t) - V * coef).cwiseAbs().maxCoeff(), 1e-12);
      EXPECT_NEAR(fit.squared_error, (V * coef - P).squaredNorm(), 1e-12);
    }
}

// The bound modes meet their bound, and every answer is the least-squares fit on its knots.
TEST(SplineFit, BoundsAreMetAndAnswersAreLeastSquaresFits)
{
  const Eigen::MatrixXd P = spline_test::noisy_curve(400, 3, 0.005);
  for(int k = 1; k <= 3; ++k)
    for(SA::Fit_algorithm a : {SA::Fit_algorithm::penalty_decomposition, SA::Fit_algorithm::greedy_removal}) {
      SCOPED_TRACE(std::string("degree ") + std::to_string(k) + ", " + SA::algorithm_name(a));
      SA::Fit_options o;
      o.degree = k;
      o.algorithm = a;
      o.max_error = 0.02;
      const SA::Spline_fit fit = SA::fit_spline(P, o);
      EXPECT_TRUE(fit.within_bound);
      EXPECT_LE(fit.max_error, 0.02);
      EXPECT_GT(fit.number_of_knots(), 0u);
      EXPECT_LT(fit.number_of_knots(), 100u);
      const SA::Spline_fit ls = SA::least_squares_spline(P, fit.parameters, k, fit.spline.interior_knots());
      EXPECT_LT((ls.spline.control_points - fit.spline.control_points).cwiseAbs().maxCoeff(), 1e-9);
      o.max_error.reset();
      o.rms_error = 0.01;
      const SA::Spline_fit rms = SA::fit_spline(P, o);
      EXPECT_LE(rms.rms_error, 0.01);
      EXPECT_TRUE(rms.within_bound);
    }
}

// The errors reported are the distances to the spline at the samples' parameters.
TEST(SplineFit, ErrorsAreDistancesToTheSpline)
{
  const Eigen::MatrixXd P = spline_test::noisy_curve(150, 5);
  const SA::Spline_fit fit = SA::fit_spline(P, penalty_options(3, SA::Fit_algorithm::penalty_decomposition, 0.01));
  const Eigen::VectorXd d = (fit.spline.evaluate(fit.parameters) - P).rowwise().norm();
  EXPECT_LT((d - fit.errors).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_NEAR(fit.max_error, d.maxCoeff(), 1e-15);
  EXPECT_NEAR(fit.rms_error, std::sqrt(d.squaredNorm() / 150), 1e-15);
  EXPECT_NEAR(fit.objective, d.squaredNorm() + 0.01 * double(fit.number_of_knots()), 1e-12);
  EXPECT_EQ(fit.spline.knots.size(), fit.spline.control_points.rows() + 4);
}

// Penalty mode with every sample a candidate on smooth noisy data: the k-th derivative jumps
// of the full fit are spread over many candidates, each below the threshold.  The continuation
// in lambda must keep a sensible number of knots, and its objective must be within 5 % of greedy
// removal's at the same lambda (the two are heuristics; neither is the optimum, 5 % is the
// spread measured between them on such data).  Made to fail once: without the continuation
// (the old code), the penalty decomposition kept 0 knots at every lambda below, with objectives
// 10x to 1000x greedy's.
TEST(SplineFit, PenaltyOnDenseCandidatesOverSmoothNoisyData)
{
  const Eigen::MatrixXd P = spline_test::noisy_curve(400, 17, 0.002);
  for(int k = 1; k <= 3; ++k)
    for(double lambda : {1e-5, 1e-4, 1e-3}) {
      SCOPED_TRACE(std::string("degree ") + std::to_string(k) + ", lambda " + std::to_string(lambda));
      const SA::Spline_fit pd = SA::fit_spline(P, penalty_options(k, SA::Fit_algorithm::penalty_decomposition, lambda));
      const SA::Spline_fit greedy = SA::fit_spline(P, penalty_options(k, SA::Fit_algorithm::greedy_removal, lambda));
      // The curve (cos 3s, sin 5s (1 + s)) needs knots for any of these lambdas: one polynomial
      // piece leaves a squared error far above the cost of a few knots.
      const SA::Spline_fit none = SA::least_squares_spline(P, pd.parameters, k, Eigen::VectorXd());
      ASSERT_GT(none.squared_error, 100 * lambda);
      EXPECT_GE(pd.number_of_knots(), 2u);
      EXPECT_LT(pd.number_of_knots(), 200u); // far fewer than the 398 candidates
      EXPECT_LE(pd.objective, 1.05 * greedy.objective);
      EXPECT_NEAR(pd.objective, pd.squared_error + lambda * double(pd.number_of_knots()), 1e-12);
    }
  // Denser and smoother: 2000 samples of the benchmark's rose, noise 5e-4, lambda up to 0.1.
  // Made to fail once: with the continuation started at the fixed lambda / 4^6, lambda = 0.1
  // still kept 0 knots (objective 157 against greedy's 0.54).  Measured now: 1.01x and 1.26x
  // greedy's objective; 1.5 leaves room for the heuristics' spread, far below the failure.
  const Eigen::MatrixXd rose = spline_test::noisy_rose(2000, 5e-4);
  for(double lambda : {0.1, 0.01}) {
    SCOPED_TRACE("rose, lambda " + std::to_string(lambda));
    const SA::Spline_fit pd = SA::fit_spline(rose, penalty_options(3, SA::Fit_algorithm::penalty_decomposition, lambda));
    const SA::Spline_fit greedy = SA::fit_spline(rose, penalty_options(3, SA::Fit_algorithm::greedy_removal, lambda));
    EXPECT_GE(pd.number_of_knots(), 2u);
    EXPECT_LE(pd.objective, 1.5 * greedy.objective);
  }
  // The limits on the same data: (nearly) every one of the 398 candidates, at an objective no
  // worse than keeping them all (a knot whose removal costs less than 1e-16 may go: one did for
  // degree 1), or one polynomial piece.
  for(int k = 1; k <= 3; ++k) {
    SCOPED_TRACE(std::string("limits, degree ") + std::to_string(k));
    const SA::Spline_fit tiny = SA::fit_spline(P, penalty_options(k, SA::Fit_algorithm::penalty_decomposition, 1e-16));
    const SA::Spline_fit all = SA::least_squares_spline(P, tiny.parameters, k, tiny.candidates);
    EXPECT_GE(tiny.number_of_knots(), 390u);
    EXPECT_LE(tiny.objective, all.squared_error + 1e-16 * 398 + 1e-15 * all.squared_error);
    EXPECT_EQ(SA::fit_spline(P, penalty_options(k, SA::Fit_algorithm::penalty_decomposition, 1e6)).number_of_knots(), 0u);
  }
}
