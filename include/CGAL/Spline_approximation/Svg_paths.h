// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SPLINE_APPROXIMATION_SVG_PATHS_H
#define CGAL_SPLINE_APPROXIMATION_SVG_PATHS_H

/// \file Svg_paths.h
/// SVG path data (`<path d="...">`) read into exact contours of Bezier segments and elliptical
/// arcs: one contour per subpath.
///
/// Commands M/m L/l H/h V/v C/c S/s Q/q T/t A/a Z/z, absolute and relative, with implicit repeats
/// (pairs after a moveto are linetos) and the SVG number grammar (`1e-3`, `.5.5` is two numbers,
/// `-1-2` too; an arc flag is one character, so `a1 1 0 11 2 2` has flags 1 and 1).  An
/// elliptical arc is converted from its end points to its centre and angles (SVG 1.1, F.6.5) and
/// kept exactly (`Elliptical_arc`): radii too small for its end points are scaled up until they
/// fit, a zero radius gives a line, and equal end points give no segment (F.6.6).  A subpath ended
/// by Z is closed (a line segment back to its start is added where it does not end there); a moveto
/// alone draws nothing and gives no contour.
///
/// `transform` attributes (matrix, translate, scale, rotate with an optional centre, skewX, skewY,
/// and lists of them) are applied, the path's own and those of every element around it (`<g>`,
/// `<a>`, ...), innermost first; arcs are mapped exactly, also by non-uniform scales and skews.
/// Not applied or not read: `<use>` (its reference is not drawn), the viewport of `<svg>`
/// (`viewBox`, `x`, `y`, `width`, `height`), CSS (a `transform` in `style` or a style sheet;
/// `transform="none"` is refused as an unknown function),
/// other shapes (`<rect>`, `<circle>`, ...), and whether a path is drawn at all: paths inside
/// `<defs>`, `<symbol>`, `<clipPath>`, `<mask>` or `<marker>` are read like any other.  y points
/// down as in SVG.

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
  std::size_t path_elements = 0; ///< `<path>` elements with a `d` attribute
};

/// Parses the value of one `d` attribute.
/// \param source names the input in messages ("'file.svg'", or "path data")
/// \throws Invalid_input with the line and column (counted in `d`) and the reason (also an arc
///         flag other than 0 or 1).
std::vector<Bezier_contour> parse_svg_path_data(const std::string& d, const std::string& source = "path data");

/// Reads the `d` attribute of every `<path>` element of an SVG document (a small tolerant scan
/// of the XML: comments, CDATA, processing instructions and other elements are skipped).
/// \param source names the input in messages
/// \throws Invalid_input with the line and column in `text` and the reason: malformed markup
///         (an unterminated tag, comment or attribute value; an attribute without a value),
///         bad path data, a malformed `transform` (an unknown function, a missing parenthesis,
///         a wrong count of numbers, a skew of 90 degrees), or no path data at all.
Svg_paths parse_svg_paths(const std::string& text, const std::string& source = "SVG text");

/// Same, from a file.
/// \throws Invalid_input also if the file cannot be read.
Svg_paths read_svg_paths(const std::string& filename);

} // namespace Spline_approximation
} // namespace CGAL

#endif
