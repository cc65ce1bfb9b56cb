// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Degree 1 side by side with the classic polyline simplifiers (issue 37, item 3a): our fits
// (greedy, penalty, exact DP), Douglas-Peucker and CGAL's Polyline_simplification_2, every
// result measured with one independent error.

#ifndef BENCH_SPLINE_APPROXIMATION_POLYLINE_COMPARISON_H
#define BENCH_SPLINE_APPROXIMATION_POLYLINE_COMPARISON_H

#include <Eigen/Core>

#include <string>
#include <vector>

namespace bench_spline {

/// A planar curve of the comparison: one or more polylines (a glyph's contours, an SVG file's
/// subpaths) simplified with one tolerance per method, their vertex counts added.
struct Comparison_curve
{
  std::string name;
  std::vector<Eigen::MatrixXd> polylines; ///< rows are the vertices (x, y)
  std::vector<bool> closed;
};

/// The vertices Douglas-Peucker keeps for a max distance `eps` to the simplified polyline
/// (indices, increasing); closed: split at vertex 0 and the vertex farthest from it.
std::vector<Eigen::Index> douglas_peucker(const Eigen::MatrixXd& P, double eps, bool closed = false);

/// The max over the vertices of `input` of their distance to the polyline `output` (point to
/// segment, the nearest segment; closed: the closing segment included).
double max_distance_to_polyline(const Eigen::MatrixXd& input, const Eigen::MatrixXd& output, bool closed);

/// The table: for each curve and each target error (a fraction of the curve's extent), every
/// method's tolerance bisected so that the measured error is at most the target, and the fewest
/// vertices found.  `methods` selects by name: greedy, penalty, exact, dp (Douglas-Peucker),
/// cgal (Squared_distance_cost), cgal-hybrid (Hybrid_squared_distance_cost).
void polyline_comparison(const std::vector<Comparison_curve>& curves, const std::vector<double>& relative_targets,
                         const std::string& methods);

/// The curves of the comparison besides the caller's: glyph contours (if FreeType was found and
/// the font is there) and SVG paths (a drawing written here, or the file given).
std::vector<Comparison_curve> comparison_curves(const std::string& svg_file, int samples_per_segment);

} // namespace bench_spline

#endif
