// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Bezier segments evaluated by de Casteljau, elliptical arcs by their angle, contours mapped by
// affine maps and sampled into polylines.

#include <CGAL/Spline_approximation/Bezier_contour.h>
#include <CGAL/Spline_approximation/errors.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace CGAL {
namespace Spline_approximation {

Eigen::RowVector2d Elliptical_arc::operator()(double u) const
{
  const double t = start_angle + u * sweep_angle;
  return center + std::cos(t) * axis_u + std::sin(t) * axis_v;
}

Eigen::RowVector2d Elliptical_arc::derivative(double u) const
{
  const double t = start_angle + u * sweep_angle;
  return sweep_angle * (std::cos(t) * axis_v - std::sin(t) * axis_u);
}

Eigen::RowVector2d Bezier_segment::operator()(double u) const
{
  if(is_arc) {
    // The stored end points at 0 and 1: cos and sin would miss them by round-off.
    if(u == 0) return start();
    if(u == 1) return end();
    return arc(u);
  }
  // de Casteljau: stable, and exact at u = 0 and u = 1 (the joints are met exactly).
  Eigen::Matrix<double, 4, 2> b = control_points;
  for(int r = 1; r <= degree; ++r)
    for(int i = 0; i <= degree - r; ++i) b.row(i) = (1 - u) * b.row(i) + u * b.row(i + 1);
  return b.row(0);
}

Eigen::RowVector2d Bezier_segment::start_derivative() const
{
  if(is_arc) return arc.derivative(0);
  return degree * (control_points.row(1) - control_points.row(0));
}

Eigen::RowVector2d Bezier_segment::end_derivative() const
{
  if(is_arc) return arc.derivative(1);
  return degree * (control_points.row(degree) - control_points.row(degree - 1));
}

bool Bezier_segment::is_point() const
{
  for(int i = 1; i <= degree; ++i)
    if(control_points.row(i) != control_points.row(0)) return false;
  return !is_arc || ((arc.axis_u.array() == 0).all() && (arc.axis_v.array() == 0).all()) || arc.sweep_angle == 0;
}

Bezier_segment Bezier_segment::transformed(const Eigen::Affine2d& m) const
{
  // Row-vector points: p -> p L^T + t.
  const Eigen::Matrix2d Lt = m.linear().transpose();
  const Eigen::RowVector2d t = m.translation().transpose();
  Bezier_segment out = *this;
  for(int i = 0; i <= degree; ++i) out.control_points.row(i) = control_points.row(i) * Lt + t;
  if(is_arc) {
    out.arc.center = arc.center * Lt + t;
    out.arc.axis_u = arc.axis_u * Lt; // vectors: no translation
    out.arc.axis_v = arc.axis_v * Lt;
  }
  return out;
}

Bezier_contour transformed(const Bezier_contour& contour, const Eigen::Affine2d& m)
{
  Bezier_contour out;
  out.closed = contour.closed;
  for(const Bezier_segment& s : contour.segments) out.segments.push_back(s.transformed(m));
  return out;
}

Sampled_contour sample_contour(const Bezier_contour& contour, int samples_per_segment)
{
  if(samples_per_segment < 1)
    throw Invalid_input("sample_contour: at least one sample per segment is needed, not " +
                        std::to_string(samples_per_segment));
  std::vector<const Bezier_segment*> kept;
  for(const Bezier_segment& s : contour.segments) {
    if(s.degree < 1 || s.degree > 3)
      throw Invalid_input("sample_contour: a Bezier segment of degree " + std::to_string(s.degree) + " (1 to 3 expected)");
    if(!s.control_points.topRows(s.degree + 1).allFinite())
      throw Invalid_input("sample_contour: a control point is NaN or infinite");
    if(s.is_arc && (s.degree != 1 || !s.arc.center.allFinite() || !s.arc.axis_u.allFinite() ||
                    !s.arc.axis_v.allFinite() || !std::isfinite(s.arc.start_angle) || !std::isfinite(s.arc.sweep_angle)))
      throw Invalid_input("sample_contour: an elliptical arc with a NaN or infinite value (or not of degree 1)");
    if(!s.is_point()) kept.push_back(&s);
  }
  const Eigen::Index m = Eigen::Index(kept.size()), q = samples_per_segment;
  const bool closed = contour.closed;
  const Eigen::Index rows = m * q + (closed ? 0 : 1);
  if(m == 0 || (closed && rows < 3))
    throw Invalid_input(std::string("sample_contour: the contour has ") + (m == 0 ? "no segment of nonzero length" :
                        "too few samples for a closed curve (raise the samples per segment)"));
  Sampled_contour out;
  out.closed = closed;
  out.points.resize(rows, 2);
  out.parameters.resize(rows);
  for(Eigen::Index i = 0; i < m; ++i) {
    out.joints.push_back(i * q);
    for(Eigen::Index j = 0; j < q; ++j) {
      const double u = double(j) / double(q);
      out.points.row(i * q + j) = (*kept[std::size_t(i)])(u);
      out.parameters[i * q + j] = (double(i) + u) / double(m);
    }
  }
  if(!closed) {
    out.points.row(rows - 1) = kept.back()->end();
    out.parameters[rows - 1] = 1;
  }
  return out;
}

namespace {

bool smooth_joint(const Bezier_segment& a, const Bezier_segment& b, double tolerance)
{
  const Eigen::RowVector2d da = a.end_derivative(), db = b.start_derivative();
  return (da - db).norm() <= tolerance * std::max(da.norm(), db.norm());
}

} // namespace

std::vector<Bezier_contour> split_at_kinks(const Bezier_contour& contour, double relative_tolerance)
{
  std::vector<Bezier_segment> segments;
  for(const Bezier_segment& s : contour.segments)
    if(!s.is_point()) segments.push_back(s); // a point has no direction to compare
  const std::size_t m = segments.size();
  std::vector<std::size_t> kinks; // segment i starts at a kink
  for(std::size_t i = contour.closed ? 0 : 1; i < m; ++i)
    if(!smooth_joint(segments[(i + m - 1) % m], segments[i], relative_tolerance)) kinks.push_back(i);
  if(m == 0) return {};
  if(contour.closed && kinks.empty()) {
    Bezier_contour whole;
    whole.segments = segments;
    whole.closed = true;
    return {whole};
  }
  if(!contour.closed) kinks.insert(kinks.begin(), 0);
  std::vector<Bezier_contour> pieces;
  for(std::size_t k = 0; k < kinks.size(); ++k) {
    Bezier_contour piece;
    const std::size_t first = kinks[k];
    const std::size_t last = k + 1 < kinks.size() ? kinks[k + 1] : (contour.closed ? kinks[0] + m : m);
    for(std::size_t i = first; i < last; ++i) piece.segments.push_back(segments[i % m]);
    pieces.push_back(std::move(piece));
  }
  return pieces;
}

} // namespace Spline_approximation
} // namespace CGAL
