// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SPLINE_APPROXIMATION_BEZIER_CONTOUR_H
#define CGAL_SPLINE_APPROXIMATION_BEZIER_CONTOUR_H

/// \file Bezier_contour.h
/// Planar curves made of exact Bezier segments (SVG paths, glyph outlines) and their dense
/// sampling into polylines for the fit, the exact segments kept beside the samples as truth.

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Spline_approximation {

/// One Bezier segment of degree 1 (a line), 2 (quadratic) or 3 (cubic) in the plane.
struct Bezier_segment
{
  int degree = 1;
  Eigen::Matrix<double, 4, 2> control_points = Eigen::Matrix<double, 4, 2>::Zero(); ///< rows 0..degree used

  /// The point at `u` in [0, 1] (de Casteljau).
  Eigen::RowVector2d operator()(double u) const;
  Eigen::RowVector2d start() const { return control_points.row(0); }
  Eigen::RowVector2d end() const { return control_points.row(degree); }
  /// Whether every control point is the start point (a segment of zero length).
  bool is_point() const;
};

/// A chain of segments, each starting where the previous one ends; closed: the last ends
/// where the first starts (an SVG subpath ended by Z, a glyph contour).
struct Bezier_contour
{
  std::vector<Bezier_segment> segments;
  bool closed = false;
};

/// A contour sampled into a polyline, with where the samples came from.
struct Sampled_contour
{
  Eigen::MatrixXd points;       ///< one row per sample (x, y); closed: the first point is not repeated at the end
  /// The Bezier parameter of each sample, `(segment + u) / segments`: affine in u on every segment,
  /// so a spline fit at these parameters reproduces a contour whose segments meet smoothly enough
  /// (open: from 0 to 1; closed: in [0, 1), period 1, as `fit_spline` takes them).
  Eigen::VectorXd parameters;
  std::vector<Eigen::Index> joints; ///< the index of the sample at the start of every segment
  bool closed = false;
};

/// Samples every segment at `samples_per_segment` values of u spread evenly, the start of each
/// segment included and its end given by the next segment (the end of an open contour is added).
/// Segments of zero length are dropped (they would repeat a sample).
/// \throws Invalid_input if `samples_per_segment < 1`, a coordinate is not finite, or the
///         contour has nothing left to sample (fewer than two distinct points; closed: three).
Sampled_contour sample_contour(const Bezier_contour& contour, int samples_per_segment);

/// The contour cut at every joint where it is not C^1 in the Bezier parameter (the derivatives
/// `degree (b_last - b_previous)` and `degree (b_1 - b_0)` of the two segments differ by more than
/// `relative_tolerance` times the larger).  A spline with simple knots is C^1 for degree >= 2, so a
/// corner (or a joint that is smooth in shape only, G^1 with unequal speeds) cannot be one of its
/// knots: fitting the pieces separately is how such a contour is recovered exactly.  The pieces
/// are open; a closed contour without such a joint is returned whole and closed.
std::vector<Bezier_contour> split_at_kinks(const Bezier_contour& contour, double relative_tolerance = 1e-12);

} // namespace Spline_approximation
} // namespace CGAL

#endif
