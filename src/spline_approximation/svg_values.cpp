// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The values of the SVG attributes that place things: lengths with units, lists of numbers,
// viewBox and preserveAspectRatio with the map they make (SVG 2, 8.2), and the two CSS
// properties read from a style attribute (display, visibility).

#include "svg_document.h"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace CGAL {
namespace Spline_approximation {
namespace svg_internal {

namespace {

const char* const end_of_value = "the end of the value";

std::string lower(std::string s)
{
  for(char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

void trim(const std::string& s, std::size_t& begin, std::size_t& end)
{
  while(begin < end && is_space(s[begin])) ++begin;
  while(end > begin && is_space(s[end - 1])) --end;
}

} // namespace

Length parse_length(const Located_text& in, std::size_t begin, std::size_t end, const std::string& what,
                    bool auto_allowed)
{
  const std::string& s = in.text();
  trim(s, begin, end);
  Length length;
  length.at = begin;
  if(auto_allowed && end - begin == 4 && lower(s.substr(begin, 4)) == "auto") return length;
  std::size_t at = begin;
  const double number = scan_number(in, at, end, "a length for " + what, end_of_value, true);
  const std::size_t unit_at = at;
  while(at < end && (std::isalpha(static_cast<unsigned char>(s[at])) || s[at] == '%')) ++at;
  if(at < end) in.fail(at, "unexpected " + shown(s, at, end, end_of_value) + " after the length of " + what);
  const std::string unit = lower(s.substr(unit_at, at - unit_at));
  // CSS absolute units in px (96 per inch), px being SVG's user unit.
  static const struct { const char* name; double px; } units[] = {
    {"", 1}, {"px", 1}, {"in", 96}, {"cm", 96 / 2.54}, {"mm", 96 / 25.4}, {"q", 96 / 101.6}, {"pt", 96.0 / 72}, {"pc", 16}};
  length.kind = Length::user;
  length.value = std::nan("");
  if(unit == "%") {
    length.kind = Length::percent;
    length.value = number;
  }
  for(const auto& u : units)
    if(unit == u.name) length.value = number * u.px;
  if(std::isnan(length.value)) {
    static const char* const relative[] = {"em", "ex", "ch", "rem", "lh", "rlh", "vw", "vh", "vmin", "vmax", "cap", "ic"};
    for(const char* r : relative)
      if(unit == r)
        in.fail(unit_at, "the unit '" + s.substr(unit_at, at - unit_at) + "' of " + what +
                             " depends on a font or a window, which are not read (px, in, cm, mm, Q, pt, pc or %)");
    in.fail(unit_at, "unknown unit '" + s.substr(unit_at, at - unit_at) + "' in " + what +
                         " (px, in, cm, mm, Q, pt, pc or %)");
  }
  if(!std::isfinite(length.value)) in.fail(begin, "the length of " + what + " is out of range");
  return length;
}

std::vector<double> parse_number_list(const Located_text& in, std::size_t begin, std::size_t end,
                                      const std::string& what, const char* end_name)
{
  const std::string& s = in.text();
  const std::string expected = "a number in " + what;
  std::vector<double> numbers;
  std::size_t at = begin;
  skip_separators(s, at, end, false);
  while(at < end) {
    numbers.push_back(scan_number(in, at, end, expected, end_name));
    skip_separators(s, at, end, false);
    if(at < end && s[at] == ',') { // one comma, then a number must follow
      ++at;
      skip_separators(s, at, end, false);
      if(at >= end) in.fail(at, "expected " + expected + " after ',', found " + end_name);
    }
  }
  return numbers;
}

View_box parse_view_box(const Located_text& in, std::size_t begin, std::size_t end)
{
  const std::vector<double> v = parse_number_list(in, begin, end, "'viewBox'", "the end of the viewBox");
  if(v.size() != 4)
    in.fail(begin, "'viewBox' takes 4 numbers (min-x, min-y, width, height), not " + std::to_string(v.size()));
  if(v[2] < 0 || v[3] < 0) in.fail(begin, std::string("the viewBox's ") + (v[2] < 0 ? "width" : "height") + " is negative");
  View_box box;
  box.x = v[0];
  box.y = v[1];
  box.width = v[2];
  box.height = v[3];
  box.at = begin;
  return box;
}

Aspect_ratio parse_aspect_ratio(const Located_text& in, std::size_t begin, std::size_t end)
{
  const std::string& s = in.text();
  std::vector<std::pair<std::string, std::size_t>> words;
  for(std::size_t at = begin; at < end;) {
    while(at < end && is_space(s[at])) ++at;
    const std::size_t first = at;
    while(at < end && !is_space(s[at])) ++at;
    if(at > first) words.emplace_back(s.substr(first, at - first), first);
  }
  Aspect_ratio aspect;
  std::size_t w = 0;
  if(w < words.size() && words[w].first == "defer") ++w; // for <image> only; no effect here
  const std::string allowed = " in 'preserveAspectRatio' (none, or xMinYMin ... xMaxYMax, then meet or slice)";
  if(w >= words.size()) in.fail(end, "expected an alignment" + allowed + ", found the end of the value");
  const std::string& align = words[w].first;
  static const char* const names[] = {"Min", "Mid", "Max"};
  bool known = align == "none";
  aspect.none = known;
  for(int x = 0; x < 3; ++x)
    for(int y = 0; y < 3; ++y)
      if(align == std::string("x") + names[x] + "Y" + names[y]) {
        known = true;
        aspect.align_x = x;
        aspect.align_y = y;
      }
  if(!known) in.fail(words[w].second, "unknown alignment '" + align + "'" + allowed);
  if(++w < words.size()) {
    if(words[w].first != "meet" && words[w].first != "slice")
      in.fail(words[w].second, "expected meet or slice after the alignment, found '" + words[w].first + "'");
    aspect.slice = words[w].first == "slice";
    ++w;
  }
  if(w < words.size()) in.fail(words[w].second, "unexpected '" + words[w].first + "' in 'preserveAspectRatio'");
  return aspect;
}

std::string style_property(const std::string& text, std::size_t begin, std::size_t end, const std::string& property)
{
  // Declarations split at ';' outside quotes, parentheses and comments.
  std::string result, declaration;
  char quote = 0;
  int parentheses = 0;
  auto finish = [&]() {
    const std::size_t colon = declaration.find(':');
    if(colon != std::string::npos) {
      std::size_t b = 0, e = colon;
      trim(declaration, b, e);
      if(lower(declaration.substr(b, e - b)) == property) {
        std::string value = lower(declaration.substr(colon + 1));
        const std::size_t important = value.find('!');
        if(important != std::string::npos) value.resize(important);
        std::size_t vb = 0, ve = value.size();
        trim(value, vb, ve);
        result = value.substr(vb, ve - vb);
      }
    }
    declaration.clear();
  };
  for(std::size_t i = begin; i < end; ++i) {
    const char c = text[i];
    if(quote == 0 && c == '/' && i + 1 < end && text[i + 1] == '*') { // a comment: skipped
      const std::size_t close = text.find("*/", i + 2);
      i = close == std::string::npos || close + 2 > end ? end : close + 1;
      continue;
    }
    if(quote != 0) {
      if(c == quote) quote = 0;
    } else if(c == '"' || c == '\'') {
      quote = c;
    } else if(c == '(') {
      ++parentheses;
    } else if(c == ')' && parentheses > 0) {
      --parentheses;
    } else if(c == ';' && parentheses == 0) {
      finish();
      continue;
    }
    declaration += c;
  }
  finish();
  return result;
}

std::string keyword(const std::string& text, std::size_t begin, std::size_t end)
{
  trim(text, begin, end);
  return lower(text.substr(begin, end - begin));
}

Eigen::Affine2d view_box_transform(const View_box& box, const Aspect_ratio& aspect, double x, double y, double width,
                                   double height)
{
  double sx = width / box.width, sy = height / box.height;
  double tx = x - box.x * sx, ty = y - box.y * sy;
  if(!aspect.none) { // one scale for both axes, the box placed by the alignment in the room left
    sx = sy = aspect.slice ? std::max(sx, sy) : std::min(sx, sy);
    tx = x - box.x * sx + aspect.align_x * (width - box.width * sx) / 2;
    ty = y - box.y * sy + aspect.align_y * (height - box.height * sy) / 2;
  }
  Eigen::Affine2d m = Eigen::Affine2d::Identity();
  m.linear() << sx, 0, 0, sy;
  m.translation() << tx, ty;
  return m;
}

} // namespace svg_internal
} // namespace Spline_approximation
} // namespace CGAL
