// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SPLINE_APPROXIMATION_SVG_PATHS_H
#define CGAL_SPLINE_APPROXIMATION_SVG_PATHS_H

/// \file Svg_paths.h
/// The geometry of an SVG document read into exact contours of Bezier segments and elliptical
/// arcs: one contour per subpath of every `<path d="...">` and one per basic shape drawn.
///
/// Path data: commands M/m L/l H/h V/v C/c S/s Q/q T/t A/a Z/z, absolute and relative, with
/// implicit repeats (pairs after a moveto are linetos) and the SVG number grammar (`1e-3`, `.5.5`
/// is two numbers, `-1-2` too; an arc flag is one character, so `a1 1 0 11 2 2` has flags 1 and
/// 1).  An elliptical arc is converted from its end points to its centre and angles (SVG 1.1,
/// F.6.5) and kept exactly (`Elliptical_arc`): radii too small for its end points are scaled up
/// until they fit, a zero radius gives a line, and equal end points give no segment (F.6.6).  A
/// subpath ended by Z is closed (a line segment back to its start is added where it does not end
/// there); a moveto alone draws nothing and gives no contour.
///
/// Basic shapes (SVG 2, chapter 10), exact and starting and turning as the specification's
/// equivalent paths do (clockwise on SVG's y-down screen): `<rect>` (x, y, width, height, rx,
/// ry: one radius given serves for both, none or a zero one gives square corners, each at most
/// half the side; lines, and quarter ellipses at rounded corners, from (x + rx, y)), `<circle>`
/// and `<ellipse>` (four quarter arcs from (cx + rx, cy); `<ellipse>` with one radius uses it for
/// both), `<line>` (open), `<polyline>` (open) and `<polygon>` (closed) with their points in
/// the SVG number grammar.  A width, height or radius of 0 disables the shape (no contour); a
/// negative one, or an odd count of coordinates, is refused.  Repeated points and corners that
/// meet give no segment of zero length; a `<line>` of zero length, or a polyline of one point,
/// gives no contour.
///
/// Where things are: `transform` attributes (matrix, translate, scale, rotate with an optional
/// centre, skewX, skewY, and lists of them) of every element, innermost first; arcs are mapped
/// exactly, also by non-uniform scales and skews.  `<use href="#id">` (or `xlink:href`) draws
/// the element with that id as its child, moved by the `<use>`'s x and y after its own transform;
/// a `<symbol>` so drawn gets the `<use>`'s width and height (100 % by default) as its viewport.
/// A reference outside the file, to no element, or in a cycle (a `<use>` drawing itself, also
/// through others, drawn or not) is refused, and so is a file whose `<use>` elements would draw
/// more than 1,000,000 elements and segments in all (measured before anything is drawn), or
/// nesting more than 256 deep (counting what `<use>` draws).
///
/// **Coordinates are the outermost `<svg>`'s viewport coordinates in CSS px** (96 per inch),
/// y down: its `viewBox` is mapped into its `width` and `height` as `preserveAspectRatio` says
/// (every alignment, `meet` by default, `slice`, `none`).  Lengths anywhere may have the absolute
/// units px, in, cm, mm, Q, pt, pc (converted at 96 px per inch) or be percentages of the
/// viewport they are drawn in; units relative to a font or a window (em, ex, vw, ...) are
/// refused.  The outermost `<svg>`'s width or height as a percentage or not given (the size of
/// a window) is taken from the viewBox: both its size, or one through its aspect ratio; without
/// a viewBox, user units are viewport units (its x and y never apply).  Nested `<svg>` elements
/// are viewports too (x, y, width, height, viewBox).  `Svg_paths::user_to_viewport` is the
/// outermost map, for going back to user units.
///
/// What is drawn: not `<defs>`, `<symbol>`, `<clipPath>`, `<mask>`, `<marker>`, `<pattern>` (and
/// other elements that hold no drawing, such as `<metadata>`) nor what is inside them, except
/// through a `<use>`; not elements with `display="none"` (attribute or `style`) nor what is
/// inside them; not paths and shapes whose inherited `visibility` is hidden or collapse.  CSS is
/// read only for these two properties, from the `style` attribute (which wins over the
/// attribute): any other property there (a `transform`, `x`, `r`, ...) and style sheets
/// (`<style>`) are ignored, and so is every paint property (`fill:none` still gives a contour);
/// `transform="none"` is refused as an unknown function.
/// `<switch>` is read as a group (every child drawn); `<text>` and `<image>` give no contour.

#include <CGAL/Spline_approximation/Bezier_contour.h>

#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Spline_approximation {

/// The contours of an SVG file, in drawing (document) order, in viewport coordinates.
struct Svg_paths
{
  std::vector<Bezier_contour> contours;
  /// `<path>` elements with a `d` attribute drawn (each drawing by a `<use>` counted)
  std::size_t path_elements = 0;
  /// Basic shapes drawn, counted likewise, those of zero size (which give no contour) included
  std::size_t shape_elements = 0;
  /// The outermost `<svg>`'s viewport size in px; 0 where the document does not give it
  double viewport_width = 0, viewport_height = 0;
  /// The outermost `<svg>`'s map from its user units (viewBox) to the viewport coordinates of
  /// `contours`: its inverse gives the coordinates in user units
  Eigen::Affine2d user_to_viewport = Eigen::Affine2d::Identity();
};

/// Parses the value of one `d` attribute.
/// \param source names the input in messages ("'file.svg'", or "path data")
/// \throws Invalid_input with the line and column (counted in `d`) and the reason (also an arc
///         flag other than 0 or 1).
std::vector<Bezier_contour> parse_svg_path_data(const std::string& d, const std::string& source = "path data");

/// Reads the paths and basic shapes an SVG document draws (a small tolerant scan of the XML:
/// comments, CDATA, processing instructions, text and other elements are skipped; an end tag
/// closes the innermost open element of its name).  Every attribute read is checked, also in
/// elements that are not drawn.
/// \param source names the input in messages
/// \throws Invalid_input with the line and column in `text` and the reason: malformed markup
///         (an unterminated tag, comment or attribute value; an attribute without a value or
///         given twice), bad path data or points, a malformed `transform` (an unknown function,
///         a missing parenthesis, a wrong count of numbers, a skew of 90 degrees), a malformed
///         or negative length, an unknown or relative unit, a malformed `viewBox` or
///         `preserveAspectRatio`, a percentage where the viewport's size is not given, a bad or
///         cyclic `<use>` reference, too much drawn by `<use>` or too deep a nesting,
///         coordinates beyond double range, or no path with a `d` attribute and no basic shape
///         drawn at all.
Svg_paths parse_svg_paths(const std::string& text, const std::string& source = "SVG text");

/// Same, from a file.
/// \throws Invalid_input also if the file cannot be read.
Svg_paths read_svg_paths(const std::string& filename);

} // namespace Spline_approximation
} // namespace CGAL

#endif
