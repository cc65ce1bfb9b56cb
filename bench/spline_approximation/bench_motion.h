// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The motion tables of bench_spline_approximation (bench_motion.cpp).

#ifndef SPLINE_APPROXIMATION_BENCH_MOTION_H
#define SPLINE_APPROXIMATION_BENCH_MOTION_H

#include <string>
#include <vector>

struct Motion_bench_options
{
  long frames = 4000;                 ///< of the generated walk, at 120 Hz
  double noise_degrees = 0.02;        ///< capture jitter added to every generated angle
  std::vector<std::string> bvh_files; ///< measured too, if given
  std::vector<double> bounds = {0.1, 0.5, 1, 2};
  bool penalty = false;               ///< also the penalty decomposition (slow: a continuation per bisection step)
};

/// 5. compression against the bound in degrees: stored-value ratio, knots, errors, seconds.
void motion_compression_table(const Motion_bench_options& o);
/// 6. a jittery walk regularised: distance to the clean walk before and after.
void motion_jitter_table(const Motion_bench_options& o);

#endif
