// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SPLINE_APPROXIMATION_B_SPLINE_H
#define CGAL_SPLINE_APPROXIMATION_B_SPLINE_H

/// \file B_spline.h
/// A B-spline curve in D dimensions, clamped (open) or periodic (closed): degree, knots and control points.

#include <Eigen/Core>

#include <cstddef>

namespace CGAL {
namespace Spline_approximation {

/// A clamped B-spline `s(t) = sum_i N_i(t) c_i` on `[knots[0], knots[last]]` (in this package
/// `[0, 1]`): the first and last knots repeated `degree + 1` times, the interior ones simple.
/// Closed (`closed == true`): a periodic spline of period 1, `s(t + 1) = s(t)`, with `knots` the
/// m simple knots on the circle, in [0, 1), and m control points (basis function i of the knot
/// vector extended by whole periods uses control point i mod m); without knots it is the
/// constant `control_points.row(0)` (a periodic polynomial is constant), and `knots` is empty.
struct B_spline
{
  int degree = 3;                 ///< 1 (polyline) to 3 (cubic)
  bool closed = false;            ///< periodic of period 1 (a closed curve)
  Eigen::VectorXd knots;          ///< open: full, non-decreasing knot vector, size `control_points.rows() + degree + 1`; closed: the knots in [0, 1)
  Eigen::MatrixXd control_points; ///< one row per control point, one column per dimension

  /// The interior knots (open: the knot vector without its clamped ends; closed: every knot).
  Eigen::VectorXd interior_knots() const
  {
    if(closed) return knots;
    const Eigen::Index m = knots.size() - 2 * (degree + 1);
    return m > 0 ? Eigen::VectorXd(knots.segment(degree + 1, m)) : Eigen::VectorXd();
  }
  std::size_t number_of_interior_knots() const
  {
    if(closed) return std::size_t(knots.size());
    const Eigen::Index m = knots.size() - 2 * (degree + 1);
    return m > 0 ? std::size_t(m) : 0;
  }
  /// The point at parameter `t` (open: clamped to the knot range; closed: taken modulo 1).
  Eigen::RowVectorXd operator()(double t) const;
  /// The points at every parameter of `t`, one row each.
  Eigen::MatrixXd evaluate(const Eigen::VectorXd& t) const;
};

} // namespace Spline_approximation
} // namespace CGAL

#endif
