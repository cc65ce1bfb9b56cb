// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Bezier segments evaluated by de Casteljau, and contours sampled into polylines.

#include <CGAL/Spline_approximation/Bezier_contour.h>
#include <CGAL/Spline_approximation/errors.h>

#include <algorithm>
#include <string>

namespace CGAL {
namespace Spline_approximation {

Eigen::RowVector2d Bezier_segment::operator()(double u) const
{
  // de Casteljau: stable, and exact at u = 0 and u = 1 (the joints are met exactly).
  Eigen::Matrix<double, 4, 2> b = control_points;
  for(int r = 1; r <= degree; ++r)
    for(int i = 0; i <= degree - r; ++i) b.row(i) = (1 - u) * b.row(i) + u * b.row(i + 1);
  return b.row(0);
}

bool Bezier_segment::is_point() const
{
  for(int i = 1; i <= degree; ++i)
    if(control_points.row(i) != control_points.row(0)) return false;
  return true;
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
  const Eigen::RowVector2d da = a.degree * (a.control_points.row(a.degree) - a.control_points.row(a.degree - 1));
  const Eigen::RowVector2d db = b.degree * (b.control_points.row(1) - b.control_points.row(0));
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
