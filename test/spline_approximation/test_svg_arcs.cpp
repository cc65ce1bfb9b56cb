// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// SVG elliptical arcs against truth built here: sampled points on the known circle or ellipse
// (its implicit equation), the four flag combinations of one chord giving the four known
// centres and sweeps, radii too small scaled up to the half ellipse, a rotated ellipse through
// two points placed on it, degenerate arcs, joints and kinks, and bad flags refused.

#include <CGAL/Spline_approximation/Svg_paths.h>

#include "expect_reason.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace SA = CGAL::Spline_approximation;

namespace {

const double arc_test_pi = 3.14159265358979323846;

// The largest |implicit(p)| over every sample of every arc of `c`, implicit(p) = 0 on the truth.
template <class Implicit>
double arc_test_worst_residual(const SA::Bezier_contour& c, const Implicit& implicit, int samples = 200)
{
  double worst = 0;
  const SA::Sampled_contour s = SA::sample_contour(c, samples);
  for(Eigen::Index i = 0; i < s.points.rows(); ++i) worst = std::max(worst, std::abs(implicit(s.points.row(i))));
  return worst;
}

std::string arc_test_number(double x)
{
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}

} // namespace

// Made to fail once: with the arc evaluated as centre + cos(t) axis_v + sin(t) axis_u (axes
// swapped), the first half circle's middle was (10, 0), not (0, 10) (the residuals stayed at
// round-off: the swap only moves the points along the curve, hence the middle point checked);
// with the end points not returned exactly at u = 0 and u = 1, the joint was (-10, 1.2e-15).
TEST(SvgArcs, SamplesLieOnTheCircleAndTheEllipse)
{
  // A full circle of radius 10 about the origin from two half arcs, absolute and relative.
  for(const char* d : {"M 10 0 A 10 10 0 0 1 -10 0 A 10 10 0 0 1 10 0 Z", "m10 0 a10 10 0 0 1-20 0 a10,10,0,0,1,20,0z"}) {
    SCOPED_TRACE(d);
    const std::vector<SA::Bezier_contour> c = SA::parse_svg_path_data(d);
    ASSERT_EQ(c.size(), 1u);
    ASSERT_EQ(c[0].segments.size(), 2u); // Z is back at the start: no closing line
    EXPECT_TRUE(c[0].closed && c[0].segments[0].is_arc && c[0].segments[1].is_arc);
    const double r = arc_test_worst_residual(c[0], [](const Eigen::RowVector2d& p) { return p.squaredNorm() / 100 - 1; });
    EXPECT_LT(r, 1e-12);
    EXPECT_EQ(c[0].segments[0](1.0), Eigen::RowVector2d(-10, 0)); // the joints exactly
    EXPECT_EQ(c[0].segments[1](0.0), Eigen::RowVector2d(-10, 0));
    // The sweep: from angle 0 through +90 degrees (y down in SVG: sweep 1 is the positive angle).
    EXPECT_NEAR(c[0].segments[0](0.5)[0], 0, 1e-14);
    EXPECT_NEAR(c[0].segments[0](0.5)[1], 10, 1e-14);
  }
  // An ellipse of semi-axes 6 (x) and 2 (y) about (1, 1), a quarter and three quarters of it.
  const std::vector<SA::Bezier_contour> e = SA::parse_svg_path_data("M 7 1 A 6 2 0 0 0 1 -1 A 6 2 0 1 0 7 1");
  const double r = arc_test_worst_residual(e[0], [](const Eigen::RowVector2d& p) {
    return (p[0] - 1) * (p[0] - 1) / 36 + (p[1] - 1) * (p[1] - 1) / 4 - 1;
  });
  EXPECT_LT(r, 1e-12);
  EXPECT_NEAR(e[0].segments[0].arc.sweep_angle, -arc_test_pi / 2, 1e-14);
  EXPECT_NEAR(e[0].segments[1].arc.sweep_angle, -3 * arc_test_pi / 2, 1e-14);
}

// The chord from (0, 0) to (6, 0) on circles of radius 5: centres (3, 4) and (3, -4); the short
// arcs sweep 2 asin(3/5), the long ones 2 pi minus that.  Their middle points, found by hand:
// about (3, 4) the short arc passes (3, -1), the long one (3, 9); about (3, -4): (3, 1) and (3, -9).
// Made to fail once: with the sweep flag's correction flipped (2 pi taken off when sweep is 1,
// added when 0), every sweep and middle point was wrong ((3, 9) for (3, -1)), also in the other
// arc tests but the one on bad flags.
TEST(SvgArcs, FourFlagCombinationsGiveTheFourArcs)
{
  const double small = 2 * std::asin(0.6), large = 2 * arc_test_pi - small;
  struct Case { const char* flags; double cy, sweep, mid_y; };
  for(const Case& k : {Case{"0 1", 4, small, -1}, Case{"1 0", 4, -large, 9}, Case{"0 0", -4, -small, 1},
                       Case{"1 1", -4, large, -9}}) {
    SCOPED_TRACE(k.flags);
    const std::vector<SA::Bezier_contour> c = SA::parse_svg_path_data(std::string("M 0 0 A 5 5 0 ") + k.flags + " 6 0");
    ASSERT_EQ(c[0].segments.size(), 1u);
    const SA::Bezier_segment& s = c[0].segments[0];
    ASSERT_TRUE(s.is_arc);
    EXPECT_NEAR(s.arc.center[0], 3, 1e-14);
    EXPECT_NEAR(s.arc.center[1], k.cy, 1e-14);
    EXPECT_NEAR(s.arc.sweep_angle, k.sweep, 1e-14);
    EXPECT_NEAR(s(0.5)[0], 3, 1e-14);
    EXPECT_NEAR(s(0.5)[1], k.mid_y, 1e-14);
    EXPECT_NEAR((s.arc(1.0) - Eigen::RowVector2d(6, 0)).norm(), 0, 1e-14); // the formula meets the end point
    const double r = arc_test_worst_residual(c[0], [&](const Eigen::RowVector2d& p) {
      return (p - Eigen::RowVector2d(3, k.cy)).squaredNorm() / 25 - 1;
    });
    EXPECT_LT(r, 1e-12);
  }
}

// Made to fail once: without the radius correction (F.6.6) (the radicand clamped to 0, the radius
// left at 1) the circle's far point was (3, -1), not (3, -3), and the residual 0.89.
TEST(SvgArcs, RadiiTooSmallGiveTheHalfEllipse)
{
  // Radius 1 for a chord of 6: scaled to 3, the half circle about (3, 0); sweep 1 passes (3, -3).
  std::vector<SA::Bezier_contour> c = SA::parse_svg_path_data("M 0 0 A 1 1 0 0 1 6 0");
  const SA::Bezier_segment& s = c[0].segments[0];
  EXPECT_NEAR(s.arc.center.norm() - 3, 0, 1e-14);
  EXPECT_NEAR(std::abs(s.arc.sweep_angle), arc_test_pi, 1e-14);
  EXPECT_NEAR(s(0.5)[0], 3, 1e-14);
  EXPECT_NEAR(s(0.5)[1], -3, 1e-14);
  EXPECT_LT(arc_test_worst_residual(c[0], [](const Eigen::RowVector2d& p) {
              return (p - Eigen::RowVector2d(3, 0)).squaredNorm() / 9 - 1;
            }), 1e-12);
  // Radii 1 and 2 (ratio kept): scaled by 3 to 3 and 6; either large-arc flag gives the same half.
  for(const char* d : {"M 0 0 A 1 2 0 0 1 6 0", "M 0 0 A 1 2 0 1 1 6 0", "M 0 0 A -1 -2 0 0 1 6 0"}) {
    SCOPED_TRACE(d);
    c = SA::parse_svg_path_data(d);
    EXPECT_NEAR(c[0].segments[0](0.5)[1], -6, 1e-14);
    EXPECT_LT(arc_test_worst_residual(c[0], [](const Eigen::RowVector2d& p) {
                return (p[0] - 3) * (p[0] - 3) / 9 + p[1] * p[1] / 36 - 1;
              }), 1e-12);
  }
  // A zero radius: a line; equal end points: no segment (the L after it still drawn).
  c = SA::parse_svg_path_data("M 0 0 A 0 5 0 0 1 4 3 A 5 5 0 0 1 4 3 L 5 5");
  ASSERT_EQ(c[0].segments.size(), 2u);
  EXPECT_FALSE(c[0].segments[0].is_arc);
  EXPECT_EQ(c[0].segments[0].end(), Eigen::RowVector2d(4, 3));
  EXPECT_EQ(c[0].segments[1].start(), Eigen::RowVector2d(4, 3));
}

// Two points placed on the ellipse about (1, 2) with semi-axes 4 and 2 turned by 30 degrees, at
// angles 20 and 130 degrees of its parametrisation: the short positive arc must have that centre,
// sweep 110 degrees and pass the point at 75; the long negative one sweeps -250 through 255.
// Made to fail once: with Step 1's rotation transposed (the x-axis rotation taken as -30 there),
// the centre was 1.26 away, the sweep 70 degrees off, the residual 2.72.
TEST(SvgArcs, RotatedEllipse)
{
  const double phi = arc_test_pi / 6, deg = arc_test_pi / 180;
  const Eigen::RowVector2d c(1, 2);
  auto on = [&](double t) {
    return Eigen::RowVector2d(c[0] + 4 * std::cos(t) * std::cos(phi) - 2 * std::sin(t) * std::sin(phi),
                              c[1] + 4 * std::cos(t) * std::sin(phi) + 2 * std::sin(t) * std::cos(phi));
  };
  auto implicit = [&](const Eigen::RowVector2d& p) {
    const Eigen::RowVector2d q = p - c;
    const double x = q[0] * std::cos(phi) + q[1] * std::sin(phi), y = -q[0] * std::sin(phi) + q[1] * std::cos(phi);
    return x * x / 16 + y * y / 4 - 1;
  };
  const Eigen::RowVector2d a = on(20 * deg), b = on(130 * deg);
  const std::string ends = "M " + arc_test_number(a[0]) + " " + arc_test_number(a[1]) + " A 4 2 30 ";
  const std::string to = " " + arc_test_number(b[0]) + " " + arc_test_number(b[1]);
  struct Case { const char* flags; double sweep, middle; };
  for(const Case& k : {Case{"0 1", 110, 75}, Case{"1 0", -250, 20 - 125}}) {
    SCOPED_TRACE(k.flags);
    const std::vector<SA::Bezier_contour> p = SA::parse_svg_path_data(ends + k.flags + to);
    const SA::Bezier_segment& s = p[0].segments[0];
    ASSERT_TRUE(s.is_arc);
    EXPECT_LT((s.arc.center - c).norm(), 1e-12);
    EXPECT_NEAR(s.arc.sweep_angle, k.sweep * deg, 1e-12);
    EXPECT_LT((s(0.5) - on(k.middle * deg)).norm(), 1e-12);
    EXPECT_LT(arc_test_worst_residual(p[0], implicit), 1e-12);
  }
}

// Made to fail once: with an arc's end derivative taken as its chord (an arc treated as a line),
// the circle of two half arcs was cut into 2 pieces at its smooth joints.
TEST(SvgArcs, JointsKinksAndSampling)
{
  const std::vector<SA::Bezier_contour> circle = SA::parse_svg_path_data("M 1 0 A 1 1 0 0 1 -1 0 A 1 1 0 0 1 1 0 Z");
  const std::vector<SA::Bezier_contour> whole = SA::split_at_kinks(circle[0]);
  ASSERT_EQ(whole.size(), 1u); // equal sweeps: C^1 in u at both joints
  EXPECT_TRUE(whole[0].closed);
  const SA::Sampled_contour s = SA::sample_contour(circle[0], 8);
  EXPECT_EQ(s.joints, (std::vector<Eigen::Index>{0, 8}));
  EXPECT_DOUBLE_EQ(s.parameters[4], 0.25); // affine in the angle on every arc
  EXPECT_NEAR(s.points(4, 0), 0, 1e-15);
  EXPECT_NEAR(s.points(4, 1), 1, 1e-15);
  // A half circle then a line: a corner at their joint, the arc's tangent there vertical.
  const std::vector<SA::Bezier_contour> d = SA::parse_svg_path_data("M 1 0 A 1 1 0 0 1 -1 0 L -3 0");
  EXPECT_EQ(SA::split_at_kinks(d[0]).size(), 2u);
  EXPECT_NEAR(d[0].segments[0].end_derivative()[0], 0, 1e-15);
  EXPECT_NEAR(d[0].segments[0].end_derivative()[1], -arc_test_pi, 1e-15);
  // Compact flags: one character each, so "112 0" is flags 1, 1 and the point (2, 0) relative.
  const std::vector<SA::Bezier_contour> e = SA::parse_svg_path_data("M0 0a1 1 0 112 0");
  ASSERT_TRUE(e[0].segments[0].is_arc);
  EXPECT_EQ(e[0].segments[0].end(), Eigen::RowVector2d(2, 0));
}

// Made to fail once: with any digit taken as a flag (not 0 or 1), "A 1 1 0 2 1 2 2" was accepted.
TEST(SvgArcs, BadFlagsRefusedWithLineAndColumn)
{
  EXPECT_THROW_REASON(SA::parse_svg_path_data("M 0 0 A 1 1 0 2 1 2 2"), SA::Invalid_input,
                      "path data line 1, column 15: expected the large-arc flag (0 or 1) of 'A', found '2'");
  EXPECT_THROW_REASON(SA::parse_svg_path_data("M 0 0\n a 1 1 0 0 -1 2 2"), SA::Invalid_input,
                      "line 2, column 12: expected the sweep flag (0 or 1) of 'a', found '-'");
  EXPECT_THROW_REASON(SA::parse_svg_path_data("M 0 0 A 1 1 0 1"), SA::Invalid_input,
                      "column 16: expected the sweep flag (0 or 1) of 'A', found the end of the path data");
  EXPECT_THROW_REASON(SA::parse_svg_path_data("M 0 0 A 1 1 0 0 1 2"), SA::Invalid_input,
                      "column 20: expected a number for 'A', found the end of the path data");
  // Radii 1e300 times the chord: not computable in doubles (the end points' offset underflows).
  EXPECT_THROW_REASON(SA::parse_svg_path_data("M 0 0 A 1e300 1e300 0 0 1 1e-300 0"), SA::Invalid_input,
                      "column 8: the arc's radii and end points are too far apart in scale");
  // Near the largest doubles: the chord's halves taken first, so this half circle is computed.
  EXPECT_NEAR(SA::parse_svg_path_data("M -1e308 0 A 1 1 0 0 1 1e308 0")[0].segments[0](0.5)[1] / 1e308, -1, 1e-15);
  EXPECT_THROW_REASON(SA::parse_svg_paths("<svg>\n  <path d='M 0 0 A 1 1 0 0 x 2 2'/>\n</svg>", "'f.svg'"),
                      SA::Invalid_input, "'f.svg' line 2, column 28: expected the sweep flag (0 or 1) of 'A', found 'x'");
}
