// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Fits a generated planar curve (CGAL Point_2, a noisy rose) with the fewest cubic knots
// within a max error, and the fewest polyline vertices with the exact dynamic programming;
// prints the knots and the errors; then a closed curve (a noisy ellipse with a wiggle) by a
// periodic cubic spline.
//
// Usage: fit_curve [number-of-points] [max-error]

#include <CGAL/Spline_approximation/approximate_curve.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>
#include <vector>

namespace SA = CGAL::Spline_approximation;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;

int main(int argc, char** argv)
{
  const int n = argc > 1 ? std::atoi(argv[1]) : 2000;
  const double tolerance = argc > 2 ? std::atof(argv[2]) : 0.005;
  std::mt19937 gen(1);
  std::normal_distribution<double> noise(0.0, 0.0005);
  std::vector<K::Point_2> points;
  for(int j = 0; j < n; ++j) {
    const double s = 3.0 * double(j) / double(n - 1), r = std::cos(2 * s) + 0.2 * s;
    points.emplace_back(r * std::cos(s) + noise(gen), r * std::sin(s) + noise(gen));
  }
  try {
    const SA::Spline_fit cubic = SA::approximate_curve(points, SA::parameters::max_error_bound(tolerance));
    std::cout << n << " points, cubic within max error " << tolerance << " (" << SA::algorithm_name(cubic.algorithm)
              << "): " << cubic.number_of_knots() << " knots, " << cubic.spline.control_points.rows()
              << " control points, max error " << cubic.max_error << ", rms " << cubic.rms_error
              << ", within bound: " << (cubic.within_bound ? "yes" : "no") << ", " << cubic.seconds << " s\n";
    std::cout << "knots:";
    for(Eigen::Index i = 0; i < cubic.spline.knots.size(); ++i) std::cout << ' ' << cubic.spline.knots[i];
    std::cout << '\n';
    // Degree 1: the exact optimum of |A X - P|^2 + lambda #knots (dynamic programming on a grid
    // of 25 candidate knots), against the penalty decomposition on the same candidates.
    const double lambda = 0.02;
    auto np = SA::parameters::spline_degree(1).knot_penalty(lambda).candidate_grid_size(std::size_t(25));
    const SA::Spline_fit exact = SA::approximate_curve(points, np.fit_algorithm(SA::Fit_algorithm::dynamic_programming));
    const SA::Spline_fit pd = SA::approximate_curve(points, np);
    std::cout << "polyline, lambda " << lambda << ": optimum " << exact.number_of_knots() + 2 << " vertices (objective "
              << exact.objective << "), penalty decomposition " << pd.number_of_knots() + 2 << " vertices (objective "
              << pd.objective << ", gap " << 100 * (pd.objective / exact.objective - 1) << " %)\n";
    std::cout << "largest errors: cubic at sample ";
    Eigen::Index worst;
    cubic.errors.maxCoeff(&worst);
    std::cout << worst << " (" << cubic.errors[worst] << "), polyline " << exact.max_error << '\n';
    // A closed curve: the last point joins the first (not repeated), the spline is periodic.
    std::vector<K::Point_2> loop;
    for(int j = 0; j < n; ++j) {
      const double a = 2 * M_PI * double(j) / double(n), r = 1 + 0.1 * std::sin(5 * a);
      loop.emplace_back(1.5 * r * std::cos(a) + noise(gen), r * std::sin(a) + noise(gen));
    }
    const SA::Spline_fit closed = SA::approximate_curve(loop, SA::parameters::max_error_bound(tolerance).closed_curve(true));
    std::cout << "closed curve within max error " << tolerance << ": " << closed.number_of_knots() << " knots, "
              << closed.spline.control_points.rows() << " control points, max error " << closed.max_error
              << ", closed: " << (closed.closed() ? "yes" : "no") << ", gap at the seam "
              << (closed.spline(0.0) - closed.spline(1.0)).norm() << '\n';
  } catch(const SA::Invalid_input& e) {
    std::cerr << "refused: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
