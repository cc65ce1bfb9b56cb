// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Test data built independently of the package: splines in the truncated-power form
// p(t) + sum_i c_i (t - kappa_i)_+^k, whose k-th derivative jumps exactly at the kappa_i.

#ifndef SPLINE_APPROXIMATION_TEST_DATA_H
#define SPLINE_APPROXIMATION_TEST_DATA_H

#include <CGAL/Spline_approximation/Spline_fit.h>

#include <Eigen/Core>
#include <Eigen/LU>

#include <cmath>
#include <random>
#include <vector>

namespace spline_test {

/// Options of a penalty-mode fit: degree, algorithm, lambda, candidate grid (0: every sample).
inline CGAL::Spline_approximation::Fit_options penalty_options(int degree, CGAL::Spline_approximation::Fit_algorithm a,
                                                              double lambda, std::size_t grid = 0, bool closed = false)
{
  CGAL::Spline_approximation::Fit_options o;
  o.degree = degree;
  o.algorithm = a;
  o.penalty = lambda;
  o.candidate_grid_size = grid;
  o.closed_curve = closed;
  return o;
}

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

// A periodic (period 1) degree-k spline in D = 2 whose k-th derivative jumps exactly at the
// given knots in (0, 1) and nowhere else (not at the seam 0): the truncated-power form
// sum_e a_e x^e + sum_i c_i (x - kappa_i)_+^k on [0, 1), its coefficients drawn from the null
// space of the k + 1 conditions s^(d)(1) = s^(d)(0), d = 0..k.  `jumps` returns the c_i per
// dimension (the caller checks they are far from zero: every knot is needed).
inline Eigen::MatrixXd periodic_spline(const Eigen::VectorXd& t, int k, const std::vector<double>& knots,
                                       Eigen::MatrixXd* jumps = nullptr)
{
  const Eigen::Index m = Eigen::Index(knots.size()), unknowns = k + 1 + m;
  auto falling = [](int n, int d) { double f = 1; for(int q = 0; q < d; ++q) f *= double(n - q); return f; };
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(k + 1, unknowns);
  for(int d = 0; d <= k; ++d) {
    for(int e = d + 1; e <= k; ++e) C(d, e) = falling(e, d); // d/dx^d of x^e at 1 minus at 0
    for(Eigen::Index i = 0; i < m; ++i) C(d, k + 1 + i) = falling(k, d) * std::pow(1 - knots[std::size_t(i)], k - d);
  }
  const Eigen::MatrixXd kernel = C.fullPivLu().kernel();
  Eigen::MatrixXd coef(unknowns, 2);
  // Fixed generic combinations of the kernel.
  Eigen::VectorXd w0(kernel.cols()), w1(kernel.cols());
  for(Eigen::Index c = 0; c < kernel.cols(); ++c) {
    w0[c] = 1.0 + 0.37 * double(c);
    w1[c] = std::cos(1.3 * double(c) + 0.4);
  }
  coef.col(0) = kernel * w0;
  coef.col(1) = kernel * w1;
  coef /= coef.cwiseAbs().maxCoeff(); // data of unit size
  if(jumps) *jumps = coef.bottomRows(m);
  Eigen::MatrixXd P(t.size(), 2);
  for(Eigen::Index j = 0; j < t.size(); ++j) {
    const double x = t[j] - std::floor(t[j]);
    for(int c = 0; c < 2; ++c) {
      double v = 0;
      for(int e = 0; e <= k; ++e) v += coef(e, c) * std::pow(x, e);
      for(Eigen::Index i = 0; i < m; ++i)
        if(x > knots[std::size_t(i)]) v += coef(k + 1 + i, c) * std::pow(x - knots[std::size_t(i)], k);
      P(j, c) = v;
    }
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

// A noisy rose-like planar curve with n samples (the benchmark's): smooth and densely sampled.
inline Eigen::MatrixXd noisy_rose(Eigen::Index n, double noise, unsigned seed = 1)
{
  std::mt19937 gen(seed);
  std::normal_distribution<double> g(0.0, noise);
  Eigen::MatrixXd P(n, 2);
  for(Eigen::Index j = 0; j < n; ++j) {
    const double s = 3.0 * double(j) / double(n - 1), r = std::cos(2 * s) + 0.2 * s;
    P(j, 0) = r * std::cos(s) + g(gen);
    P(j, 1) = r * std::sin(s) + g(gen);
  }
  return P;
}

} // namespace spline_test

#endif
