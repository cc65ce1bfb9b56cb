// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Shared by the SVG reader's files (not installed): the document as a tree of the elements that
// matter for geometry, with their attributes already checked (svg_markup.cpp), the values those
// attributes take (svg_values.cpp), the basic shapes' outlines (svg_shapes.cpp), and the walk
// that draws the tree into contours (svg_render.cpp).

#ifndef CGAL_SPLINE_APPROXIMATION_SRC_SVG_DOCUMENT_H
#define CGAL_SPLINE_APPROXIMATION_SRC_SVG_DOCUMENT_H

#include <CGAL/Spline_approximation/Svg_paths.h>

#include "svg_syntax.h"

#include <Eigen/Geometry>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace CGAL {
namespace Spline_approximation {
namespace svg_internal {

const std::size_t no_element = std::size_t(-1);
// The most elements and segments the <use> elements of a file may draw in all (a guard against a
// file that multiplies its content: each level of references may multiply it again).
const std::size_t max_use_expansion = 1000000;

// A length in user units (absolute units converted at 96 px per inch), or a percentage of the
// viewport, resolved only when drawn (the viewport depends on where a <use> draws it).
struct Length
{
  enum Kind { absent, user, percent }; // absent: not given, or 'auto'
  Kind kind = absent;
  double value = 0;
  std::size_t at = 0; // where the value starts, for errors found when it is resolved
};

struct View_box
{
  double x = 0, y = 0, width = 0, height = 0;
  std::size_t at = 0;
};

// preserveAspectRatio: align 0, 1, 2 = min, mid, max on each axis; `none`: each axis scaled alone.
struct Aspect_ratio
{
  bool none = false;
  int align_x = 1, align_y = 1;
  bool slice = false;
};

// The basic shapes last (rect to polygon): `kind >= rect` tells a shape.
enum class Element_kind { container, not_rendered, svg, symbol, use, path, rect, circle, ellipse, line, polyline, polygon };

struct Element
{
  std::string name; // as written, with its prefix (end tags are matched by it)
  Element_kind kind = Element_kind::container;
  std::size_t at = 0; // its '<'
  std::size_t parent = no_element;
  std::vector<std::size_t> children;
  Eigen::Affine2d transform = Eigen::Affine2d::Identity();
  bool transformed = false;
  std::size_t transform_at = 0;
  bool display_none = false;
  int visibility = -1; // -1: inherited, 0: hidden (or collapse), 1: visible
  // The kind's length attributes: <rect> x y width height rx ry, <circle> cx cy r, <ellipse> cx cy
  // rx ry, <line> x1 y1 x2 y2, <use> and <svg> x y width height.
  std::vector<Length> lengths;
  std::vector<Eigen::RowVector2d> points; // <polyline>, <polygon>
  std::vector<Bezier_contour> path;       // <path>: its d, in its own coordinates
  bool has_d = false;
  std::size_t d_at = 0;
  std::size_t target = no_element; // <use>: the element referenced
  std::string href;                 // as written ("#id")
  std::size_t href_at = 0;
  std::size_t drawn_size = 0; // elements and segments drawing it makes, at most (saturated)
  bool shared = false;        // a <use> target or inside one: it may be drawn more than once
  std::optional<View_box> view_box; // <svg>, <symbol>
  Aspect_ratio aspect;
};

struct Svg_document
{
  std::vector<Element> elements; // in document order
  std::vector<std::size_t> top;  // the elements outside any other
};

// svg_markup.cpp: the markup scanned into elements, every attribute read checked, every <use>
// reference resolved, reference cycles refused, and every element measured (drawn_size).
Svg_document read_svg_markup(const Located_text& in);

// svg_values.cpp.  `what` names the attribute in messages ("'width' of <rect>").
Length parse_length(const Located_text& in, std::size_t begin, std::size_t end, const std::string& what,
                    bool auto_allowed);
// Numbers separated by white space and/or one comma.
std::vector<double> parse_number_list(const Located_text& in, std::size_t begin, std::size_t end,
                                      const std::string& what, const char* end_name);
View_box parse_view_box(const Located_text& in, std::size_t begin, std::size_t end);
Aspect_ratio parse_aspect_ratio(const Located_text& in, std::size_t begin, std::size_t end);
// The value of `property` among the CSS declarations of a style attribute in [begin, end),
// trimmed, lower case, without "!important"; empty if not declared (the last declaration wins).
std::string style_property(const std::string& text, std::size_t begin, std::size_t end, const std::string& property);
// [begin, end) trimmed and in lower case (a presentation attribute's keyword).
std::string keyword(const std::string& text, std::size_t begin, std::size_t end);
// The map from a viewBox to the viewport (x, y, width, height) (SVG 2, 8.2).
Eigen::Affine2d view_box_transform(const View_box& box, const Aspect_ratio& aspect, double x, double y, double width,
                                   double height);

// svg_shapes.cpp: the outlines of the basic shapes as SVG 2 (section 10) draws them, in user
// units; nothing where a size of zero disables the shape.  rx or ry absent: std::nullopt.
std::optional<Bezier_contour> rect_outline(double x, double y, double width, double height, std::optional<double> rx,
                                           std::optional<double> ry);
std::optional<Bezier_contour> ellipse_outline(double cx, double cy, double rx, double ry);
std::optional<Bezier_contour> line_outline(double x1, double y1, double x2, double y2);
std::optional<Bezier_contour> polyline_outline(const std::vector<Eigen::RowVector2d>& points, bool closed);

// svg_render.cpp: draws the document into `out` (contours and counts).  The paths no <use> can
// draw are moved out of `document`.
void render_svg(const Located_text& in, Svg_document& document, Svg_paths& out);

} // namespace svg_internal
} // namespace Spline_approximation
} // namespace CGAL

#endif
