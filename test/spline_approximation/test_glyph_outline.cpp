// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Glyph outlines read through FreeType (DejaVu Sans, a TrueType font: lines and quadratic
// Bezier segments in integer font units) fitted back with their exact truth known: at degree 1
// a polygonal glyph gives exactly its corners; at degree 2 the quadratic outline is recovered at
// round-off with knots only at true segment joints.  Built only when FreeType was found.

#include <CGAL/Spline_approximation/Glyph_outline.h>
#include <CGAL/Spline_approximation/Spline_fit.h>

#include "expect_reason.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>

namespace SA = CGAL::Spline_approximation;

namespace {

bool have_font() { return bool(std::ifstream(SA::default_glyph_font)); }

SA::Fit_options bound_options(int degree, double max_error, bool closed)
{
  SA::Fit_options o;
  o.degree = degree;
  o.algorithm = SA::Fit_algorithm::greedy_removal;
  o.max_error = max_error;
  o.closed_curve = closed;
  return o;
}

// The parameters of the joints of a sampled contour.
std::set<double> joint_parameters(const SA::Sampled_contour& s)
{
  std::set<double> out;
  for(Eigen::Index j : s.joints) out.insert(s.parameters[j]);
  return out;
}

} // namespace

// Made to fail once: with the scale divided by units_per_em twice, the letters were 0.36 high
// (more than 500 expected); with the sampled parameters divided by the segment count + 1, the
// closing segment got a knot of its own at 0.913 besides the 12 corners of 'E'.
TEST(GlyphOutline, PolygonalGlyphGivesExactlyItsCorners)
{
  if(!have_font()) GTEST_SKIP() << "no " << SA::default_glyph_font << " (Debian: fonts-dejavu-core)";
  for(const char* text : {"E", "L", "H"}) {
    SCOPED_TRACE(text);
    const SA::Glyph_outline g = SA::read_glyph_outline(SA::default_glyph_font, SA::first_code_point(text), 1000);
    EXPECT_EQ(g.font_format, "TrueType");
    EXPECT_EQ(g.units_per_em, 2048);
    ASSERT_FALSE(g.contours.empty());
    for(const SA::Bezier_contour& c : g.contours) {
      ASSERT_TRUE(c.closed);
      const SA::Sampled_contour s = SA::sample_contour(c, 8);
      EXPECT_GT(s.points.colwise().maxCoeff()[1] - s.points.colwise().minCoeff()[1], 500); // a capital letter, em 1000
      const SA::Spline_fit fit = SA::fit_spline(s.points, s.parameters, bound_options(1, 1e-9, true));
      EXPECT_TRUE(fit.within_bound);
      EXPECT_LT(fit.max_error, 1e-10);
      // The corners: joints where the direction turns (a joint between collinear lines is no knot).
      std::set<double> corners;
      const std::size_t m = c.segments.size();
      for(std::size_t i = 0; i < m; ++i) {
        ASSERT_EQ(c.segments[i].degree, 1);
        const Eigen::RowVector2d a = c.segments[(i + m - 1) % m].end() - c.segments[(i + m - 1) % m].start();
        const Eigen::RowVector2d b = c.segments[i].end() - c.segments[i].start();
        if(std::abs(a[0] * b[1] - a[1] * b[0]) > 1e-9 * a.norm() * b.norm()) corners.insert(s.parameters[s.joints[i]]);
      }
      std::set<double> knots;
      for(Eigen::Index i = 0; i < fit.spline.knots.size(); ++i) knots.insert(fit.spline.knots[i]);
      EXPECT_EQ(knots, corners);
      EXPECT_GE(corners.size(), 4u);
    }
  }
}

// A TrueType glyph's contours are chains of quadratics; where two meet with equal derivatives
// (an implied on-curve point, the midpoint of two off-curve points) a C^1 quadratic spline has
// a simple knot there.  Elsewhere (corners, and joints smooth in shape but not in speed) it
// cannot: a spline with simple knots is C^1, and no set of knots at samples fits a kink at
// round-off (each kink leaves one condition more than the pieces around it can meet).  So the
// contours are cut at those joints (split_at_kinks) and each piece is fitted: round-off error
// with knots only at the pieces' interior joints.  Made to fail once: with the FreeType conic
// control point replaced by the segment's end (a line instead of a quadratic), no piece kept a
// knot (0 pieces with knots, more than 5 expected).
TEST(GlyphOutline, QuadraticOutlineRecoveredAtRoundoffWithKnotsAtJoints)
{
  if(!have_font()) GTEST_SKIP() << "no " << SA::default_glyph_font << " (Debian: fonts-dejavu-core)";
  std::size_t quadratics = 0, pieces_with_knots = 0;
  for(const char* text : {"o", "g", "S", "8", "e", "@"}) {
    SCOPED_TRACE(text);
    const SA::Glyph_outline g = SA::read_glyph_outline(SA::default_glyph_font, SA::first_code_point(text), 1000);
    for(const SA::Bezier_contour& c : g.contours)
      for(const SA::Bezier_contour& piece : SA::split_at_kinks(c)) {
        for(const SA::Bezier_segment& s : piece.segments) quadratics += std::size_t(s.degree == 2);
        const SA::Sampled_contour s = SA::sample_contour(piece, 10);
        if(s.points.rows() < 3) continue;
        const SA::Spline_fit fit = SA::fit_spline(s.points, s.parameters, bound_options(2, 1e-8, piece.closed));
        EXPECT_TRUE(fit.within_bound);
        EXPECT_LT(fit.max_error, 1e-9); // round-off on coordinates of about 1000
        const std::set<double> joints = joint_parameters(s);
        const Eigen::VectorXd knots = fit.spline.interior_knots();
        for(Eigen::Index i = 0; i < knots.size(); ++i)
          EXPECT_TRUE(joints.count(knots[i])) << "knot " << knots[i] << " is not at a joint";
        pieces_with_knots += std::size_t(knots.size() > 0);
      }
  }
  EXPECT_GT(quadratics, 100u);
  EXPECT_GT(pieces_with_knots, 5u); // the test sees C^1 joints kept as knots, not only single segments
}

// Made to fail once: without the missing-glyph check, U+10FFFF threw nothing (FreeType loads
// glyph 0, the "missing" box, for a character the font does not map).
TEST(GlyphOutline, MissingFontOrGlyphRefusedWithReason)
{
  EXPECT_THROW_REASON(SA::read_glyph_outline("/no/such/font.ttf", U'g'), SA::Invalid_input,
                      "cannot open font file '/no/such/font.ttf': No such file");
  if(!have_font()) GTEST_SKIP() << "no " << SA::default_glyph_font;
  EXPECT_THROW_REASON(SA::read_glyph_outline(SA::default_glyph_font, U'\U0010FFFF'), SA::Invalid_input,
                      "has no glyph for U+10FFFF");
  EXPECT_THROW_REASON(SA::read_glyph_outline(SA::default_glyph_font, U'g', 0), SA::Invalid_input,
                      "the em size must be positive");
  EXPECT_THROW_REASON(SA::read_glyph_outline("/etc/hostname", U'g'), SA::Invalid_input, "is not a font FreeType can read");
  EXPECT_EQ(SA::first_code_point("\xC3\xA9t\xC3\xA9"), U'\u00E9');
  EXPECT_EQ(SA::first_code_point("\xE2\x82\xAC"), U'\u20AC');
  EXPECT_THROW_REASON(SA::first_code_point("\xC3"), SA::Invalid_input, "is not valid UTF-8");
  EXPECT_THROW_REASON(SA::first_code_point(""), SA::Invalid_input, "an empty string");
}
