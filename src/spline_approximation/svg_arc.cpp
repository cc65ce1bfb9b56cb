// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The SVG elliptical arc from its end points to its centre and angles (SVG 1.1 implementation
// notes F.6.5, with the radii corrected as in F.6.6), kept as an exact arc of an ellipse.

#include "svg_syntax.h"

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace Spline_approximation {
namespace svg_internal {

std::optional<Bezier_segment> svg_arc(const Eigen::RowVector2d& from, const Eigen::RowVector2d& to, double rx,
                                      double ry, double rotation_degrees, bool large_arc, bool sweep,
                                      std::string& reason)
{
  reason.clear();
  if(from == to) return std::nullopt; // F.6.2: the arc is omitted
  Bezier_segment s;
  s.degree = 1;
  s.control_points.row(0) = from;
  s.control_points.row(1) = to;
  if(rx == 0 || ry == 0) return s; // F.6.6: a straight line
  rx = std::abs(rx);
  ry = std::abs(ry);
  double c = 1, sn = 0;
  cos_sin_degrees(rotation_degrees, c, sn);
  // Step 1: half the chord in the ellipse's axes, then divided by the radii (X, Y): the ellipse
  // becomes the unit circle, which keeps the squares below out of overflow.
  const Eigen::RowVector2d h = from / 2 - to / 2; // halves first: no overflow near the largest doubles
  const double X = (c * h[0] + sn * h[1]) / rx, Y = (-sn * h[0] + c * h[1]) / ry;
  const double d = std::hypot(X, Y); // the end points' distance from the centre if it were the chord's middle
  if(!(d > 0) || !std::isfinite(d)) {
    reason = "the arc's radii and end points are too far apart in scale to compute it in double precision";
    return std::nullopt;
  }
  double scale = 1, X1 = X, Y1 = Y;
  if(d > 1) { // F.6.6: radii too small, scaled up until the end points are on the ellipse
    scale = d;
    X1 /= scale;
    Y1 /= scale;
  }
  // Step 2: the centre on the unit circle's side given by the flags, then (Step 3) in the plane.
  const double e2 = X1 * X1 + Y1 * Y1;
  const double coefficient = (large_arc != sweep ? 1 : -1) * std::sqrt(std::max(0.0, (1 - e2) / e2));
  const double cX = coefficient * Y1, cY = -coefficient * X1;
  rx *= scale;
  ry *= scale;
  const Eigen::RowVector2d axis_u(rx * c, rx * sn), axis_v(-ry * sn, ry * c);
  s.arc.center = cX * axis_u + cY * axis_v + (from / 2 + to / 2);
  s.arc.axis_u = axis_u;
  s.arc.axis_v = axis_v;
  // Step 4: the angles of the end points on the unit circle, the sweep on the flag's side.
  const double ux = X1 - cX, uy = Y1 - cY, vx = -X1 - cX, vy = -Y1 - cY;
  const double pi = 3.14159265358979323846;
  double delta = std::atan2(ux * vy - uy * vx, ux * vx + uy * vy);
  if(!sweep && delta > 0) delta -= 2 * pi;
  if(sweep && delta < 0) delta += 2 * pi;
  s.arc.start_angle = std::atan2(uy, ux);
  s.arc.sweep_angle = delta;
  s.is_arc = true;
  if(!s.arc.center.allFinite() || !axis_u.allFinite() || !axis_v.allFinite()) {
    reason = "the arc's radii are beyond double range";
    return std::nullopt;
  }
  return s;
}

} // namespace svg_internal
} // namespace Spline_approximation
} // namespace CGAL
