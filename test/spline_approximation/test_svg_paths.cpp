// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// SVG path data against hand-computed control points for every command (absolute and
// relative, implicit repeats, the reflections of S and T, subpaths and Z), the sampling of
// contours, a C^2 cubic path recovered with exactly its joints by a degree-3 fit, and bad
// input refused with its line, column and reason.

#include <CGAL/Spline_approximation/Spline_fit.h>
#include <CGAL/Spline_approximation/Svg_paths.h>

#include "expect_reason.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

namespace SA = CGAL::Spline_approximation;

namespace {

// The control points of a segment, row by row, e.g. {{0, 0}, {1, 2}}.
void expect_segment(const SA::Bezier_segment& s, const std::vector<std::vector<double>>& points)
{
  ASSERT_EQ(s.degree + 1, int(points.size()));
  for(int i = 0; i <= s.degree; ++i) {
    EXPECT_DOUBLE_EQ(s.control_points(i, 0), points[std::size_t(i)][0]) << "control point " << i;
    EXPECT_DOUBLE_EQ(s.control_points(i, 1), points[std::size_t(i)][1]) << "control point " << i;
  }
}

} // namespace

// Made to fail once: with H taking its number as y, the H segment ended at (30, 50) (absolute)
// and (30, 60) (relative) instead of (50, 40); with Z not marking the subpath closed, the
// contour came out open.
TEST(SvgPaths, LinesAbsoluteAndRelativeAndClose)
{
  for(const char* d : {"M 10 20 L 30 40 H 50 V 60 Z", "m10,20 l20,20 h20 v20 z", "M10 20L30 40H50V60L10 20Z"}) {
    SCOPED_TRACE(d);
    const std::vector<SA::Bezier_contour> c = SA::parse_svg_path_data(d);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_TRUE(c[0].closed);
    ASSERT_EQ(c[0].segments.size(), 4u); // Z adds no segment where the path is back at its start already
    expect_segment(c[0].segments[0], {{10, 20}, {30, 40}});
    expect_segment(c[0].segments[1], {{30, 40}, {50, 40}});
    expect_segment(c[0].segments[2], {{50, 40}, {50, 60}});
    expect_segment(c[0].segments[3], {{50, 60}, {10, 20}});
  }
}

// Made to fail once: with the moveto's implicit repeats kept movetos (not linetos), "M0 0 1 1 2 0"
// gave no contour at all.
TEST(SvgPaths, ImplicitRepeatsAndNumberGrammar)
{
  std::vector<SA::Bezier_contour> c = SA::parse_svg_path_data("M0 0 1 1 2 0");
  ASSERT_EQ(c.size(), 1u);
  ASSERT_EQ(c[0].segments.size(), 2u);
  EXPECT_FALSE(c[0].closed);
  expect_segment(c[0].segments[1], {{1, 1}, {2, 0}});
  c = SA::parse_svg_path_data("m0 0 1 1 2 0"); // relative repeats: each from the current point
  expect_segment(c[0].segments[1], {{1, 1}, {3, 1}});
  c = SA::parse_svg_path_data("M.5.5-1-2"); // ".5.5" is two numbers, "-1-2" too
  expect_segment(c[0].segments[0], {{0.5, 0.5}, {-1, -2}});
  c = SA::parse_svg_path_data("M1e-3,2E+1\n l+1.5e1 .25 L 0.0 -.0");
  expect_segment(c[0].segments[0], {{0.001, 20}, {15.001, 20.25}});
  expect_segment(c[0].segments[1], {{15.001, 20.25}, {0, 0}});
  c = SA::parse_svg_path_data("M 0 0 C 1 2 3 4 5 6 7 8 9 10 11 12"); // C repeated implicitly
  ASSERT_EQ(c[0].segments.size(), 2u);
  expect_segment(c[0].segments[1], {{5, 6}, {7, 8}, {9, 10}, {11, 12}});
}

// Made to fail once: with S reflecting the wrong way (2 c - p instead of 2 p - c, c the previous
// control point, p the current point), the second segment's first control point was (1, 2), not (4, -1).
TEST(SvgPaths, CubicsAndSmoothReflections)
{
  std::vector<SA::Bezier_contour> c = SA::parse_svg_path_data("M1 1 c 1 2 3 4 5 6");
  expect_segment(c[0].segments[0], {{1, 1}, {2, 3}, {4, 5}, {6, 7}});
  // The point at u = 1/2 of a cubic: (P0 + 3 P1 + 3 P2 + P3) / 8.
  const Eigen::RowVector2d mid = c[0].segments[0](0.5);
  EXPECT_DOUBLE_EQ(mid[0], (1 + 3 * 2 + 3 * 4 + 6) / 8.0);
  EXPECT_DOUBLE_EQ(mid[1], (1 + 3 * 3 + 3 * 5 + 7) / 8.0);
  for(const char* d : {"M0 0 C 1 1 2 1 3 0 S 5 -1 6 0", "M0 0 c 1 1 2 1 3 0 s 2 -1 3 0"}) {
    SCOPED_TRACE(d);
    c = SA::parse_svg_path_data(d);
    ASSERT_EQ(c[0].segments.size(), 2u);
    expect_segment(c[0].segments[1], {{3, 0}, {4, -1}, {5, -1}, {6, 0}});
  }
  // S chained: reflects the previous S's second control point.
  c = SA::parse_svg_path_data("M0 0 C 1 1 2 1 3 0 S 5 -1 6 0 S 8 1 9 0");
  expect_segment(c[0].segments[2], {{6, 0}, {7, 1}, {8, 1}, {9, 0}});
  // S after a non-cubic: the first control point is the current point.
  c = SA::parse_svg_path_data("M0 0 L 1 0 S 2 1 3 0");
  expect_segment(c[0].segments[1], {{1, 0}, {1, 0}, {2, 1}, {3, 0}});
  c = SA::parse_svg_path_data("M0 0 Q 1 1 2 0 S 3 1 4 0"); // a quadratic is not a cubic to reflect
  expect_segment(c[0].segments[1], {{2, 0}, {2, 0}, {3, 1}, {4, 0}});
}

// Made to fail once: with T reflecting the last quadratic control point even after a line,
// "M0 0 L 2 0 T 4 0" took (4, 0) (the reflection of a stale point) as its control point.
TEST(SvgPaths, QuadraticsAndSmoothReflections)
{
  std::vector<SA::Bezier_contour> c = SA::parse_svg_path_data("M0 0 Q 1 1 2 0 T 4 0");
  ASSERT_EQ(c[0].segments.size(), 2u);
  expect_segment(c[0].segments[0], {{0, 0}, {1, 1}, {2, 0}});
  expect_segment(c[0].segments[1], {{2, 0}, {3, -1}, {4, 0}});
  c = SA::parse_svg_path_data("m0 0 q 1 1 2 0 t 2 0 t 2 0"); // chained relative T
  ASSERT_EQ(c[0].segments.size(), 3u);
  expect_segment(c[0].segments[2], {{4, 0}, {5, 1}, {6, 0}});
  c = SA::parse_svg_path_data("M0 0 L 2 0 T 4 0"); // T after a non-quadratic: control point = current point
  expect_segment(c[0].segments[1], {{2, 0}, {2, 0}, {4, 0}});
  const Eigen::RowVector2d q = SA::parse_svg_path_data("M0 0 Q 1 1 2 0")[0].segments[0](0.25);
  EXPECT_DOUBLE_EQ(q[0], 0.5);             // (1-u)^2 0 + 2u(1-u) 1 + u^2 2
  EXPECT_DOUBLE_EQ(q[1], 2 * 0.25 * 0.75); // 2u(1-u) 1
}

// Made to fail once: with Z not marking the subpath closed, the second contour came out open.
// (Z leaves the current point at the subpath's start through the closing line it adds.)
TEST(SvgPaths, SubpathsAndClosing)
{
  std::vector<SA::Bezier_contour> c = SA::parse_svg_path_data("M0 0 L1 0 M 5 5 L 6 5 L 6 6 z m 1 1 l 1 0 M 9 9");
  ASSERT_EQ(c.size(), 3u); // the lone final moveto draws nothing
  EXPECT_FALSE(c[0].closed);
  EXPECT_TRUE(c[1].closed);
  EXPECT_FALSE(c[2].closed);
  ASSERT_EQ(c[1].segments.size(), 3u); // the closing line added by z
  expect_segment(c[1].segments[2], {{6, 6}, {5, 5}});
  expect_segment(c[2].segments[0], {{6, 6}, {7, 6}});
  // A drawing command right after Z starts a new subpath at the closed one's start.
  c = SA::parse_svg_path_data("M0 0 L1 0 L1 1 Z L 2 2");
  ASSERT_EQ(c.size(), 2u);
  expect_segment(c[1].segments[0], {{0, 0}, {2, 2}});
}

// Made to fail once: with Z not closing, 17 samples instead of 16 (the first repeated at the end).
TEST(SvgPaths, SamplingKeepsJointsAndParameters)
{
  const std::vector<SA::Bezier_contour> c = SA::parse_svg_path_data("M0 0 H 4 V 4 H 0 Z");
  const SA::Sampled_contour s = SA::sample_contour(c[0], 4);
  EXPECT_TRUE(s.closed);
  ASSERT_EQ(s.points.rows(), 16); // the first point not repeated
  EXPECT_EQ(s.joints, (std::vector<Eigen::Index>{0, 4, 8, 12}));
  EXPECT_DOUBLE_EQ(s.points(5, 0), 4);
  EXPECT_DOUBLE_EQ(s.points(5, 1), 1);
  EXPECT_DOUBLE_EQ(s.parameters[5], 1.25 / 4);
  const SA::Sampled_contour open = SA::sample_contour(SA::parse_svg_path_data("M0 0 L 1 0 L 1 0 L 2 0")[0], 2);
  EXPECT_EQ(open.points.rows(), 5); // the zero-length segment dropped, the end point added
  EXPECT_DOUBLE_EQ(open.parameters[4], 1);
  EXPECT_THROW_REASON(SA::sample_contour(c[0], 0), SA::Invalid_input, "at least one sample per segment");
}

namespace {

// A C^2 cubic path in SVG syntax: the Bezier form of a uniform cubic B-spline on control points
// d (Boehm), so that a cubic spline with simple knots at the joints is exactly it.  Written with
// C for the first segment and S after it (the joints are C^1 with equal speeds, so the
// reflection holds).  closed: the periodic B-spline, and a Z.
std::string c2_cubic_path(const std::vector<Eigen::RowVector2d>& d, bool closed)
{
  const std::size_t n = d.size(), segments = closed ? n : n - 3;
  auto D = [&](std::size_t i) { return d[i % n]; };
  std::string out;
  char buffer[200];
  for(std::size_t i = 0; i < segments; ++i) {
    const Eigen::RowVector2d b0 = (D(i) + 4 * D(i + 1) + D(i + 2)) / 6, b2 = (D(i + 1) + 2 * D(i + 2)) / 3,
                             b3 = (D(i + 1) + 4 * D(i + 2) + D(i + 3)) / 6, b1 = (2 * D(i + 1) + D(i + 2)) / 3;
    if(i == 0) {
      std::snprintf(buffer, sizeof buffer, "M %.17g %.17g C %.17g %.17g %.17g %.17g %.17g %.17g\n", b0[0], b0[1], b1[0],
                    b1[1], b2[0], b2[1], b3[0], b3[1]);
    } else {
      std::snprintf(buffer, sizeof buffer, " S %.17g %.17g %.17g %.17g", b2[0], b2[1], b3[0], b3[1]);
    }
    out += buffer;
  }
  return out + (closed ? " Z" : "");
}

} // namespace

// Made to fail once: with S reflecting the wrong way, the path was no longer C^2 at its joints
// and the open fit kept 57 knots for 4 joints; with the sampled parameters divided by the segment
// count + 1 (not affine over the whole contour), it kept 5.
TEST(SvgPaths, CubicPathRecoveredWithItsJoints)
{
  const std::vector<Eigen::RowVector2d> d = {{0, 0}, {3, 5}, {7, 4}, {9, -2}, {14, 1}, {15, 8}, {10, 12}, {4, 9}};
  for(bool closed : {false, true}) {
    SCOPED_TRACE(closed ? "closed" : "open");
    const std::string text = "<svg><path d=\"" + c2_cubic_path(d, closed) + "\"/></svg>";
    const SA::Svg_paths svg = SA::parse_svg_paths(text);
    ASSERT_EQ(svg.contours.size(), 1u);
    const SA::Sampled_contour s = SA::sample_contour(svg.contours[0], 12);
    SA::Fit_options o;
    o.degree = 3;
    o.algorithm = SA::Fit_algorithm::greedy_removal;
    o.max_error = 1e-9;
    o.closed_curve = closed;
    const SA::Spline_fit fit = SA::fit_spline(s.points, s.parameters, o);
    EXPECT_TRUE(fit.within_bound);
    EXPECT_LT(fit.max_error, 1e-10);
    // The knots are the joints (open: the interior ones; closed: every one, the seam included).
    std::vector<double> expected, found;
    const std::size_t m = svg.contours[0].segments.size();
    for(std::size_t i = closed ? 0 : 1; i < m; ++i) expected.push_back(double(i) / double(m));
    const Eigen::VectorXd knots = fit.spline.interior_knots();
    for(Eigen::Index i = 0; i < knots.size(); ++i) found.push_back(knots[i]);
    ASSERT_EQ(found.size(), expected.size());
    for(std::size_t i = 0; i < found.size(); ++i) EXPECT_NEAR(found[i], expected[i], 1e-12);
  }
}

// Made to fail once: with the column counted from 0, every reason below said one column less;
// with the newlines not counted, "line 1, column 13" instead of "line 2, column 7".
TEST(SvgPaths, BadPathDataRefusedWithLineAndColumn)
{
  auto parse = [](const std::string& d) { return SA::parse_svg_path_data(d); };
  EXPECT_THROW_REASON(parse("M 0 0 L 1"), SA::Invalid_input,
                      "line 1, column 10: expected a number for 'L', found the end of the path data");
  EXPECT_THROW_REASON(parse("M 0 0\n  L 1 x"), SA::Invalid_input, "line 2, column 7: expected a number for 'L', found 'x'");
  EXPECT_THROW_REASON(parse("M 1e 2"), SA::Invalid_input, "column 5: the exponent of a number has no digits");
  EXPECT_THROW_REASON(parse("L 1 2"), SA::Invalid_input, "column 1: path data must start with a moveto");
  EXPECT_THROW_REASON(parse("M 0 0 X 1"), SA::Invalid_input, "column 7: unknown path command 'X'");
  EXPECT_THROW_REASON(parse("M 0 0 L 1 1 Z 2 2"), SA::Invalid_input, "column 15: expected a command after 'Z'");
  EXPECT_THROW_REASON(parse("M 1e999 0"), SA::Invalid_input, "column 3: the number '1e999' is out of range");
}

// Made to fail once: with the newlines not counted, the arc below (then refused as an arc, now
// for its sweep flag) was reported at "line 1, column 25"; with the column counted from 0, every
// column was one less.
TEST(SvgPaths, BadMarkupRefusedWithLineAndColumn)
{
  const std::string good = "<?xml version=\"1.0\"?>\n<!-- <path d=\"M bad\"/> -->\n<svg>\n  <g transform=\"scale(2)\">\n"
                           "    <path id='a' d='M0 0 L 1 1'/><path d=\"M 2 2 Q 3 3 4 2 Z\"></path>\n  </g>\n"
                           "<pathology d=\"not a path\"/></svg>\n";
  const SA::Svg_paths svg = SA::parse_svg_paths(good);
  EXPECT_EQ(svg.path_elements, 2u);
  ASSERT_EQ(svg.contours.size(), 2u);
  EXPECT_TRUE(svg.contours[1].closed);
  EXPECT_THROW_REASON(SA::parse_svg_paths("<svg>\n<path\n   d=\"M 0 0 a 1 1 0 0 2 2 2\"/>", "'x.svg'"), SA::Invalid_input,
                      "'x.svg' line 3, column 23: expected the sweep flag (0 or 1) of 'a', found '2'");
  EXPECT_THROW_REASON(SA::parse_svg_paths("<svg>\n  <path d=\"M 0 0 L 1 1\"", "f"), SA::Invalid_input,
                      "f line 2, column 3: unterminated tag <path");
  EXPECT_THROW_REASON(SA::parse_svg_paths("<svg>\n<path d=\"M 0 0 L 1 1/>\n</svg>\n", "f"), SA::Invalid_input,
                      "f line 2, column 9: unterminated value of attribute 'd'");
  EXPECT_THROW_REASON(SA::parse_svg_paths("<svg><path d /></svg>", "f"), SA::Invalid_input,
                      "line 1, column 12: attribute 'd' of <path> has no value");
  EXPECT_THROW_REASON(SA::parse_svg_paths("<svg><path d=M/></svg>", "f"), SA::Invalid_input,
                      "line 1, column 14: the value of attribute 'd' is not quoted");
  EXPECT_THROW_REASON(SA::parse_svg_paths("<svg><!-- <path d='M 0 0 L 1 1'/> </svg>", "f"), SA::Invalid_input,
                      "line 1, column 6: unterminated comment");
  EXPECT_THROW_REASON(SA::parse_svg_paths("<svg><path d='M 0 0&#10;L 1 1'/></svg>", "f"), SA::Invalid_input,
                      "column 20: character and entity references");
  EXPECT_THROW_REASON(SA::parse_svg_paths("<svg><defs><path d='M 0 0 L 1 1'/></defs></svg>", "f"), SA::Invalid_input,
                      "f: no <path> with a 'd' attribute and no basic shape");
  EXPECT_THROW_REASON(SA::read_svg_paths("/no/such/file.svg"), SA::Invalid_input,
                      "cannot open SVG file '/no/such/file.svg': No such file");
}
