// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The basic shapes of SVG 2 (section 10) as exact contours: lines, and quarters of ellipses for
// circles, ellipses and rounded corners, each starting where and turning the way the
// specification's equivalent path does.  Every joint is one computed point shared by the two
// segments meeting there, so the contour closes exactly.

#include "svg_document.h"

#include <algorithm>

namespace CGAL {
namespace Spline_approximation {
namespace svg_internal {

namespace {

typedef Eigen::RowVector2d Point;

Bezier_segment line(const Point& from, const Point& to)
{
  Bezier_segment s;
  s.control_points.row(0) = from;
  s.control_points.row(1) = to;
  return s;
}

// The quarter of the ellipse about `center` with semi-axes rx and ry along x and y from angle
// k pi/2 to (k + 1) pi/2 (the angle turning from +x towards +y: clockwise on SVG's y-down
// screen, as an arc with sweep flag 1), from `from` to `to` (its end points, given exactly).
Bezier_segment quarter(const Point& center, double rx, double ry, int k, const Point& from, const Point& to)
{
  const double half_pi = 1.57079632679489661923;
  Bezier_segment s = line(from, to);
  s.is_arc = true;
  s.arc.center = center;
  s.arc.axis_u = Point(rx, 0);
  s.arc.axis_v = Point(0, ry);
  s.arc.start_angle = k * half_pi;
  s.arc.sweep_angle = half_pi;
  return s;
}

} // namespace

std::optional<Bezier_contour> rect_outline(double x, double y, double width, double height, std::optional<double> rx,
                                           std::optional<double> ry)
{
  if(!(width > 0 && height > 0)) return std::nullopt; // zero disables the rectangle
  // SVG 2: one radius given serves for both, none gives square corners, each at most half the side.
  if(!rx) rx = ry;
  if(!ry) ry = rx;
  double a = rx.value_or(0), b = ry.value_or(0);
  if(a == 0 || b == 0) a = b = 0; // a corner needs both radii
  // The corners' coordinates, once: x0 < x1 <= x2 < x3 (x1 = x2 where the radius is half the width).
  const double x0 = x, x3 = x + width, y0 = y, y3 = y + height;
  double x1 = x + a, x2 = x3 - a, y1 = y + b, y2 = y3 - b;
  if(a >= width / 2) {
    a = width / 2;
    x1 = x2 = x + a;
  }
  if(b >= height / 2) {
    b = height / 2;
    y1 = y2 = y + b;
  }
  Bezier_contour c;
  c.closed = true;
  auto add_line = [&](const Point& from, const Point& to) {
    if(from != to) c.segments.push_back(line(from, to)); // none where the corners meet
  };
  const bool round = a > 0;
  add_line(Point(x1, y0), Point(x2, y0));
  if(round) c.segments.push_back(quarter(Point(x2, y1), a, b, 3, Point(x2, y0), Point(x3, y1)));
  add_line(Point(x3, y1), Point(x3, y2));
  if(round) c.segments.push_back(quarter(Point(x2, y2), a, b, 0, Point(x3, y2), Point(x2, y3)));
  add_line(Point(x2, y3), Point(x1, y3));
  if(round) c.segments.push_back(quarter(Point(x1, y2), a, b, 1, Point(x1, y3), Point(x0, y2)));
  add_line(Point(x0, y2), Point(x0, y1));
  if(round) c.segments.push_back(quarter(Point(x1, y1), a, b, 2, Point(x0, y1), Point(x1, y0)));
  return c;
}

std::optional<Bezier_contour> ellipse_outline(double cx, double cy, double rx, double ry)
{
  if(!(rx > 0 && ry > 0)) return std::nullopt; // zero disables the circle or ellipse
  const Point center(cx, cy);
  // From (cx + rx, cy) through (cx, cy + ry), (cx - rx, cy), (cx, cy - ry): SVG 2, 10.3 and 10.4.
  const Point p[5] = {{cx + rx, cy}, {cx, cy + ry}, {cx - rx, cy}, {cx, cy - ry}, {cx + rx, cy}};
  Bezier_contour c;
  c.closed = true;
  for(int k = 0; k < 4; ++k) c.segments.push_back(quarter(center, rx, ry, k, p[k], p[k + 1]));
  return c;
}

std::optional<Bezier_contour> line_outline(double x1, double y1, double x2, double y2)
{
  if(x1 == x2 && y1 == y2) return std::nullopt; // a point has no curve
  Bezier_contour c;
  c.segments.push_back(line(Point(x1, y1), Point(x2, y2)));
  return c;
}

std::optional<Bezier_contour> polyline_outline(const std::vector<Eigen::RowVector2d>& points, bool closed)
{
  Bezier_contour c;
  c.closed = closed;
  for(std::size_t i = 1; i < points.size(); ++i)
    if(points[i] != points[i - 1]) c.segments.push_back(line(points[i - 1], points[i])); // repeated points: no segment
  if(closed && !c.segments.empty() && points.back() != points.front()) c.segments.push_back(line(points.back(), points.front()));
  if(c.segments.empty()) return std::nullopt;
  return c;
}

} // namespace svg_internal
} // namespace Spline_approximation
} // namespace CGAL
