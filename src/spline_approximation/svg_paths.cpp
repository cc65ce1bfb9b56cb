// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The SVG path reader: a scan of the markup for <path d="...">, the transforms of the path and
// of the elements around it, and the path-data grammar of SVG 1.1 (section 8.3).  Every error
// names the line and column of the character where the input stops making sense.

#include <CGAL/Spline_approximation/Svg_paths.h>
#include <CGAL/Spline_approximation/errors.h>

#include "svg_syntax.h"

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

bool starts_with(const std::string& s, std::size_t at, const char* prefix)
{
  return s.compare(at, std::strlen(prefix), prefix) == 0;
}

} // namespace

std::vector<Bezier_contour> parse_svg_path_data(const std::string& d, const std::string& source)
{
  const Located_text in(d, source);
  return Path_data_parser(in, 0, d.size()).parse();
}

Svg_paths parse_svg_paths(const std::string& s, const std::string& source)
{
  const Located_text in(s, source);
  Svg_paths out;
  // The open elements and the transform from each one's coordinates to the document's: an
  // element's `transform` applies to it and everything inside it, after its own children's.
  struct Open_element
  {
    std::string name;
    Eigen::Affine2d to_document;
    bool transformed;
  };
  std::vector<Open_element> open_elements;
  std::size_t at = 0;
  // Skips to the end of a construct opened at `open`, or fails naming what is unterminated.
  auto skip_to = [&](std::size_t open, const char* close, const char* what) {
    const std::size_t e = s.find(close, open);
    if(e == std::string::npos) in.fail(open, std::string("unterminated ") + what);
    at = e + std::strlen(close);
  };
  while((at = s.find('<', at)) != std::string::npos) {
    const std::size_t open = at;
    if(starts_with(s, at, "<!--")) { skip_to(open, "-->", "comment '<!--'"); continue; }
    if(starts_with(s, at, "<![CDATA[")) { skip_to(open, "]]>", "CDATA section"); continue; }
    if(starts_with(s, at, "<?")) { skip_to(open, "?>", "processing instruction '<?'"); continue; }
    if(starts_with(s, at, "<!")) { skip_to(open, ">", "tag"); continue; }
    if(starts_with(s, at, "</")) { // closes the innermost open element of that name (others: tolerated)
      std::size_t i = at + 2;
      while(i < s.size() && !is_space(s[i]) && s[i] != '>') ++i;
      const std::string name = s.substr(at + 2, i - at - 2);
      skip_to(open, ">", "tag");
      for(std::size_t k = open_elements.size(); k-- > 0;)
        if(open_elements[k].name == name) {
          open_elements.resize(k);
          break;
        }
      continue;
    }
    // An element's start tag: its name, then attributes up to '>' or '/>'.
    std::size_t i = at + 1;
    while(i < s.size() && !is_space(s[i]) && s[i] != '>' && s[i] != '/') ++i;
    const std::string name = s.substr(at + 1, i - at - 1);
    if(name.empty()) in.fail(open, "a '<' that starts no tag");
    const bool path = name == "path" || (name.size() > 5 && name.compare(name.size() - 5, 5, ":path") == 0);
    Open_element element{name, Eigen::Affine2d::Identity(), false};
    if(!open_elements.empty()) {
      element.to_document = open_elements.back().to_document;
      element.transformed = open_elements.back().transformed;
    }
    std::vector<Bezier_contour> contours;
    bool has_d = false;
    std::size_t d_at = 0;
    for(;;) {
      while(i < s.size() && is_space(s[i])) ++i;
      if(i >= s.size()) in.fail(open, "unterminated tag <" + name + " (no '>' before the end of the file)");
      if(s[i] == '>' || starts_with(s, i, "/>")) {
        at = i + (s[i] == '>' ? 1 : 2);
        if(s[i] == '>') open_elements.push_back(element);
        break;
      }
      const std::size_t name_at = i;
      while(i < s.size() && !is_space(s[i]) && s[i] != '=' && s[i] != '>' && s[i] != '/') ++i;
      const std::string attribute = s.substr(name_at, i - name_at);
      if(attribute.empty()) in.fail(name_at, "unexpected '" + std::string(1, s[name_at]) + "' in tag <" + name + ">");
      while(i < s.size() && is_space(s[i])) ++i;
      if(i >= s.size() || s[i] != '=') in.fail(name_at, "attribute '" + attribute + "' of <" + name + "> has no value");
      ++i;
      while(i < s.size() && is_space(s[i])) ++i;
      if(i >= s.size() || (s[i] != '"' && s[i] != '\''))
        in.fail(i, "the value of attribute '" + attribute + "' is not quoted");
      const std::size_t value_begin = i + 1, value_end = s.find(s[i], value_begin);
      if(value_end == std::string::npos) in.fail(i, "unterminated value of attribute '" + attribute + "'");
      i = value_end + 1;
      if(attribute == "transform") {
        element.to_document = element.to_document * parse_transform(in, value_begin, value_end);
        element.transformed = true;
        if(!element.to_document.matrix().allFinite())
          in.fail(value_begin, "the transform, composed with those of the elements around it, is beyond double range");
      }
      if(path && attribute == "d") {
        d_at = value_begin;
        const std::size_t amp = s.find('&', value_begin);
        if(amp < value_end) in.fail(amp, "character and entity references in path data are not supported");
        Path_data_parser parser(in, value_begin, value_end);
        for(Bezier_contour& c : parser.parse()) contours.push_back(std::move(c));
        has_d = true;
      }
    }
    if(has_d) { // the path's own transform may come after its d
      for(Bezier_contour& c : contours) {
        if(element.transformed) c = transformed(c, element.to_document);
        for(const Bezier_segment& segment : c.segments)
          if(!segment.control_points.allFinite() || !segment.arc.center.allFinite() || !segment.arc.axis_u.allFinite() ||
             !segment.arc.axis_v.allFinite())
            in.fail(d_at, "the path's transformed coordinates are beyond double range");
        out.contours.push_back(std::move(c));
      }
      ++out.path_elements;
    }
  }
  if(out.path_elements == 0) throw Invalid_input(source + ": no <path> element with a 'd' attribute");
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
