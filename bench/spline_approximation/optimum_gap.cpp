// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "optimum_gap.h"

#include <CGAL/Spline_approximation/Spline_fit.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

namespace SA = CGAL::Spline_approximation;

namespace bench_spline {
namespace {

// A rose-like planar curve with noise, and a random walk with a drifting heading: a smooth
// curve with a few sharp turns, and one with detail at every scale.
Eigen::MatrixXd gap_rose(Eigen::Index n, unsigned seed)
{
  std::mt19937 gen(seed);
  std::normal_distribution<double> g(0.0, 0.002);
  Eigen::MatrixXd P(n, 2);
  for(Eigen::Index j = 0; j < n; ++j) {
    const double s = 3.0 * double(j) / double(n - 1), r = std::cos(2 * s) + 0.2 * s;
    P.row(j) << r * std::cos(s) + g(gen), r * std::sin(s) + g(gen);
  }
  return P;
}

Eigen::MatrixXd gap_walk(Eigen::Index n, unsigned seed)
{
  std::mt19937 gen(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  Eigen::MatrixXd P(n, 2);
  double x = 0, y = 0, heading = 0;
  for(Eigen::Index j = 0; j < n; ++j) {
    heading += 0.2 * g(gen);
    x += 0.01 * std::cos(heading);
    y += 0.01 * std::sin(heading);
    P.row(j) << x, y;
  }
  return P;
}

struct Method
{
  const char* name;
  SA::Fit_algorithm algorithm;
  bool relocate;
  double gap_sum = 0, gap_max = 0, seconds = 0;
  int over_5 = 0;
};

} // namespace

void optimum_gap_table(std::size_t grid, unsigned seeds)
{
  std::printf("\n8. degree 1, fewest vertices within an RMS bound (a fraction of the diagonal), %zu candidate knots:\n"
              "   vertices (knots + 2) against the exact optimum of the dynamic programming, with and without knot "
              "relocation\n",
              grid);
  std::vector<Method> methods = {{"greedy, no relocation", SA::Fit_algorithm::greedy_removal, false},
                                 {"greedy", SA::Fit_algorithm::greedy_removal, true},
                                 {"penalty, no relocation", SA::Fit_algorithm::penalty_decomposition, false},
                                 {"penalty", SA::Fit_algorithm::penalty_decomposition, true}};
  std::printf("%-6s %6s %4s %6s | %8s %8s |", "curve", "samples", "seed", "bound", "optimum", "seconds");
  for(const Method& m : methods) std::printf(" %s |", m.name);
  std::printf("\n");
  int problems = 0;
  double dp_seconds = 0;
  for(unsigned seed = 1; seed <= seeds; ++seed)
    for(Eigen::Index n : {600, 1500})
      for(int family = 0; family < 2; ++family)
        for(double relative : {2e-2, 1e-2, 5e-3, 3e-3}) {
          const Eigen::MatrixXd P = family == 0 ? gap_rose(n, seed) : gap_walk(n, seed);
          const double diagonal = (P.colwise().maxCoeff() - P.colwise().minCoeff()).norm();
          SA::Fit_options o;
          o.degree = 1;
          o.candidate_grid_size = grid;
          o.rms_error = relative * diagonal;
          o.algorithm = SA::Fit_algorithm::dynamic_programming;
          SA::Spline_fit exact;
          try {
            exact = SA::fit_spline(P, o);
          } catch(const SA::Invalid_input&) {
            continue; // beyond the DP's work limit: no known optimum
          }
          // Every candidate kept and still over the bound: the bound is below the noise.
          if(!exact.within_bound) continue;
          ++problems;
          dp_seconds += exact.seconds;
          const double optimum = double(exact.number_of_knots() + 2);
          std::printf("%-6s %6lld %4u %6.0e | %8.0f %8.3f |", family == 0 ? "rose" : "walk", (long long)n, seed,
                      relative, optimum, exact.seconds);
          for(Method& m : methods) {
            o.algorithm = m.algorithm;
            o.relocate_knots_up_to = m.relocate ? SIZE_MAX : 0;
            const SA::Spline_fit f = SA::fit_spline(P, o);
            const double gap = (double(f.number_of_knots() + 2) - optimum) / optimum;
            m.gap_sum += gap;
            m.gap_max = std::max(m.gap_max, gap);
            m.over_5 += gap > 0.05;
            m.seconds += f.seconds;
            std::printf(" %4zu %+6.1f%% %s |", f.number_of_knots() + 2, 100 * gap, f.within_bound ? "    " : "MISS");
          }
          std::printf("\n");
        }
  std::printf("%d problems; the dynamic programming took %.2f s in all\n", problems, dp_seconds);
  std::printf("%-24s | %9s %9s %12s %9s\n", "method", "mean gap", "max gap", "over 5 %", "seconds");
  for(const Method& m : methods)
    std::printf("%-24s | %8.2f%% %8.1f%% %6d of %-3d %9.3f\n", m.name, 100 * m.gap_sum / std::max(1, problems),
                100 * m.gap_max, m.over_5, problems, m.seconds);
}

} // namespace bench_spline
