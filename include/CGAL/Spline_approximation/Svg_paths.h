// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SPLINE_APPROXIMATION_SVG_PATHS_H
#define CGAL_SPLINE_APPROXIMATION_SVG_PATHS_H

/// \file Svg_paths.h
/// SVG path data (`<path d="...">`) read into exact Bezier contours: one contour per subpath.
///
/// Commands M/m L/l H/h V/v C/c S/s Q/q T/t Z/z, absolute and relative, with implicit repeats
/// (pairs after a moveto are linetos) and the SVG number grammar (`1e-3`, `.5.5` is two numbers,
/// `-1-2` too).  Elliptical arcs (A/a) are refused with the reason: an arc is not a Bezier
/// curve, so it has no exact truth here (convert arcs to curves first).  A subpath ended by Z
/// is closed (a line segment back to its start is added where it does not end there); a moveto
/// alone draws nothing and gives no contour.  Coordinates are kept as written: `transform`
/// attributes are not applied (they are counted, so the caller can warn), and y points down as in SVG.

#include <CGAL/Spline_approximation/Bezier_contour.h>

#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Spline_approximation {

/// The contours of an SVG file, in document order.
struct Svg_paths
{
  std::vector<Bezier_contour> contours;
  std::size_t path_elements = 0;      ///< `<path>` elements with a `d` attribute
  std::size_t transforms_ignored = 0; ///< elements with a `transform` attribute (not applied)
};

/// Parses the value of one `d` attribute.
/// \param source names the input in messages ("'file.svg'", or "path data")
/// \throws Invalid_input with the line and column (counted in `d`) and the reason.
std::vector<Bezier_contour> parse_svg_path_data(const std::string& d, const std::string& source = "path data");

/// Reads the `d` attribute of every `<path>` element of an SVG document (a small tolerant scan
/// of the XML: comments, CDATA, processing instructions and other elements are skipped).
/// \param source names the input in messages
/// \throws Invalid_input with the line and column in `text` and the reason: malformed markup
///         (an unterminated tag, comment or attribute value; an attribute without a value),
///         bad path data, or no path data at all.
Svg_paths parse_svg_paths(const std::string& text, const std::string& source = "SVG text");

/// Same, from a file.
/// \throws Invalid_input also if the file cannot be read.
Svg_paths read_svg_paths(const std::string& filename);

} // namespace Spline_approximation
} // namespace CGAL

#endif
