// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Degree 1, the fewest vertices within an RMS bound: the heuristics against the exact optimum
// of the dynamic programming, with and without the knot relocation (issue 37's "within 5 % of
// the optimal vertex count"), on open and closed curves.

#ifndef BENCH_SPLINE_APPROXIMATION_OPTIMUM_GAP_H
#define BENCH_SPLINE_APPROXIMATION_OPTIMUM_GAP_H

#include <cstddef>

namespace bench_spline {

/// Prints one row per problem (curve family, samples, seed, bound) and a summary per method:
/// mean and largest vertex gap, problems more than 5 % off, time; open curves (a noisy rose, a
/// random walk) and closed ones (a noisy blob, a closed random walk) as asked, summed apart.
/// `grid` candidate knots.
void optimum_gap_table(std::size_t grid, unsigned seeds, bool open_curves = true, bool closed_curves = false);

} // namespace bench_spline

#endif
