// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Indices "unwrapped" around a closed curve: index u stands for entry u mod m, (u div m) periods
// on, so that a knot or a segment can run across the seam.

#ifndef CGAL_SPLINE_APPROXIMATION_PERIODIC_INDEX_H
#define CGAL_SPLINE_APPROXIMATION_PERIODIC_INDEX_H

namespace CGAL {
namespace Spline_approximation {
namespace internal {

typedef long long Index;

// a div b rounded towards minus infinity (b > 0): the period of unwrapped index a.
inline Index floor_div(Index a, Index b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

} // namespace internal
} // namespace Spline_approximation
} // namespace CGAL

#endif
