// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// SVG documents beyond <path>: the basic shapes against their curves (a circle's samples at its
// radius, a rounded rectangle's tangents and its perimeter in closed form, polygon vertices as
// written), the viewBox mapped into the viewport (points computed by hand for every kind of
// alignment), <use> with its x, y and transform (in an order where the wrong one gives other
// points), <defs> and <symbol> not drawn by themselves, display and visibility, and bad input
// refused with line, column and reason.

#include <CGAL/Spline_approximation/Svg_paths.h>
#include <CGAL/Spline_approximation/errors.h>

#include "expect_reason.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace SA = CGAL::Spline_approximation;

namespace {

const double elements_test_pi = 3.14159265358979323846;

SA::Svg_paths elements_test_read(const std::string& body, const std::string& svg_attributes = "")
{
  return SA::parse_svg_paths("<svg" + svg_attributes + ">\n" + body + "\n</svg>", "'e.svg'");
}

void elements_test_expect_point(const Eigen::RowVector2d& p, double x, double y, double tolerance = 0)
{
  EXPECT_NEAR(p[0], x, tolerance);
  EXPECT_NEAR(p[1], y, tolerance);
}

// The length of the contour's polyline at `samples` per segment, closed back to its start.
double elements_test_polyline_length(const SA::Bezier_contour& c, int samples)
{
  const SA::Sampled_contour s = SA::sample_contour(c, samples);
  double length = 0;
  const Eigen::Index n = s.points.rows();
  for(Eigen::Index i = 0; i < n; ++i) length += (s.points.row((i + 1) % n) - s.points.row(i)).norm();
  return length;
}

} // namespace

// Made to fail once: with the centre's coordinates swapped in ellipse_outline, the circle's
// samples were up to 7.07 off its radius (the end points, computed apart, stayed right); with
// the second semi-axis of the quarter arcs taken from rx, the ellipse's residual was 3.0.
TEST(SvgShapes, CircleAndEllipseSamplesOnTheirCurves)
{
  const SA::Svg_paths svg =
    elements_test_read("<circle cx='3' cy='-2' r='7'/><ellipse cx='1' cy='2' rx='4' ry='2'/><ellipse ry='3'/>");
  ASSERT_EQ(svg.contours.size(), 3u);
  EXPECT_EQ(svg.shape_elements, 3u);
  EXPECT_EQ(svg.path_elements, 0u);
  const SA::Bezier_contour& circle = svg.contours[0];
  EXPECT_TRUE(circle.closed);
  ASSERT_EQ(circle.segments.size(), 4u);
  // SVG 2: from (cx + r, cy) towards (cx, cy + r), clockwise on the y-down screen.
  EXPECT_EQ(circle.segments[0].start(), Eigen::RowVector2d(10, -2));
  EXPECT_EQ(circle.segments[0].end(), Eigen::RowVector2d(3, 5));
  EXPECT_EQ(circle.segments[3].end(), Eigen::RowVector2d(10, -2));
  const SA::Sampled_contour s = SA::sample_contour(circle, 100);
  double worst = 0;
  for(Eigen::Index i = 0; i < s.points.rows(); ++i)
    worst = std::max(worst, std::abs((s.points.row(i) - Eigen::RowVector2d(3, -2)).norm() - 7));
  EXPECT_LT(worst, 1e-12);
  for(const SA::Bezier_segment& a : circle.segments) EXPECT_TRUE(a.is_arc);
  const SA::Sampled_contour e = SA::sample_contour(svg.contours[1], 100);
  worst = 0;
  for(Eigen::Index i = 0; i < e.points.rows(); ++i) {
    const double u = (e.points(i, 0) - 1) / 4, v = (e.points(i, 1) - 2) / 2;
    worst = std::max(worst, std::abs(u * u + v * v - 1));
  }
  EXPECT_LT(worst, 1e-12);
  EXPECT_EQ(svg.contours[1].segments[1].start(), Eigen::RowVector2d(1, 4));
  // One radius given (the other auto): a circle of that radius.
  EXPECT_EQ(svg.contours[2].segments[0].start(), Eigen::RowVector2d(3, 0));
  EXPECT_EQ(svg.contours[2].segments[0].end(), Eigen::RowVector2d(0, 3));
}

// Made to fail once: with the quarter arcs' sweep negated (each turning the other way from its
// start angle, its end points unchanged), 4 of the 8 joints had opposite unit tangents and the
// perimeter was 414.19 instead of 294.25.
TEST(SvgShapes, RoundedRectTangentContinuousWithItsPerimeter)
{
  const double x = 10, y = 20, w = 100, h = 60, r = 15;
  const SA::Svg_paths svg = elements_test_read("<rect x='10' y='20' width='100' height='60' rx='15'/>");
  ASSERT_EQ(svg.contours.size(), 1u);
  const SA::Bezier_contour& c = svg.contours[0];
  EXPECT_TRUE(c.closed);
  ASSERT_EQ(c.segments.size(), 8u); // 4 sides and 4 corners
  // From (x + rx, y) along the top side, then the corner down to the right side (SVG 2, 10.2).
  EXPECT_EQ(c.segments[0].start(), Eigen::RowVector2d(x + r, y));
  EXPECT_EQ(c.segments[0].end(), Eigen::RowVector2d(x + w - r, y));
  EXPECT_EQ(c.segments[1].end(), Eigen::RowVector2d(x + w, y + r));
  EXPECT_EQ(c.segments[7].end(), Eigen::RowVector2d(x + r, y));
  for(std::size_t i = 0; i < 8; ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(c.segments[i].is_arc, i % 2 == 1);
    const SA::Bezier_segment& a = c.segments[i];
    const SA::Bezier_segment& b = c.segments[(i + 1) % 8];
    EXPECT_EQ(a.end(), b.start());
    EXPECT_LT((a.end_derivative().normalized() - b.start_derivative().normalized()).norm(), 1e-12);
  }
  // 2 (w + h) - (8 - 2 pi) r: each corner trades a square of side r for a quarter circle.
  // The polylines' lengths fall short by O(1/n^2): Richardson's extrapolation leaves O(1/n^4).
  const double coarse = elements_test_polyline_length(c, 512), fine = elements_test_polyline_length(c, 1024);
  EXPECT_NEAR((4 * fine - coarse) / 3, 2 * (w + h) - (8 - 2 * elements_test_pi) * r, 1e-9);
}

// SVG 2's radii: one given serves for both (before either is clamped), each at most half its
// side, a zero one gives square corners.  Made to fail once: with the missing radius copied
// after clamping (ry = min(rx, width / 2)), the first rectangle's corners had ry 20, not 30.
TEST(SvgShapes, RectRadiiAutoClampedAndZero)
{
  const SA::Svg_paths svg = elements_test_read(
    "<rect width='40' height='100' rx='30'/><rect x='1' width='10' height='10' rx='8' ry='100'/>"
    "<rect width='10' height='10' rx='0' ry='3'/><rect x='2' y='3' width='4' height='5'/>"
    "<rect width='0' height='5' rx='1'/><rect width='5'/>",
    " width='200' height='100'");
  EXPECT_EQ(svg.shape_elements, 6u); // the last two drawn with a zero size: no contour
  ASSERT_EQ(svg.contours.size(), 4u);
  const SA::Bezier_contour& tall = svg.contours[0];
  ASSERT_EQ(tall.segments.size(), 6u); // the top and bottom sides have no length left
  ASSERT_TRUE(tall.segments[0].is_arc);
  EXPECT_EQ(tall.segments[0].start(), Eigen::RowVector2d(20, 0));
  EXPECT_EQ(tall.segments[0].end(), Eigen::RowVector2d(40, 30));
  EXPECT_EQ(tall.segments[0].arc.axis_u, Eigen::RowVector2d(20, 0));
  EXPECT_EQ(tall.segments[0].arc.axis_v, Eigen::RowVector2d(0, 30));
  const SA::Bezier_contour& round = svg.contours[1]; // radii 5 and 5: a circle
  ASSERT_EQ(round.segments.size(), 4u);
  EXPECT_EQ(round.segments[0].start(), Eigen::RowVector2d(6, 0));
  EXPECT_EQ(round.segments[0].end(), Eigen::RowVector2d(11, 5));
  for(int k : {2, 3}) {
    const SA::Bezier_contour& square = svg.contours[std::size_t(k)];
    ASSERT_EQ(square.segments.size(), 4u);
    for(const SA::Bezier_segment& s : square.segments) EXPECT_FALSE(s.is_arc);
  }
  EXPECT_EQ(svg.contours[3].segments[0].start(), Eigen::RowVector2d(2, 3));
  EXPECT_EQ(svg.contours[3].segments[0].end(), Eigen::RowVector2d(6, 3));
  EXPECT_EQ(svg.contours[3].segments[1].end(), Eigen::RowVector2d(6, 8));
  // A percentage rx serves as ry too, as a length (10 % of the width 200, not of the height).
  const SA::Svg_paths percent = elements_test_read("<rect width='100' height='50' rx='10%'/>", " width='200' height='100'");
  EXPECT_EQ(percent.contours[0].segments[1].arc.axis_v, Eigen::RowVector2d(0, 20));
}

// Made to fail once: with the polygon's closing segment left out (its contour still closed),
// the polygon had 3 segments, not 4, and its last one ended at (-3.5, 0.5).
TEST(SvgShapes, PolygonPolylineAndLineVerticesExact)
{
  const SA::Svg_paths svg = elements_test_read(
    "<polygon points='0,0 10-5 1e1,2.5e1 -3.5.5'/>\n<polyline points=' 0,0 10-5 1e1,2.5e1 -3.5.5 '/>\n"
    "<polyline points='1 1 1 1 2 2'/><line x1='1' y1='2' x2='3' y2='4'/><polygon points='5 5 6 6 5 5'/>"
    "<line x1='1' x2='1'/><polyline points=''/><polygon points='7,7'/>");
  EXPECT_EQ(svg.shape_elements, 8u);
  ASSERT_EQ(svg.contours.size(), 5u);
  const std::vector<Eigen::RowVector2d> v = {{0, 0}, {10, -5}, {10, 25}, {-3.5, 0.5}};
  const SA::Bezier_contour& polygon = svg.contours[0];
  EXPECT_TRUE(polygon.closed);
  ASSERT_EQ(polygon.segments.size(), 4u);
  for(std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(polygon.segments[i].degree, 1);
    EXPECT_EQ(polygon.segments[i].start(), v[i]);
    EXPECT_EQ(polygon.segments[i].end(), v[(i + 1) % 4]);
  }
  const SA::Bezier_contour& polyline = svg.contours[1];
  EXPECT_FALSE(polyline.closed);
  ASSERT_EQ(polyline.segments.size(), 3u);
  for(std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(polyline.segments[i].start(), v[i]);
    EXPECT_EQ(polyline.segments[i].end(), v[i + 1]);
  }
  ASSERT_EQ(svg.contours[2].segments.size(), 1u); // the repeated point gives no segment
  EXPECT_EQ(svg.contours[2].segments[0].end(), Eigen::RowVector2d(2, 2));
  EXPECT_FALSE(svg.contours[3].closed);
  EXPECT_EQ(svg.contours[3].segments[0].start(), Eigen::RowVector2d(1, 2));
  EXPECT_EQ(svg.contours[3].segments[0].end(), Eigen::RowVector2d(3, 4));
  EXPECT_EQ(svg.contours[4].segments.size(), 2u); // back at its start: no closing segment added
}

// Made to fail once: with the alignment's offset left out of view_box_transform (every box at
// the viewport's top left), the meet case gave (20, 20), not (70, 20): 9 expectations failed.
TEST(SvgViewport, ViewBoxMappedByEveryAlignment)
{
  // viewBox 50 x 50 into 200 x 100: meet scales by min(4, 2) = 2, leaving 100 across: xMid 50.
  auto map = [](const std::string& attributes) {
    const SA::Svg_paths svg = elements_test_read("<path d='M 10 10 L 50 50'/>", attributes);
    return svg.contours.at(0).segments.at(0);
  };
  const std::string box = " width='200' height='100' viewBox='0 0 50 50'";
  SA::Bezier_segment s = map(box);
  elements_test_expect_point(s.start(), 70, 20);
  elements_test_expect_point(s.end(), 150, 100);
  elements_test_expect_point(map(box + " preserveAspectRatio='xMinYMin'").start(), 20, 20);
  elements_test_expect_point(map(box + " preserveAspectRatio='xMaxYMax meet'").start(), 120, 20);
  // slice scales by max(4, 2) = 4: 200 down, yMid -50.
  elements_test_expect_point(map(box + " preserveAspectRatio='xMidYMid slice'").start(), 40, -10);
  elements_test_expect_point(map(box + " preserveAspectRatio='  xMinYMax   slice '").start(), 40, -60);
  elements_test_expect_point(map(box + " preserveAspectRatio='none'").start(), 40, 20); // 4 and 2
  elements_test_expect_point(map(box + " preserveAspectRatio='defer none slice'").start(), 40, 20);
  // The box's origin: (0, 0) is 10 and 20 from it.
  elements_test_expect_point(map(" width='200' height='100' viewBox='-10 -20 50 50'").start(), 90, 60);
  // Only the viewBox: its own size, unscaled; only a width: the height through its aspect ratio.
  elements_test_expect_point(map(" viewBox='5 5 100 100'").start(), 5, 5);
  elements_test_expect_point(map(" width='100' viewBox='0 0 50 25'").start(), 20, 20);
  elements_test_expect_point(map(" height='100%' width='auto' viewBox='0 0 50 25'").start(), 10, 10);
  const SA::Svg_paths svg = elements_test_read("<path d='M 10 10 L 50 50'/>", box);
  EXPECT_EQ(svg.viewport_width, 200);
  EXPECT_EQ(svg.viewport_height, 100);
  elements_test_expect_point((svg.user_to_viewport.inverse() * Eigen::Vector2d(70, 20)).transpose(), 10, 10, 1e-13);
  // Nested: x, y and width, height place its viewBox (10 x 5 at scale 5 in 50 x 40: yMax 15 down).
  const SA::Svg_paths nested = elements_test_read(
    "<svg x='10' y='20' width='50' height='40' viewBox='0 0 10 5' preserveAspectRatio='xMinYMax'>"
    "<path d='M 0 0 L 10 5'/></svg><svg x='1' y='2'><path d='M 0 0 L 1 0'/></svg>",
    " width='100' height='100'");
  elements_test_expect_point(nested.contours[0].segments[0].start(), 10, 35);
  elements_test_expect_point(nested.contours[0].segments[0].end(), 60, 60);
  elements_test_expect_point(nested.contours[1].segments[0].start(), 1, 2); // no viewBox: moved only
}

// Absolute units at 96 px per inch, on the viewport and in the drawing; percentages of the
// viewport (under a viewBox: of the viewBox).  Made to fail once: with mm taken as 96 / 2.54
// (a cm), the viewport was 3779.5 wide, not 377.95, and the 25.4mm rectangle 960 px high.
TEST(SvgViewport, UnitsAndPercentages)
{
  const double mm = 96 / 25.4;
  SA::Svg_paths svg = elements_test_read("<path d='M 10 10 L 50 50'/>", " width='2in' height='96px' viewBox='0 0 50 50'");
  elements_test_expect_point(svg.contours[0].segments[0].start(), 48 + 19.2, 19.2, 1e-12); // scale 1.92, xMid 48
  svg = elements_test_read("<rect width='1in' height='25.4mm'/><rect width='2.54cm' height='72pt'/>"
                           "<rect width='6pc' height='101.6Q'/><rect width='96PX' height='1e2'/>",
                           " width='100mm' height='50mm'");
  EXPECT_NEAR(svg.viewport_width, 100 * mm, 1e-12);
  EXPECT_NEAR(svg.viewport_height, 50 * mm, 1e-12);
  ASSERT_EQ(svg.contours.size(), 4u);
  for(std::size_t i = 0; i < 4; ++i) { // the top right corner: 96 x 96 (the last 96 x 100: user units, unscaled)
    elements_test_expect_point(svg.contours[i].segments[0].end(), 96, 0, 1e-12);
    elements_test_expect_point(svg.contours[i].segments[1].end(), 96, i < 3 ? 96 : 100, 1e-12);
  }
  svg = elements_test_read("<rect x='10%' y='10%' width='50%' height='50%'/><circle r='10%'/>", " width='200' height='100'");
  elements_test_expect_point(svg.contours[0].segments[0].start(), 20, 10);
  elements_test_expect_point(svg.contours[0].segments[1].end(), 120, 60);
  // r: a percentage of the viewport's diagonal over sqrt 2.
  elements_test_expect_point(svg.contours[1].segments[0].start(), 0.1 * std::sqrt((200.0 * 200 + 100 * 100) / 2), 0, 1e-12);
  svg = elements_test_read("<rect width='50%' height='50%'/>", " width='400' height='200' viewBox='0 0 200 100'");
  elements_test_expect_point(svg.contours[0].segments[1].end(), 200, 100); // 100 x 50 user units, scaled by 2
}

// Made to fail once: with the percentage check skipped (a NaN size used: the rectangle then
// draws nothing), the first case threw nothing.
TEST(SvgViewport, BadLengthsAndViewportsRefusedWithLineAndColumn)
{
  auto read = [](const std::string& body, const std::string& attributes = "") { elements_test_read(body, attributes); };
  EXPECT_THROW_REASON(read("<rect width='50%' height='2'/>"), SA::Invalid_input,
                      "'e.svg' line 2, column 14: a percentage of the viewport, whose size the document does not give");
  EXPECT_THROW_REASON(read("<rect width='1em' height='2'/>"), SA::Invalid_input,
                      "line 2, column 15: the unit 'em' of 'width' of <rect> depends on a font or a window");
  EXPECT_THROW_REASON(read("<circle r='3 furlongs'/>"), SA::Invalid_input,
                      "line 2, column 13: unexpected ' ' after the length of 'r' of <circle>");
  EXPECT_THROW_REASON(read("<circle r='3furlongs'/>"), SA::Invalid_input,
                      "line 2, column 13: unknown unit 'furlongs' in 'r' of <circle>");
  EXPECT_THROW_REASON(read("<line x1='px'/>"), SA::Invalid_input, "line 2, column 11: expected a length for 'x1' of <line>");
  EXPECT_THROW_REASON(read("", " viewBox='0 0 10'"), SA::Invalid_input,
                      "line 1, column 15: 'viewBox' takes 4 numbers (min-x, min-y, width, height), not 3");
  EXPECT_THROW_REASON(read("", " viewBox='0 0 -10 10'"), SA::Invalid_input, "column 15: the viewBox's width is negative");
  EXPECT_THROW_REASON(read("", " width='-1'"), SA::Invalid_input, "line 1, column 13: 'width' of <svg> is negative");
  EXPECT_THROW_REASON(read("", " viewBox='0 0 1 1' preserveAspectRatio='xMidYmid'"), SA::Invalid_input,
                      "line 1, column 45: unknown alignment 'xMidYmid' in 'preserveAspectRatio'");
  EXPECT_THROW_REASON(read("", " preserveAspectRatio='none meetme'"), SA::Invalid_input,
                      "line 1, column 32: expected meet or slice after the alignment, found 'meetme'");
  // A viewBox of zero size disables the document: nothing is drawn.
  EXPECT_THROW_REASON(read("<path d='M 0 0 L 1 1'/>", " viewBox='0 0 0 10'"), SA::Invalid_input, "is drawn");
}

// <use>: the referenced element as its child, moved by x and y after the <use>'s own transform.
// (1, 0) -> rotate(90) (0, 1) -> x, y (5, 2) -> scale(2) (10, 4) -> the group (20, 4); (0, 2) ->
// (-2, 0) -> (3, 1) -> (6, 2) -> (16, 2).  With x and y applied before the <use>'s transform
// (15, 3) and (11, 1); without the path's own transform (22, 2) and (20, 6).
// Made to fail once: with the translation by x and y composed on the outside of the <use>'s
// transform, the first path came out at (15, 3) and (11, 1).
TEST(SvgUse, XYAfterItsTransformAndTheTargetsOwnFirst)
{
  const SA::Svg_paths svg = elements_test_read(
    "<defs><path id='p' d='M 1 0 L 0 2' transform='rotate(90)'/></defs>\n"
    "<g transform='translate(10 0)'><use href='#p' x='5' y='1' transform='scale(2)'/></g>\n"
    "<g id='g'><line x2='1'/></g><use xlink:href='#g' y='3'/><use id='u1' href='#g' x='1'/><use href='#u1' x='10'/>\n"
    "<symbol id='s' viewBox='0 0 10 10'><circle cx='5' cy='5' r='5'/></symbol>\n"
    "<use href='#s' x='100' width='20' height='40'/><use href='#s' transform='translate(0 50)'/>",
    " width='200' height='100'");
  EXPECT_EQ(svg.path_elements, 1u); // the path in <defs> drawn once, by the <use>
  ASSERT_EQ(svg.contours.size(), 7u);
  elements_test_expect_point(svg.contours[0].segments[0].start(), 20, 4, 1e-15);
  elements_test_expect_point(svg.contours[0].segments[0].end(), 16, 2, 1e-15);
  // The group as written, then drawn at y 3, at x 1, and at x 11 through a <use> of a <use>.
  const double lines[4][2] = {{0, 0}, {0, 3}, {1, 0}, {11, 0}};
  for(int i = 0; i < 4; ++i) {
    elements_test_expect_point(svg.contours[std::size_t(1 + i)].segments[0].start(), lines[i][0], lines[i][1]);
    elements_test_expect_point(svg.contours[std::size_t(1 + i)].segments[0].end(), lines[i][0] + 1, lines[i][1]);
  }
  // The symbol's viewBox 10 x 10 in the <use>'s 20 x 40 at (100, 0): scale 2, yMid 10 down, so
  // its circle is centred at (110, 20) with radius 10.
  const SA::Bezier_contour& in_use = svg.contours[5];
  elements_test_expect_point(in_use.segments[0].start(), 120, 20);
  elements_test_expect_point(in_use.segments[1].start(), 110, 30);
  // Without width and height: 100 % of the viewport (200 x 100): scale 10, xMid 50 across.
  elements_test_expect_point(svg.contours[6].segments[0].start(), 50 + 100, 50 + 50);
}

// Made to fail once: with the elements that hold no drawing read as groups, the first document
// was not refused and the second drew 7 contours instead of 1.
TEST(SvgUse, DefsSymbolsAndOtherHoldersNotDrawnByThemselves)
{
  const std::string held = "<defs><path d='M0 0 L1 1'/><rect width='1' height='1'/></defs>\n"
                           "<symbol><circle r='1'/></symbol><clipPath><path d='M0 0 L2 2'/></clipPath>\n"
                           "<mask><rect width='1' height='1'/></mask><marker><path d='M0 0 L3 3'/></marker>\n"
                           "<pattern><g><path d='M0 0 L4 4'/></g></pattern><g><symbol><line x2='1'/></symbol></g>";
  EXPECT_THROW_REASON(elements_test_read(held), SA::Invalid_input,
                      "'e.svg': no <path> with a 'd' attribute and no basic shape (<rect>, <circle>, <ellipse>, "
                      "<line>, <polyline>, <polygon>) is drawn");
  const SA::Svg_paths svg = elements_test_read(held + "<g><path d='M 0 0 L 5 0'/></g>");
  ASSERT_EQ(svg.contours.size(), 1u);
  EXPECT_EQ(svg.contours[0].segments[0].end(), Eigen::RowVector2d(5, 0));
  EXPECT_EQ(svg.path_elements, 1u);
  EXPECT_EQ(svg.shape_elements, 0u);
}

// Made to fail once: without the cycle check (refuse_cycles returning at once), the first three
// were refused for their depth ("nested more than 256 deep") instead, and the cycle in <defs>
// that nothing draws was not refused at all; with a <use>'s target left out of measure(), the
// 10^8 lines were drawn until AddressSanitizer's memory limit (hard_rss_limit_mb=600) ended the run.
TEST(SvgUse, CyclesBadReferencesAndExpansionRefused)
{
  auto read = [](const std::string& body) { elements_test_read(body); };
  EXPECT_THROW_REASON(read("<g id='a'>\n  <use href='#a'/></g>"), SA::Invalid_input,
                      "'e.svg' line 3, column 14: the <use> refers to '#a', which contains it: a cycle");
  EXPECT_THROW_REASON(read("<use id='u' xlink:href='#u'/>"), SA::Invalid_input,
                      "line 2, column 25: the <use> refers to '#u', which contains it: a cycle");
  EXPECT_THROW_REASON(read("<use href='#a'/><g id='a'><use href='#b'/></g>\n<g id='b'><g><use href='#a'/></g></g>"),
                      SA::Invalid_input,
                      "line 3, column 25: the <use> refers to '#a', which draws this <use> again through other references: a cycle");
  EXPECT_THROW_REASON(read("<defs><g id='a'><use href='#b'/></g><use id='b' href='#a'/></defs><path d='M 0 0 L 1 1'/>"),
                      SA::Invalid_input, "a cycle");
  EXPECT_THROW_REASON(read("<use href='#nowhere'/>"), SA::Invalid_input,
                      "line 2, column 12: the <use> refers to '#nowhere', and no element has that id");
  EXPECT_THROW_REASON(read("<use href='other.svg#a'/>"), SA::Invalid_input,
                      "line 2, column 12: the <use> refers to 'other.svg#a': only elements of the same file ('#id') are read");
  EXPECT_THROW_REASON(read("<use href='#'/>"), SA::Invalid_input, "refers to '#': only elements of the same file");
  // Ten references per level, 8 levels: 10^8 lines from one path, refused before drawing any.
  std::string laughs = "<defs><line id='l0' x2='1'/>";
  for(int level = 1; level <= 8; ++level) {
    laughs += "<g id='l" + std::to_string(level) + "'>";
    for(int k = 0; k < 10; ++k) laughs += "<use href='#l" + std::to_string(level - 1) + "'/>";
    laughs += "</g>";
  }
  EXPECT_THROW_REASON(read(laughs + "</defs><use href='#l8'/>"), SA::Invalid_input,
                      "the <use> elements draw more than 1000000 elements and segments in all");
  EXPECT_EQ(elements_test_read(laughs + "</defs><use href='#l4'/>").contours.size(), 10000u); // 10^4: drawn
}

// display none (attribute or style, the style winning) hides an element and what is inside it;
// visibility is inherited and a child may show itself again.  Made to fail once: with the style
// attribute not read, 8 contours were drawn, not 4 (those ending at 3, 8 twice and 9, and the
// collapsed rectangle), and the one ending at 4 was not.
TEST(SvgCss, DisplayNoneAndVisibility)
{
  const SA::Svg_paths svg = elements_test_read(
    "<path d='M0 0 L1 0'/><g display='none'><path d='M0 0 L2 0'/></g>\n"
    "<path style='fill:red; display : None !important' d='M0 0 L3 0'/>\n"
    "<path display='none' style='display:inline' d='M0 0 L4 0'/>\n"
    "<g visibility='hidden'><path d='M0 0 L5 0'/><path visibility='visible' d='M0 0 L6 0'/></g>\n"
    "<g style='visibility:collapse'><rect width='1' height='1'/></g>\n"
    "<path style=\"/* display:none */ stroke:url('#a;display:none')\" d='M0 0 L7 0'/>\n"
    "<g id='gone' style='display:none'><path d='M0 0 L8 0'/></g><use href='#gone'/>\n"
    "<g style='visibility:hidden'><use href='#shown'/></g><defs><path id='shown' d='M0 0 L9 0'/></defs>");
  std::vector<double> ends;
  for(const SA::Bezier_contour& c : svg.contours) ends.push_back(c.segments.back().end()[0]);
  EXPECT_EQ(ends, (std::vector<double>{1, 4, 6, 7}));
  EXPECT_EQ(svg.path_elements, 4u); // hidden paths are not drawn, so not counted
}

// Made to fail once: with the odd count of points accepted, the first case threw nothing; with
// only the arc's centre and axes checked (not their sum), the arc under the viewBox threw nothing.
TEST(SvgShapes, BadShapesRefusedWithLineAndColumn)
{
  auto read = [](const std::string& body) { elements_test_read(body); };
  EXPECT_THROW_REASON(read("<polygon points='1 2 3'/>"), SA::Invalid_input,
                      "'e.svg' line 2, column 23: 'points' of <polygon> has an odd count of numbers (3): the last point has no y");
  EXPECT_THROW_REASON(read("<polyline points='1,2,'/>"), SA::Invalid_input,
                      "line 2, column 23: expected a number in 'points' of <polyline> after ',', found the end of the points");
  EXPECT_THROW_REASON(read("<polyline points='1,2 x'/>"), SA::Invalid_input,
                      "line 2, column 23: expected a number in 'points' of <polyline>, found 'x'");
  EXPECT_THROW_REASON(read("<circle r='-1'/>"), SA::Invalid_input, "line 2, column 12: 'r' of <circle> is negative");
  EXPECT_THROW_REASON(read("<rect width='10' height='-0.5'/>"), SA::Invalid_input,
                      "line 2, column 26: 'height' of <rect> is negative");
  EXPECT_THROW_REASON(read("<ellipse rx='1' ry='-2%'/>"), SA::Invalid_input, "column 21: 'ry' of <ellipse> is negative");
  EXPECT_THROW_REASON(read("<rect width='1' height='1' width='2'/>"), SA::Invalid_input,
                      "line 2, column 28: attribute 'width' is given twice in <rect>");
  EXPECT_THROW_REASON(read("<circle r='auto'/>"), SA::Invalid_input, "expected a length for 'r' of <circle>, found 'a'");
  // Coordinates beyond double range: a circle's end point, an arc whose samples would overflow
  // once the viewBox doubles it (its centre and axes still finite).
  EXPECT_THROW_REASON(read("<circle cx='1e308' r='1e308'/>"), SA::Invalid_input,
                      "line 2, column 1: the <circle>'s coordinates in the viewport are beyond double range");
  EXPECT_THROW_REASON(elements_test_read("<path d='M 0 0 A 1e308 30 30 1 1 40 10'/>", " viewBox='0 0 100 100' width='200'"),
                      SA::Invalid_input, "line 2, column 10: the path's transformed coordinates are beyond double range");
  // Also in an element that is not drawn.
  EXPECT_THROW_REASON(read("<defs><line x1='1e'/></defs><path d='M 0 0 L 1 1'/>"), SA::Invalid_input,
                      "line 2, column 18: unknown unit 'e' in 'x1' of <line>");
}
