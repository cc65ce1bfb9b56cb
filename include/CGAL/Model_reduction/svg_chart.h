// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_MODEL_REDUCTION_SVG_CHART_H
#define CGAL_MODEL_REDUCTION_SVG_CHART_H

/// \file svg_chart.h
/// A small SVG line chart for benchmark tables (e.g. error against time, log-log,
/// one series per mesh).  Plain SVG text: no dependency.

#include <iosfwd>
#include <string>
#include <vector>

namespace CGAL {
namespace Model_reduction {

/// One curve: points joined in the order given, with a marker at each.
struct Chart_series
{
  std::string name;
  std::vector<double> x, y;
};

/// \brief A line chart.
///
/// On a logarithmic axis the ticks are the powers of ten in the range (with 2 and 5
/// between them when fewer than three decades are shown), and points with a
/// non-positive or non-finite coordinate are left out; on a linear axis the ticks
/// are round numbers.
struct Line_chart
{
  std::string title;
  std::string x_label = "time [s]";
  std::string y_label = "error";
  bool log_x = true;
  bool log_y = true;
  int width = 720;
  int height = 480;
  std::vector<Chart_series> series;
};

/// Writes the chart as a standalone SVG document.
/// \throws Invalid_input if a series has different numbers of x and y values, or
///         no point can be drawn, or the stream fails.
void write_svg_line_chart(std::ostream& out, const Line_chart& chart);
/// File-name version.
void write_svg_line_chart(const std::string& filename, const Line_chart& chart);

} // namespace Model_reduction
} // namespace CGAL

#endif
