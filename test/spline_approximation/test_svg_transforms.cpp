// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// SVG transform attributes against points computed by hand: each function, lists of them,
// nested groups (in an order where the wrong composition gives other points), the rotation
// about a centre, arcs under non-uniform scales and skews still on their mapped ellipse, and
// malformed transforms refused with line, column and reason.

#include <CGAL/Spline_approximation/Svg_paths.h>

#include "expect_reason.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace SA = CGAL::Spline_approximation;

namespace {

// The line from (1, 0) to (0, 2) under `transform`, on a <path> inside an <svg>.
SA::Bezier_segment transform_test_line(const std::string& transform)
{
  const SA::Svg_paths svg =
    SA::parse_svg_paths("<svg><path transform=\"" + transform + "\" d=\"M 1 0 L 0 2\"/></svg>", "transform test");
  EXPECT_EQ(svg.contours.size(), 1u);
  return svg.contours.at(0).segments.at(0);
}

void transform_test_expect(const SA::Bezier_segment& s, double x0, double y0, double x1, double y1, double tolerance = 0)
{
  EXPECT_NEAR(s.start()[0], x0, tolerance);
  EXPECT_NEAR(s.start()[1], y0, tolerance);
  EXPECT_NEAR(s.end()[0], x1, tolerance);
  EXPECT_NEAR(s.end()[1], y1, tolerance);
}

} // namespace

// (1, 0) and (0, 2) by hand: translate adds, scale multiplies, rotate(90) is (x, y) -> (-y, x),
// skewX(a) adds tan(a) y to x, skewY(a) tan(a) x to y, matrix(a b c d e f) is (ax + cy + e, bx + dy + f).
// Made to fail once: with skewX's and skewY's matrices swapped, skewX(45) gave (1, 1) and (0, 2)
// (6 failed expectations).
TEST(SvgTransforms, EachFunction)
{
  transform_test_expect(transform_test_line("translate(5 -1)"), 6, -1, 5, 1);
  transform_test_expect(transform_test_line("translate(5)"), 6, 0, 5, 2); // ty = 0
  transform_test_expect(transform_test_line("scale(2 3)"), 2, 0, 0, 6);
  transform_test_expect(transform_test_line("scale(2)"), 2, 0, 0, 4); // sy = sx
  transform_test_expect(transform_test_line("rotate(90)"), 0, 1, -2, 0);
  transform_test_expect(transform_test_line("rotate(-90)"), 0, -1, 2, 0);
  transform_test_expect(transform_test_line("rotate(30)"), std::sqrt(3.0) / 2, 0.5, -1, std::sqrt(3.0), 1e-15);
  transform_test_expect(transform_test_line("skewX(45)"), 1, 0, 2, 2, 1e-15);
  transform_test_expect(transform_test_line("skewY(45)"), 1, 1, 0, 2, 1e-15);
  transform_test_expect(transform_test_line("skewX(-30)"), 1, 0, -2 / std::sqrt(3.0), 2, 1e-15);
  transform_test_expect(transform_test_line("matrix(1 2 3 4 5 6)"), 6, 8, 11, 14);
  transform_test_expect(transform_test_line(""), 1, 0, 0, 2); // empty: the identity
}

// rotate(90 1 1) about (1, 1): (1, 0) is (0, -1) from the centre, turned (1, 0): (2, 1);
// (0, 2) is (-1, 1), turned (-1, -1): (0, 0).
// Made to fail once: with the centre's translations swapped (translate(-c) rotate translate(c)),
// (1, 0) went to (-2, 1) and (0, 2) to (-4, 0); the list form below failed too when lists were
// composed the wrong way round (next test).
TEST(SvgTransforms, RotationAboutACentre)
{
  transform_test_expect(transform_test_line("rotate(90 1 1)"), 2, 1, 0, 0);
  transform_test_expect(transform_test_line("rotate(90,1,1)"), 2, 1, 0, 0);
  transform_test_expect(transform_test_line("translate(1 1) rotate(90) translate(-1 -1)"), 2, 1, 0, 0);
}

// "translate(10 0) scale(2)": scale first, so (1, 0) -> (12, 0) and (0, 2) -> (10, 4); the other
// order would give (22, 0) and (20, 4).
// Made to fail once: with each function composed on the left (result = t * result), every list
// below gave (22, 0).
TEST(SvgTransforms, ListsRightmostFirstAnySeparators)
{
  for(const char* t : {"translate(10 0) scale(2)", "translate(10,0),scale(2)", "translate(10,0)scale(2)",
                       "  translate( 10 , 0 ) ,\n scale ( 2 )  ", "translate(10) scale(2) rotate(0)"}) {
    SCOPED_TRACE(t);
    transform_test_expect(transform_test_line(t), 12, 0, 10, 4);
  }
}

// Group translate(10 0), inside it a group scale(2), inside it a path rotate(90): the path's own
// transform first, then the inner group's, then the outer's.  (1, 0) -> (0, 1) -> (0, 2) ->
// (10, 2); (0, 2) -> (-2, 0) -> (-4, 0) -> (6, 0).  The reverse order gives (0, 22) and (-4, 20).
// Made to fail once: with a child's transform composed on the left of its parent's
// (own * parent), the first path came out at (0, 22) and (-4, 20); with closed elements not
// popped, the paths after them kept their transforms ((12, 0) for (11, 0) and for (1, 0)).
TEST(SvgTransforms, NestedGroupsComposeInnermostFirst)
{
  const std::string text = "<svg>\n<g transform='translate(10 0)'>\n <g id='x' transform=\"scale(2)\">\n"
                           "  <path d='M 1 0 L 0 2' transform='rotate(90)'/>\n </g>\n"
                           " <path d='M 1 0 L 0 2'/>\n</g>\n<g><path d='M 1 0 L 0 2'/></g>\n"
                           "<g transform='scale(5)'/><path d='M 1 0 L 0 2'/></svg>";
  const SA::Svg_paths svg = SA::parse_svg_paths(text);
  ASSERT_EQ(svg.contours.size(), 4u);
  transform_test_expect(svg.contours[0].segments[0], 10, 2, 6, 0);
  transform_test_expect(svg.contours[1].segments[0], 11, 0, 10, 2); // after </g>: the outer group only
  transform_test_expect(svg.contours[2].segments[0], 1, 0, 0, 2);   // no transform left
  transform_test_expect(svg.contours[3].segments[0], 1, 0, 0, 2);   // a self-closed group holds nothing
}

// The unit half circle from (1, 0) through (0, 1) to (-1, 0) under maps that turn it into ellipse
// arcs: scale(3 1) onto (x/3)^2 + y^2 = 1 through (0, 1); skewX(30) onto (x - y tan 30)^2 + y^2 = 1
// through (tan 30, 1); matrix(2 1 1 3 4 5) onto |M^-1 (p - (4, 5))| = 1 through (5, 8).
// Made to fail once: with the arc's centre mapped but not its axes, the residuals were 0.89
// (scale), 0.77 (skew) and 0.92 (matrix), the skew's and the matrix's middle points 0.58 and 2.2 off.
TEST(SvgTransforms, ArcsUnderNonUniformMapsStayExact)
{
  const double t30 = 1 / std::sqrt(3.0);
  Eigen::Matrix2d M;
  M << 2, 1, 1, 3;
  const Eigen::Matrix2d Minv = M.inverse();
  struct Case
  {
    const char* transform;
    Eigen::RowVector2d middle;
    std::function<double(const Eigen::RowVector2d&)> implicit;
  };
  const std::vector<Case> cases = {
    {"scale(3 1)", {0, 1}, [](const Eigen::RowVector2d& p) { return p[0] * p[0] / 9 + p[1] * p[1] - 1; }},
    {"skewX(30)", {t30, 1},
     [&](const Eigen::RowVector2d& p) { return (p[0] - p[1] * t30) * (p[0] - p[1] * t30) + p[1] * p[1] - 1; }},
    {"matrix(2 1 1 3 4 5)", {5, 8},
     [&](const Eigen::RowVector2d& p) { return (Minv * (p - Eigen::RowVector2d(4, 5)).transpose()).squaredNorm() - 1; }}};
  for(const Case& k : cases) {
    SCOPED_TRACE(k.transform);
    const SA::Svg_paths svg = SA::parse_svg_paths(std::string("<svg><g transform='") + k.transform +
                                                  "'><path d='M 1 0 A 1 1 0 0 1 -1 0'/></g></svg>");
    const SA::Bezier_segment& s = svg.contours[0].segments[0];
    ASSERT_TRUE(s.is_arc);
    EXPECT_LT((s(0.5) - k.middle).norm(), 1e-14);
    const SA::Sampled_contour samples = SA::sample_contour(svg.contours[0], 100);
    double worst = 0;
    for(Eigen::Index i = 0; i < samples.points.rows(); ++i)
      worst = std::max(worst, std::abs(k.implicit(samples.points.row(i))));
    EXPECT_LT(worst, 1e-12);
  }
}

// Made to fail once: with the transform's positions counted in the attribute value (not in the
// file), every case failed ("line 1, column 10: unknown transform function 'foo'" for the first).
TEST(SvgTransforms, MalformedTransformsRefusedWithLineAndColumn)
{
  auto parse = [](const std::string& transform) {
    return SA::parse_svg_paths("<svg>\n<g transform=\"" + transform + "\"><path d='M 0 0 L 1 1'/></g></svg>", "'t.svg'");
  };
  // The value starts at line 2, column 15.
  EXPECT_THROW_REASON(parse("scale(2) foo(1)"), SA::Invalid_input,
                      "'t.svg' line 2, column 24: unknown transform function 'foo'");
  EXPECT_THROW_REASON(parse("rotate(1 2)"), SA::Invalid_input, "line 2, column 15: 'rotate' takes 1 or 3 numbers, not 2");
  EXPECT_THROW_REASON(parse("matrix(1,2,3,4,5)"), SA::Invalid_input, "column 15: 'matrix' takes 6 numbers, not 5");
  EXPECT_THROW_REASON(parse("scale()"), SA::Invalid_input, "column 15: 'scale' takes 1 or 2 numbers, not 0");
  EXPECT_THROW_REASON(parse("translate(1 2"), SA::Invalid_input,
                      "column 28: expected ')' to close 'translate(', found the end of the transform");
  EXPECT_THROW_REASON(parse("scale 2"), SA::Invalid_input, "column 21: expected '(' after 'scale', found '2'");
  EXPECT_THROW_REASON(parse("translate(1,,2)"), SA::Invalid_input,
                      "column 27: expected a number or ')' in 'translate(...)', found ','");
  EXPECT_THROW_REASON(parse("scale(2),"), SA::Invalid_input,
                      "column 24: expected a transform function after ',', found the end of the transform");
  EXPECT_THROW_REASON(parse("skewX(90)"), SA::Invalid_input, "column 15: 'skewX' of an odd multiple of 90 degrees");
  EXPECT_THROW_REASON(parse("rotate(1e999)"), SA::Invalid_input, "column 22: the number '1e999' is out of range");
  EXPECT_THROW_REASON(parse("(2)"), SA::Invalid_input, "column 15: expected a transform function (matrix, translate");
  // Finite transforms whose product, or whose image of the path, is not.
  const std::string product = "<svg><g transform='scale(1e200)'><path transform='scale(1e200)' d='M 0 0 L 1 1'/></g>";
  EXPECT_THROW_REASON(SA::parse_svg_paths(product, "f"), SA::Invalid_input,
                      "column 51: the transform, composed with those of the elements around it, is beyond double range");
  const std::string image = "<svg><g transform='scale(1e300)'><path d='M 0 0 L 1e10 1'/></g></svg>";
  EXPECT_THROW_REASON(SA::parse_svg_paths(image, "f"), SA::Invalid_input,
                      "column 43: the path's transformed coordinates are beyond double range");
  // On the path itself, after its d: still refused, at its place.
  EXPECT_THROW_REASON(SA::parse_svg_paths("<svg><path d='M 0 0 L 1 1'\n transform='scale(1 2 3)'/></svg>", "f"),
                      SA::Invalid_input, "f line 2, column 13: 'scale' takes 1 or 2 numbers, not 3");
}
