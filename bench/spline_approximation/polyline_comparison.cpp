// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Degree 1 against Douglas-Peucker and CGAL's Polyline_simplification_2 at equal measured error.
// Each method's own tolerance means something different (ours: the distance of each sample to the
// fit at its parameter; Douglas-Peucker: the distance to the chord; CGAL: the distance of the
// removed vertices to the new segment, or a ratio of it for the hybrid cost), so every result is
// measured again with one error, the max distance of the input vertices to the output polyline,
// and each method's tolerance is bisected to meet the same target.

#include "polyline_comparison.h"

#include <CGAL/Spline_approximation/Spline_fit.h>
#include <CGAL/Spline_approximation/Svg_paths.h>
#ifdef TVF_HAS_FREETYPE
#include <CGAL/Spline_approximation/Glyph_outline.h>
#endif

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyline_simplification_2/Hybrid_squared_distance_cost.h>
#include <CGAL/Polyline_simplification_2/Squared_distance_cost.h>
#include <CGAL/Polyline_simplification_2/Stop_above_cost_threshold.h>
#include <CGAL/Polyline_simplification_2/simplify.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>

namespace bench_spline {

namespace SA = CGAL::Spline_approximation;
namespace PS = CGAL::Polyline_simplification_2;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;

namespace {

double point_segment_distance(const Eigen::RowVector2d& p, const Eigen::RowVector2d& a, const Eigen::RowVector2d& b)
{
  const Eigen::RowVector2d d = b - a;
  const double L2 = d.squaredNorm();
  const double s = L2 > 0 ? std::clamp((p - a).dot(d) / L2, 0.0, 1.0) : 0.0;
  return (p - a - s * d).norm();
}

// Douglas-Peucker on P's rows first..last (inclusive), marking the kept ones.
void douglas_peucker_range(const Eigen::MatrixXd& P, Eigen::Index first, Eigen::Index last, double eps,
                           std::vector<char>& keep)
{
  std::vector<std::pair<Eigen::Index, Eigen::Index>> stack = {{first, last}};
  keep[std::size_t(first)] = keep[std::size_t(last)] = 1;
  while(!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    double worst = -1;
    Eigen::Index at = -1;
    for(Eigen::Index j = a + 1; j < b; ++j) {
      const double d = point_segment_distance(P.row(j), P.row(a), P.row(b));
      if(d > worst) { worst = d; at = j; }
    }
    if(worst > eps) {
      keep[std::size_t(at)] = 1;
      stack.push_back({a, at});
      stack.push_back({at, b});
    }
  }
}

// One simplification: the output polyline (its vertex rows) for a tolerance.
// The target error is passed too: CGAL's hybrid cost takes it as its ratio.
typedef std::function<Eigen::MatrixXd(const Eigen::MatrixXd&, bool, double, double)> Simplifier;

Eigen::MatrixXd fit_polyline(const Eigen::MatrixXd& P, bool closed, double tolerance, SA::Fit_algorithm a)
{
  SA::Fit_options o;
  o.degree = 1;
  o.algorithm = a;
  o.closed_curve = closed;
  if(a == SA::Fit_algorithm::dynamic_programming) o.rms_error = tolerance; // the DP takes no max bound
  else o.max_error = tolerance;
  return SA::fit_spline(P, o).spline.control_points; // degree 1: the control points are the vertices
}

template <class Cost>
Eigen::MatrixXd cgal_polyline(const Eigen::MatrixXd& P, bool closed, double threshold, const Cost& cost)
{
  std::vector<K::Point_2> in, out;
  for(Eigen::Index j = 0; j < P.rows(); ++j) in.emplace_back(P(j, 0), P(j, 1));
  PS::simplify(in.begin(), in.end(), cost, PS::Stop_above_cost_threshold(threshold), std::back_inserter(out), closed);
  Eigen::MatrixXd Q(Eigen::Index(out.size()), 2);
  for(std::size_t i = 0; i < out.size(); ++i) Q.row(Eigen::Index(i)) << out[i].x(), out[i].y();
  return Q;
}

struct Method
{
  std::string name;
  Simplifier simplify;
  double low, high; // the tolerance range bisected, as factors of the target error
  bool squared;     // the tolerance is a squared distance (CGAL's costs)
};

// The fewest vertices at measured error <= target.  The vertex count is not monotone in the
// tolerance (nor, for CGAL's hybrid cost, the error), so a plain bisection can stop at a poor
// local boundary: 24 tolerances spread geometrically over the method's range are tried, then
// bisection (on the log) refines between the largest one that met the target and the next.
struct Best
{
  std::size_t vertices = 0;
  double measured = 0, tolerance = 0, seconds = 0;
  bool found = false;
  std::string failure;
};

Best bisect(const Method& m, const Comparison_curve& c, double target)
{
  Best best;
  const auto start = std::chrono::steady_clock::now();
  auto run = [&](double factor) {
    const double tol = m.squared ? std::pow(factor * target, 2) : factor * target;
    std::size_t vertices = 0;
    double measured = 0;
    for(std::size_t i = 0; i < c.polylines.size(); ++i) {
      const Eigen::MatrixXd Q = m.simplify(c.polylines[i], c.closed[i], tol, target);
      vertices += std::size_t(Q.rows());
      measured = std::max(measured, max_distance_to_polyline(c.polylines[i], Q, c.closed[i]));
    }
    const bool ok = measured <= target;
    if(ok && (!best.found || vertices < best.vertices)) {
      best.found = true;
      best.vertices = vertices;
      best.measured = measured;
      best.tolerance = tol;
    }
    return ok;
  };
  // A method that gives up (the exact DP: "not computable" beyond its work limit, which comes
  // with looser bounds) ends the search: larger tolerances would only cost more; what it found
  // below stays, with the reason printed beside it.
  try {
    const int scan = 24;
    double met = -HUGE_VAL, above = HUGE_VAL; // logs of factors: the largest that met the target, the next tried
    for(int i = 0; i < scan; ++i) {
      const double f = std::log(m.low) + (std::log(m.high) - std::log(m.low)) * double(i) / double(scan - 1);
      if(run(std::exp(f))) { met = f; above = HUGE_VAL; }
      else if(above == HUGE_VAL && met > -HUGE_VAL) above = f;
    }
    for(int step = 0; step < 8 && met > -HUGE_VAL && above < HUGE_VAL; ++step) {
      const double mid = 0.5 * (met + above);
      (run(std::exp(mid)) ? met : above) = mid;
    }
  } catch(const std::exception& e) {
    best.failure = e.what();
  }
  best.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return best;
}

} // namespace

std::vector<Eigen::Index> douglas_peucker(const Eigen::MatrixXd& P, double eps, bool closed)
{
  std::vector<char> keep(std::size_t(P.rows()), 0);
  if(!closed) {
    douglas_peucker_range(P, 0, P.rows() - 1, eps, keep);
  } else { // two open halves: from vertex 0 to the farthest vertex and back (0 appended as the last row)
    Eigen::Index far = 0;
    for(Eigen::Index j = 1; j < P.rows(); ++j)
      if((P.row(j) - P.row(0)).squaredNorm() > (P.row(far) - P.row(0)).squaredNorm()) far = j;
    Eigen::MatrixXd looped(P.rows() + 1, P.cols());
    looped << P, P.row(0);
    std::vector<char> k(std::size_t(looped.rows()), 0);
    douglas_peucker_range(looped, 0, far, eps, k);
    douglas_peucker_range(looped, far, looped.rows() - 1, eps, k);
    for(std::size_t i = 0; i < keep.size(); ++i) keep[i] = k[i];
  }
  std::vector<Eigen::Index> out;
  for(std::size_t i = 0; i < keep.size(); ++i)
    if(keep[i]) out.push_back(Eigen::Index(i));
  return out;
}

double max_distance_to_polyline(const Eigen::MatrixXd& input, const Eigen::MatrixXd& output, bool closed)
{
  const Eigen::Index m = output.rows(), segments = closed ? m : m - 1;
  double worst = 0;
  for(Eigen::Index j = 0; j < input.rows(); ++j) {
    double nearest = m == 1 ? (input.row(j) - output.row(0)).norm() : std::numeric_limits<double>::infinity();
    for(Eigen::Index s = 0; s < segments; ++s)
      nearest = std::min(nearest, point_segment_distance(input.row(j), output.row(s), output.row((s + 1) % m)));
    worst = std::max(worst, nearest);
  }
  return worst;
}

void polyline_comparison(const std::vector<Comparison_curve>& curves, const std::vector<double>& relative_targets,
                         const std::string& methods)
{
  std::vector<Method> all = {
      {"greedy", [](const Eigen::MatrixXd& P, bool c, double t, double) { return fit_polyline(P, c, t, SA::Fit_algorithm::greedy_removal); },
       0.25, 2.0, false},
      {"penalty", [](const Eigen::MatrixXd& P, bool c, double t, double) { return fit_polyline(P, c, t, SA::Fit_algorithm::penalty_decomposition); },
       0.25, 2.0, false},
      {"exact", [](const Eigen::MatrixXd& P, bool c, double t, double) {
         return fit_polyline(P, c, t, SA::Fit_algorithm::dynamic_programming); // open and closed DPs
       }, 0.02, 1.0, false},
      {"dp", [](const Eigen::MatrixXd& P, bool c, double t, double) {
         const std::vector<Eigen::Index> kept = douglas_peucker(P, t, c);
         Eigen::MatrixXd Q(Eigen::Index(kept.size()), 2);
         for(std::size_t i = 0; i < kept.size(); ++i) Q.row(Eigen::Index(i)) = P.row(kept[i]);
         return Q;
       }, 0.25, 2.0, false},
      {"cgal", [](const Eigen::MatrixXd& P, bool c, double t, double) { return cgal_polyline(P, c, t, PS::Squared_distance_cost()); },
       0.25, 2.0, true},
      // The hybrid cost divides the squared distance by min(ratio^2, the squared distance of the
      // segment to the removed vertex's neighbours): with the target error as the ratio it is
      // CGAL's plain cost (in units of the target) where the polyline's features are larger than
      // the target, and relative to the feature size where they are smaller.
      {"cgal-hybrid", [](const Eigen::MatrixXd& P, bool c, double t, double target) {
         return cgal_polyline(P, c, t / (target * target), PS::Hybrid_squared_distance_cost<double>(target));
       }, 0.25, 2.0, true}};
  std::vector<std::string> selected;
  std::stringstream list(methods);
  for(std::string item; std::getline(list, item, ',');) selected.push_back(item);
  std::printf("%-26s %9s | %-11s %11s %9s %11s %8s | %s\n", "curve (polylines, points)", "target", "method", "tolerance",
              "vertices", "measured", "seconds", "vs Douglas-Peucker");
  for(const Comparison_curve& c : curves) {
    Eigen::RowVector2d lo = c.polylines[0].colwise().minCoeff(), hi = c.polylines[0].colwise().maxCoeff();
    Eigen::Index points = 0;
    for(const Eigen::MatrixXd& P : c.polylines) {
      lo = lo.cwiseMin(P.colwise().minCoeff());
      hi = hi.cwiseMax(P.colwise().maxCoeff());
      points += P.rows();
    }
    const double extent = (hi - lo).maxCoeff();
    char label[64];
    std::snprintf(label, sizeof label, "%s (%zu, %lld)", c.name.c_str(), c.polylines.size(), (long long)points);
    for(double relative : relative_targets) {
      const double target = relative * extent;
      std::vector<std::pair<std::string, Best>> results;
      for(const Method& m : all)
        if(std::find(selected.begin(), selected.end(), m.name) != selected.end())
          results.push_back({m.name, bisect(m, c, target)});
      std::size_t dp_vertices = 0;
      for(const auto& r : results)
        if(r.first == "dp" && r.second.found) dp_vertices = r.second.vertices;
      for(const auto& [name, b] : results) {
        if(!b.found) {
          std::printf("%-26s %9.3g | %-11s %s\n", label, target, name.c_str(),
                      b.failure.empty() ? "target not met in the tolerance range" : ("not computable: " + b.failure.substr(0, 70)).c_str());
          continue;
        }
        std::printf("%-26s %9.3g | %-11s %11.4g %9zu %11.4g %8.2f | ", label, target, name.c_str(), b.tolerance, b.vertices,
                    b.measured, b.seconds);
        if(dp_vertices > 0) std::printf("%+.1f %%", 100.0 * (double(b.vertices) / double(dp_vertices) - 1.0));
        else std::printf("-");
        std::printf("%s\n", b.failure.empty() ? "" : " (gave up at a larger tolerance: not computable)");
      }
    }
  }
}

std::vector<Comparison_curve> comparison_curves(const std::string& svg_file, int samples_per_segment)
{
  std::vector<Comparison_curve> out;
  auto add = [&](const std::string& name, const std::vector<SA::Bezier_contour>& contours) {
    Comparison_curve c;
    c.name = name;
    for(const SA::Bezier_contour& contour : contours) {
      const SA::Sampled_contour s = SA::sample_contour(contour, samples_per_segment);
      c.polylines.push_back(s.points);
      c.closed.push_back(s.closed);
    }
    out.push_back(std::move(c));
  };
#ifdef TVF_HAS_FREETYPE
  if(std::ifstream(SA::default_glyph_font))
    for(const char* glyph : {"g", "S", "&"})
      add(std::string("glyph '") + glyph + "'", SA::read_glyph_outline(SA::default_glyph_font, SA::first_code_point(glyph), 1000).contours);
#endif
  if(!svg_file.empty()) {
    add(svg_file, SA::read_svg_paths(svg_file).contours);
  } else {
    // A drawing made for this benchmark: a wave of cubics (open: the exact DP takes it), and a
    // closed blob of cubics and quadratics.
    add("svg wave (open)", SA::parse_svg_path_data("M 0 50 C 20 0 40 0 60 50 S 100 100 120 50 S 160 0 180 50 S 220 100 240 50"));
    add("svg blob (closed)",
        SA::parse_svg_path_data("M 40 200 C 60 140 140 130 170 180 Q 200 230 150 260 T 60 250 C 20 240 30 220 40 200 Z"));
  }
  return out;
}

} // namespace bench_spline
