// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The pictures of tvf fit: data (grey), fit (blue) and knots (red) as SVG or PNG (Cairo), and
// the chart of the error against the knot count.

#ifndef TVF_TOOL_SPLINE_PICTURES_H
#define TVF_TOOL_SPLINE_PICTURES_H

#include <CGAL/Model_reduction/svg_chart.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace tvf_tool {

/// One curve of a picture: its samples, the fitted curve densely sampled, and the knots' points.
struct Fit_picture_curve
{
  Eigen::MatrixXd samples, fit, knots;
  bool closed = false;
};

/// Seen along z, x and y at one scale; `y_down`: the data's y axis points down (SVG input).
void write_fit_svg(const std::string& path, const std::vector<Fit_picture_curve>& curves, bool y_down);

/// Same as a PNG drawn by Cairo.
/// \throws Tool_error if this tvf was built without Cairo, or the file cannot be written.
void write_fit_png(const std::string& path, const std::vector<Fit_picture_curve>& curves, bool y_down);

/// The chart (SVG) of the error against the knot count.
void write_error_chart(const std::string& path, const CGAL::Model_reduction::Line_chart& chart);

} // namespace tvf_tool

#endif
