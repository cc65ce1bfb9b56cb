// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Located errors, SVG numbers and the transform attribute (SVG 1.1, section 7.6), for the
// SVG path reader.

#include "svg_syntax.h"

#include <CGAL/Spline_approximation/errors.h>

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <vector>

namespace CGAL {
namespace Spline_approximation {
namespace svg_internal {

void Located_text::fail(std::size_t offset, const std::string& reason) const
{
  std::size_t line = 1, column = 1;
  for(std::size_t i = 0; i < offset && i < text_.size(); ++i) {
    if(text_[i] == '\n') { ++line; column = 1; }
    else ++column;
  }
  throw Invalid_input(source_ + " line " + std::to_string(line) + ", column " + std::to_string(column) + ": " + reason);
}

std::string shown(const std::string& text, std::size_t at, std::size_t end, const char* end_name)
{
  return at < end ? "'" + std::string(1, text[at]) + "'" : std::string(end_name);
}

void skip_separators(const std::string& s, std::size_t& at, std::size_t end, bool comma_allowed)
{
  while(at < end && is_space(s[at])) ++at;
  if(comma_allowed && at < end && s[at] == ',') {
    ++at;
    while(at < end && is_space(s[at])) ++at;
  }
}

double scan_number(const Located_text& in, std::size_t& at, std::size_t end, const std::string& what,
                   const char* end_name, bool unit_may_follow)
{
  const std::string& s = in.text();
  const std::size_t start = at;
  std::size_t i = at;
  if(i < end && (s[i] == '+' || s[i] == '-')) ++i;
  std::size_t digits = 0;
  while(i < end && is_digit(s[i])) { ++i; ++digits; }
  if(i < end && s[i] == '.') {
    ++i;
    while(i < end && is_digit(s[i])) { ++i; ++digits; }
  }
  if(digits == 0) in.fail(start, "expected " + what + ", found " + shown(s, start, end, end_name));
  if(i < end && (s[i] == 'e' || s[i] == 'E')) {
    std::size_t k = i + 1;
    if(k < end && (s[k] == '+' || s[k] == '-')) ++k;
    if(!(k < end && is_digit(s[k])) && unit_may_follow) k = i; // "1em": no exponent
    else if(!(k < end && is_digit(s[k])))
      in.fail(k, "the exponent of a number has no digits, found " + shown(s, k, end, end_name));
    while(k < end && is_digit(s[k])) ++k;
    i = k;
  }
  const char* first = s.data() + start + (s[start] == '+' ? 1 : 0); // from_chars takes no '+'
  double x = 0;
  const std::from_chars_result r = std::from_chars(first, s.data() + i, x);
  if(r.ec != std::errc() || !std::isfinite(x))
    in.fail(start, "the number '" + s.substr(start, i - start) + "' is out of range");
  at = i;
  return x;
}

namespace {

const char* const end_of_transform = "the end of the transform";

Eigen::Affine2d affine(double a, double b, double c, double d, double e, double f)
{
  Eigen::Affine2d m;
  m.matrix() << a, c, e, b, d, f, 0, 0, 1;
  return m;
}

} // namespace

// Exact at multiples of 90 so that rotate(90) maps (1, 0) to (0, 1), not to (6e-17, 1).
void cos_sin_degrees(double degrees, double& c, double& s)
{
  const double r = std::fmod(degrees, 360.0);
  const double quarter = r / 90.0;
  if(quarter == std::floor(quarter)) {
    const int q = (int(quarter) % 4 + 4) % 4;
    const double table[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    c = table[q][0];
    s = table[q][1];
    return;
  }
  const double a = r * (3.14159265358979323846 / 180.0);
  c = std::cos(a);
  s = std::sin(a);
}

Eigen::Affine2d parse_transform(const Located_text& in, std::size_t begin, std::size_t end)
{
  const std::string& s = in.text();
  Eigen::Affine2d result = Eigen::Affine2d::Identity();
  std::size_t at = begin;
  bool first = true;
  for(;;) {
    skip_separators(s, at, end, false);
    if(at >= end) break;
    if(!first && s[at] == ',') { // one comma between functions
      skip_separators(s, at, end, true);
      if(at >= end) in.fail(at, "expected a transform function after ',', found the end of the transform");
    }
    first = false;
    const std::size_t name_at = at;
    while(at < end && std::isalpha(static_cast<unsigned char>(s[at]))) ++at;
    const std::string name = s.substr(name_at, at - name_at);
    static const char* const names[] = {"matrix", "translate", "scale", "rotate", "skewX", "skewY"};
    static const std::size_t counts[][2] = {{6, 6}, {1, 2}, {1, 2}, {1, 3}, {1, 1}, {1, 1}};
    int kind = -1;
    for(int k = 0; k < 6; ++k)
      if(name == names[k]) kind = k;
    if(name.empty())
      in.fail(name_at, "expected a transform function (matrix, translate, scale, rotate, skewX, skewY), found " +
                           shown(s, name_at, end, end_of_transform));
    if(kind < 0) in.fail(name_at, "unknown transform function '" + name + "'");
    skip_separators(s, at, end, false);
    if(at >= end || s[at] != '(')
      in.fail(at, "expected '(' after '" + name + "', found " + shown(s, at, end, end_of_transform));
    ++at;
    skip_separators(s, at, end, false);
    std::vector<double> v;
    while(!(at < end && s[at] == ')')) {
      if(at >= end) in.fail(at, "expected ')' to close '" + name + "(', found the end of the transform");
      if(!v.empty()) skip_separators(s, at, end, true);
      if(v.size() == 6) in.fail(at, "too many numbers in '" + name + "(...)'");
      v.push_back(scan_number(in, at, end, "a number or ')' in '" + name + "(...)'", end_of_transform));
      skip_separators(s, at, end, false);
    }
    ++at;
    const std::size_t n = v.size();
    if(n != counts[kind][0] && n != counts[kind][1]) {
      const std::string allowed = counts[kind][0] == counts[kind][1] ? std::to_string(counts[kind][0]) :
                                  std::to_string(counts[kind][0]) + " or " + std::to_string(counts[kind][1]);
      in.fail(name_at, "'" + name + "' takes " + allowed + " numbers, not " + std::to_string(n));
    }
    Eigen::Affine2d t;
    double c = 1, sn = 0;
    switch(kind) {
    case 0: t = affine(v[0], v[1], v[2], v[3], v[4], v[5]); break;
    case 1: t = affine(1, 0, 0, 1, v[0], n == 2 ? v[1] : 0); break;
    case 2: t = affine(v[0], 0, 0, n == 2 ? v[1] : v[0], 0, 0); break;
    case 3: {
      cos_sin_degrees(v[0], c, sn);
      t = affine(c, sn, -sn, c, 0, 0);
      if(n == 3) t = affine(1, 0, 0, 1, v[1], v[2]) * t * affine(1, 0, 0, 1, -v[1], -v[2]); // about (cx, cy)
      break;
    }
    default: { // skewX, skewY: tan of the angle, undefined at 90 degrees
      cos_sin_degrees(v[0], c, sn);
      if(c == 0) in.fail(name_at, "'" + name + "' of an odd multiple of 90 degrees is undefined (its tangent is infinite)");
      t = kind == 4 ? affine(1, 0, sn / c, 1, 0, 0) : affine(1, sn / c, 0, 1, 0, 0);
      break;
    }
    }
    result = result * t; // the rightmost function applies first
    if(!result.matrix().allFinite()) in.fail(name_at, "the transform is beyond double range");
  }
  return result;
}

} // namespace svg_internal
} // namespace Spline_approximation
} // namespace CGAL
