// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Test data built independently of the package: splines in the truncated-power form
// p(t) + sum_i c_i (t - kappa_i)_+^k, whose k-th derivative jumps exactly at the kappa_i.

#ifndef SPLINE_APPROXIMATION_TEST_DATA_H
#define SPLINE_APPROXIMATION_TEST_DATA_H

#include <Eigen/Core>

#include <cmath>
#include <random>
#include <vector>

namespace spline_test {

// Samples of a degree-k spline in D = 2 with the given knots, at the parameters t.
inline Eigen::MatrixXd truncated_power_spline(const Eigen::VectorXd& t, int k, const std::vector<double>& knots)
{
  Eigen::MatrixXd P(t.size(), 2);
  for(Eigen::Index j = 0; j < t.size(); ++j) {
    const double x = t[j];
    // a polynomial part of degree <= k
    double a = 0.3 + 1.1 * x - (k >= 2 ? 0.7 * x * x : 0.0), b = -0.2 + 0.5 * x + (k >= 2 ? 0.9 * std::pow(x, k) : 0.0);
    for(std::size_t i = 0; i < knots.size(); ++i) {
      const double d = x > knots[i] ? std::pow(x - knots[i], k) : 0.0;
      const double s = (k == 1 ? 1.0 : k == 2 ? 8.0 : 40.0); // comparable jumps for every degree
      a += s * (i % 2 ? -1.5 : 2.0) * d;
      b += s * (1.0 + 0.5 * double(i)) * d;
    }
    P(j, 0) = a;
    P(j, 1) = b;
  }
  return P;
}

inline Eigen::VectorXd uniform_parameters(Eigen::Index n)
{
  return Eigen::VectorXd::LinSpaced(n, 0.0, 1.0);
}

// A wiggly noisy planar curve with n samples.
inline Eigen::MatrixXd noisy_curve(Eigen::Index n, unsigned seed, double noise = 0.02)
{
  std::mt19937 gen(seed);
  std::normal_distribution<double> g(0.0, noise);
  Eigen::MatrixXd P(n, 2);
  for(Eigen::Index j = 0; j < n; ++j) {
    const double s = double(j) / double(n - 1);
    P(j, 0) = std::cos(3 * s) + 0.3 * s + g(gen);
    P(j, 1) = std::sin(5 * s) * (1 + s) + g(gen);
  }
  return P;
}

} // namespace spline_test

#endif
