// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Shared by the SVG reader's files (not installed): located errors, the SVG number grammar,
// the transform attribute, path data and its elliptical arc.

#ifndef CGAL_SPLINE_APPROXIMATION_SRC_SVG_SYNTAX_H
#define CGAL_SPLINE_APPROXIMATION_SRC_SVG_SYNTAX_H

#include <CGAL/Spline_approximation/Bezier_contour.h>

#include <Eigen/Geometry>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace CGAL {
namespace Spline_approximation {
namespace svg_internal {

// Positions in a text, reported as "<source> line L, column C: reason" (both from 1).
class Located_text
{
public:
  Located_text(const std::string& text, const std::string& source) : text_(text), source_(source) {}
  [[noreturn]] void fail(std::size_t offset, const std::string& reason) const;
  const std::string& text() const { return text_; }
  const std::string& source() const { return source_; }

private:
  const std::string& text_;
  const std::string& source_;
};

inline bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; }
inline bool is_digit(char c) { return c >= '0' && c <= '9'; }

// The character at `at` quoted, or `end_name` ("the end of the path data") at `end`.
std::string shown(const std::string& text, std::size_t at, std::size_t end, const char* end_name);

// Skips white space, then one comma and white space after it if `comma_allowed`.
void skip_separators(const std::string& s, std::size_t& at, std::size_t end, bool comma_allowed);

// An SVG number at `at` (no separators skipped): sign? (digits ('.' digits?)? | '.' digits)
// (('e'|'E') sign? digits)?.  Fails with "expected <what>, found ..." where there is none.
// `unit_may_follow`: an 'e' without exponent digits ends the number instead (the unit of "1em").
double scan_number(const Located_text& in, std::size_t& at, std::size_t end, const std::string& what,
                   const char* end_name, bool unit_may_follow = false);

// cos and sin of an angle in degrees, exact at multiples of 90.
void cos_sin_degrees(double degrees, double& c, double& s);

// The value of a `transform` attribute in [begin, end): a list of matrix, translate, scale,
// rotate, skewX, skewY separated by white space and/or a comma, composed left to right (the
// rightmost applied first).  Empty: the identity.
Eigen::Affine2d parse_transform(const Located_text& in, std::size_t begin, std::size_t end);

// The path data in [begin, end) of a located text (SVG 1.1, 8.3), one contour per subpath that
// draws something (svg_paths.cpp).
std::vector<Bezier_contour> parse_path_data(const Located_text& in, std::size_t begin, std::size_t end);

// The SVG elliptical arc from `from` to `to` (SVG 1.1, F.6.5 and F.6.6): nothing if the end
// points are equal, a line if a radius is 0, else an arc with the radii scaled up if too small.
// `rotation_degrees` is the x-axis rotation.  Nothing with a non-empty `reason` if the arc cannot
// be computed in double precision.
std::optional<Bezier_segment> svg_arc(const Eigen::RowVector2d& from, const Eigen::RowVector2d& to, double rx,
                                      double ry, double rotation_degrees, bool large_arc, bool sweep,
                                      std::string& reason);

} // namespace svg_internal
} // namespace Spline_approximation
} // namespace CGAL

#endif
