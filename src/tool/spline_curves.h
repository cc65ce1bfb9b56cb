// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The curves `tvf fit` reads: CSV tables, OBJ polylines, the subpaths of SVG files and the
// contours of a font's glyph (the last two sampled from their exact Bezier segments).

#ifndef TVF_TOOL_SPLINE_CURVES_H
#define TVF_TOOL_SPLINE_CURVES_H

#include <CGAL/Spline_approximation/Bezier_contour.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace tvf_tool {

/// One curve to fit: its samples (one row each), whether it is closed, and the parameters to
/// fit it at (empty: chord length).
struct Curve_to_fit
{
  Eigen::MatrixXd samples;
  Eigen::VectorXd parameters;
  bool closed = false;
  std::string name; ///< e.g. "subpath 3", for messages
};

/// The rows of numbers of a CSV or whitespace table (a header row and '#' comments allowed).
/// \throws Tool_error with the line (and column) of the first bad row or cell.
Eigen::MatrixXd read_table(const std::string& path);

/// The vertices of an OBJ polyline: the `l` elements joined end to start (the vertices in file
/// order if there is none).
/// \throws Tool_error with the line of the first bad element.
Eigen::MatrixXd read_obj_polyline(const std::string& path);

/// Every contour sampled at `samples_per_segment` points per Bezier segment; with
/// `bezier_parameters` at the Bezier parameters (affine on every segment), else chord length.
/// Contours too short to sample are skipped.
std::vector<Curve_to_fit> sample_contours(const std::vector<CGAL::Spline_approximation::Bezier_contour>& contours,
                                          int samples_per_segment, bool bezier_parameters, const std::string& kind);

} // namespace tvf_tool

#endif
