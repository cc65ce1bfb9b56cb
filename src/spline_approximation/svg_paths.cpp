// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The path-data grammar of SVG 1.1 (section 8.3), and the reader's entry points (the markup is
// read in svg_markup.cpp, drawn in svg_render.cpp).  Every error names the line and column of
// the character where the input stops making sense.

#include <CGAL/Spline_approximation/Svg_paths.h>
#include <CGAL/Spline_approximation/errors.h>

#include "svg_document.h"

#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>

namespace CGAL {
namespace Spline_approximation {
namespace {

using namespace svg_internal;

const char* const end_of_path = "the end of the path data";

// The path data of [begin, end) in a located text, parsed into contours.
class Path_data_parser
{
public:
  Path_data_parser(const Located_text& in, std::size_t begin, std::size_t end)
    : in_(in), s_(in.text()), at_(begin), end_(end) {}

  std::vector<Bezier_contour> parse()
  {
    char command = 0; // the command in force (repeated implicitly)
    skip_separators(false);
    while(at_ < end_) {
      const std::size_t where = at_;
      const char c = s_[at_];
      if(std::isalpha(static_cast<unsigned char>(c))) {
        if(!std::strchr("MmLlHhVvCcSsQqTtZzAa", c)) in_.fail(where, "unknown path command '" + std::string(1, c) + "'");
        if(command == 0 && c != 'M' && c != 'm')
          in_.fail(where, "path data must start with a moveto (M or m), not '" + std::string(1, c) + "'");
        command = c;
        ++at_;
      } else if(command == 0) {
        in_.fail(where, "path data must start with a moveto (M or m), found " + shown(s_, where, end_, end_of_path));
      } else if(command == 'Z' || command == 'z') {
        in_.fail(where, "expected a command after 'Z', found " + shown(s_, where, end_, end_of_path));
      }
      // else: an implicit repeat of the command in force
      run(command);
      if(command == 'M') command = 'L'; // pairs after a moveto are linetos (SVG 1.1, 8.3.2)
      if(command == 'm') command = 'l';
      skip_separators(false);
    }
    end_contour(false);
    return std::move(contours_);
  }

private:
  typedef Eigen::RowVector2d Point;

  void skip_separators(bool comma_allowed) { svg_internal::skip_separators(s_, at_, end_, comma_allowed); }

  double number(char command)
  {
    skip_separators(true);
    return scan_number(in_, at_, end_, std::string("a number for '") + command + "'", end_of_path);
  }

  // An arc flag: one character, 0 or 1 (so "11" is two flags).
  bool flag(char command, const char* which)
  {
    skip_separators(true);
    if(at_ < end_ && (s_[at_] == '0' || s_[at_] == '1')) return s_[at_++] == '1';
    in_.fail(at_, std::string("expected the ") + which + " flag (0 or 1) of '" + command + "', found " +
                      shown(s_, at_, end_, end_of_path));
  }

  Point point(char command, bool relative)
  {
    Point p;
    p[0] = number(command);
    p[1] = number(command);
    return relative ? Point(current_ + p) : p;
  }

  void add(int degree, std::initializer_list<Point> points)
  {
    Bezier_segment s;
    s.degree = degree;
    s.control_points.row(0) = current_;
    int i = 1;
    for(const Point& p : points) s.control_points.row(i++) = p;
    add(s);
  }

  void add(const Bezier_segment& s)
  {
    if(!open_) { // a drawing command after Z starts a new subpath at the same point (SVG 1.1, 8.3.3)
      open_ = true;
      start_ = current_;
    }
    contour_.segments.push_back(s);
    current_ = s.end();
  }

  void arc(char command, bool rel)
  {
    const std::size_t where = at_;
    const double rx = number(command), ry = number(command), rotation = number(command);
    const bool large_arc = flag(command, "large-arc"), sweep = flag(command, "sweep");
    const Point to = point(command, rel);
    std::string reason;
    const std::optional<Bezier_segment> s = svg_arc(current_, to, rx, ry, rotation, large_arc, sweep, reason);
    if(!reason.empty()) in_.fail(where, reason);
    if(s) add(*s); // equal end points: no segment (SVG 1.1, F.6.2)
  }

  void end_contour(bool closed)
  {
    if(closed && !contour_.segments.empty() && current_ != start_) add(1, {start_});
    contour_.closed = closed;
    if(!contour_.segments.empty()) contours_.push_back(std::move(contour_));
    contour_ = Bezier_contour();
    open_ = false;
  }

  // One instance of a command (its numbers).
  void run(char command)
  {
    const bool rel = std::islower(static_cast<unsigned char>(command));
    const char upper = char(std::toupper(static_cast<unsigned char>(command)));
    char kind = 0; // what this segment was, for the reflections of S and T
    switch(upper) {
    case 'M':
      end_contour(false);
      current_ = point(command, rel && have_point_);
      start_ = current_;
      open_ = true;
      have_point_ = true;
      break;
    case 'L': add(1, {point(command, rel)}); break;
    case 'H': { const double x = number(command); add(1, {Point(rel ? current_[0] + x : x, current_[1])}); break; }
    case 'V': { const double y = number(command); add(1, {Point(current_[0], rel ? current_[1] + y : y)}); break; }
    case 'C': {
      const Point a = point(command, rel), b = point(command, rel), e = point(command, rel);
      add(3, {a, b, e});
      last_control_ = b;
      kind = 'C';
      break;
    }
    case 'S': { // the first control point reflects the previous cubic's second, if the previous was a cubic
      const Point a = previous_ == 'C' ? Point(2 * current_ - last_control_) : current_;
      const Point b = point(command, rel), e = point(command, rel);
      add(3, {a, b, e});
      last_control_ = b;
      kind = 'C';
      break;
    }
    case 'Q': {
      const Point a = point(command, rel), e = point(command, rel);
      add(2, {a, e});
      last_control_ = a;
      kind = 'Q';
      break;
    }
    case 'T': {
      const Point a = previous_ == 'Q' ? Point(2 * current_ - last_control_) : current_;
      add(2, {a, point(command, rel)});
      last_control_ = a;
      kind = 'Q';
      break;
    }
    case 'A': arc(command, rel); break;
    case 'Z':
      end_contour(true);
      current_ = start_;
      break;
    }
    previous_ = kind;
  }

  const Located_text& in_;
  const std::string& s_;
  std::size_t at_, end_;
  std::vector<Bezier_contour> contours_;
  Bezier_contour contour_;
  Point current_ = Point::Zero(), start_ = Point::Zero(), last_control_ = Point::Zero();
  bool open_ = false, have_point_ = false;
  char previous_ = 0;
};

} // namespace

namespace svg_internal {

std::vector<Bezier_contour> parse_path_data(const Located_text& in, std::size_t begin, std::size_t end)
{
  return Path_data_parser(in, begin, end).parse();
}

} // namespace svg_internal

std::vector<Bezier_contour> parse_svg_path_data(const std::string& d, const std::string& source)
{
  const Located_text in(d, source);
  return Path_data_parser(in, 0, d.size()).parse();
}

Svg_paths parse_svg_paths(const std::string& s, const std::string& source)
{
  const Located_text in(s, source);
  Svg_paths out;
  Svg_document document = read_svg_markup(in);
  render_svg(in, document, out);
  if(out.path_elements + out.shape_elements == 0)
    throw Invalid_input(source + ": no <path> with a 'd' attribute and no basic shape (<rect>, <circle>, <ellipse>, "
                                 "<line>, <polyline>, <polygon>) is drawn");
  return out;
}

Svg_paths read_svg_paths(const std::string& filename)
{
  std::ifstream file(filename, std::ios::binary);
  if(!file) throw Invalid_input("cannot open SVG file '" + filename + "': " + std::strerror(errno));
  std::ostringstream text;
  text << file.rdbuf();
  if(file.bad()) throw Invalid_input("cannot read SVG file '" + filename + "'");
  return parse_svg_paths(text.str(), "'" + filename + "'");
}

} // namespace Spline_approximation
} // namespace CGAL
