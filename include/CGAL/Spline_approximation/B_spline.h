// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SPLINE_APPROXIMATION_B_SPLINE_H
#define CGAL_SPLINE_APPROXIMATION_B_SPLINE_H

/// \file B_spline.h
/// A clamped B-spline curve in D dimensions: degree, knot vector and control points.

#include <Eigen/Core>

#include <cstddef>

namespace CGAL {
namespace Spline_approximation {

/// A clamped B-spline `s(t) = sum_i N_i(t) c_i` on `[knots[0], knots[last]]` (in this package
/// `[0, 1]`): the first and last knots repeated `degree + 1` times, the interior ones simple.
struct B_spline
{
  int degree = 3;                 ///< 1 (polyline) to 3 (cubic)
  Eigen::VectorXd knots;          ///< full, non-decreasing knot vector, size `control_points.rows() + degree + 1`
  Eigen::MatrixXd control_points; ///< one row per control point, one column per dimension

  /// The interior knots (the knot vector without its clamped ends).
  Eigen::VectorXd interior_knots() const
  {
    const Eigen::Index m = knots.size() - 2 * (degree + 1);
    return m > 0 ? Eigen::VectorXd(knots.segment(degree + 1, m)) : Eigen::VectorXd();
  }
  std::size_t number_of_interior_knots() const
  {
    const Eigen::Index m = knots.size() - 2 * (degree + 1);
    return m > 0 ? std::size_t(m) : 0;
  }
  /// The point at parameter `t` (clamped to the knot range), by de Boor's algorithm.
  Eigen::RowVectorXd operator()(double t) const;
  /// The points at every parameter of `t`, one row each.
  Eigen::MatrixXd evaluate(const Eigen::VectorXd& t) const;
};

} // namespace Spline_approximation
} // namespace CGAL

#endif
