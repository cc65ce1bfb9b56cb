// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SPLINE_APPROXIMATION_BEZIER_CONTOUR_H
#define CGAL_SPLINE_APPROXIMATION_BEZIER_CONTOUR_H

/// \file Bezier_contour.h
/// Planar curves made of exact Bezier segments and elliptical arcs (SVG paths, glyph outlines)
/// and their dense sampling into polylines for the fit, the exact segments kept beside the
/// samples as truth.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Spline_approximation {

/// An arc of an ellipse as the affine image of an arc of the unit circle:
/// `p(t) = center + cos(t) axis_u + sin(t) axis_v`, t from `start_angle` to `start_angle + sweep_angle`.
/// `axis_u` and `axis_v` are conjugate semi-diameters (the semi-axes unless an affine map sheared
/// them), so an affine map of the plane maps the arc exactly by mapping the centre and both vectors.
struct Elliptical_arc
{
  Eigen::RowVector2d center = Eigen::RowVector2d::Zero();
  Eigen::RowVector2d axis_u = Eigen::RowVector2d::Zero(), axis_v = Eigen::RowVector2d::Zero();
  double start_angle = 0, sweep_angle = 0; ///< radians; sweep_angle < 0: clockwise in (axis_u, axis_v)

  /// The point at angle `start_angle + u sweep_angle`.
  Eigen::RowVector2d operator()(double u) const;
  /// d/du of the point at u.
  Eigen::RowVector2d derivative(double u) const;
};

/// One segment in the plane: a Bezier segment of degree 1 (a line), 2 (quadratic) or 3 (cubic),
/// or an elliptical arc (`is_arc`).
struct Bezier_segment
{
  int degree = 1; ///< 1..3; an arc has 1 (its control points are its two end points)
  Eigen::Matrix<double, 4, 2> control_points = Eigen::Matrix<double, 4, 2>::Zero(); ///< rows 0..degree used
  bool is_arc = false;
  Elliptical_arc arc; ///< the curve when `is_arc`; its ends are rows 0 and 1 of `control_points`

  /// The point at `u` in [0, 1]: de Casteljau, or the arc at angle start + u sweep.  Exactly
  /// `start()` at 0 and `end()` at 1 (an arc too), so the joints are met exactly.
  Eigen::RowVector2d operator()(double u) const;
  Eigen::RowVector2d start() const { return control_points.row(0); }
  Eigen::RowVector2d end() const { return control_points.row(degree); }
  /// d/du at u = 0 and at u = 1.
  Eigen::RowVector2d start_derivative() const;
  Eigen::RowVector2d end_derivative() const;
  /// Whether the segment is a single point (every control point the start; an arc: also no axes).
  bool is_point() const;
  /// The segment under the affine map `m`: exact for both kinds (control points, or the arc's
  /// centre and conjugate semi-diameters, are mapped).
  Bezier_segment transformed(const Eigen::Affine2d& m) const;
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

/// The contour under the affine map `m` (every segment mapped exactly).
Bezier_contour transformed(const Bezier_contour& contour, const Eigen::Affine2d& m);

/// Samples every segment at `samples_per_segment` values of u spread evenly, the start of each
/// segment included and its end given by the next segment (the end of an open contour is added).
/// Segments of zero length are dropped (they would repeat a sample).  An arc is sampled at angles
/// affine in u, each sample exactly on its ellipse (to round-off).
/// \throws Invalid_input if `samples_per_segment < 1`, a coordinate is not finite, or the
///         contour has nothing left to sample (fewer than two distinct points; closed: three).
Sampled_contour sample_contour(const Bezier_contour& contour, int samples_per_segment);

/// The contour cut at every joint where it is not C^1 in the Bezier parameter (the derivatives
/// in u at the end of one segment and at the start of the next, e.g. `degree (b_last - b_previous)`
/// and `degree (b_1 - b_0)` for Bezier segments, differ by more than
/// `relative_tolerance` times the larger).  A spline with simple knots is C^1 for degree >= 2, so a
/// corner (or a joint that is smooth in shape only, G^1 with unequal speeds) cannot be one of its
/// knots: fitting the pieces separately is how such a contour is recovered exactly.  The pieces
/// are open; a closed contour without such a joint is returned whole and closed.
std::vector<Bezier_contour> split_at_kinks(const Bezier_contour& contour, double relative_tolerance = 1e-12);

} // namespace Spline_approximation
} // namespace CGAL

#endif
