// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The SVG markup scanned (not parsed: a small tolerant scan of the XML) into a tree of elements,
// each with the attributes that place or hide it read and checked where they are written, so
// that an error names its line and column even in an element never drawn.  <use> references
// are resolved, cycles among them refused, and what each element draws measured here, before
// anything is drawn.

#include "svg_document.h"

#include <algorithm>
#include <cstring>
#include <unordered_map>
#include <utility>

namespace CGAL {
namespace Spline_approximation {
namespace svg_internal {

namespace {

struct Attribute
{
  std::string name;
  std::size_t name_at, begin, end; // the value is [begin, end)
};

bool starts_with(const std::string& s, std::size_t at, const char* prefix)
{
  return s.compare(at, std::strlen(prefix), prefix) == 0;
}

std::string local_name(const std::string& name)
{
  const std::size_t colon = name.rfind(':');
  return colon == std::string::npos ? name : name.substr(colon + 1);
}

Element_kind kind_of(const std::string& local)
{
  static const std::pair<const char*, Element_kind> kinds[] = {
    {"svg", Element_kind::svg},       {"symbol", Element_kind::symbol},   {"use", Element_kind::use},
    {"path", Element_kind::path},     {"rect", Element_kind::rect},       {"circle", Element_kind::circle},
    {"ellipse", Element_kind::ellipse}, {"line", Element_kind::line},     {"polyline", Element_kind::polyline},
    {"polygon", Element_kind::polygon}};
  for(const auto& k : kinds)
    if(local == k.first) return k.second;
  // Never drawn where they are written (a <use> may still draw what is inside them).
  static const char* const hidden[] = {"defs", "clipPath", "mask", "marker", "pattern", "linearGradient",
                                       "radialGradient", "filter", "metadata", "title", "desc", "style",
                                       "script", "foreignObject"};
  for(const char* h : hidden)
    if(local == h) return Element_kind::not_rendered;
  return Element_kind::container; // <g>, <a>, <switch>, and anything unknown: its children are drawn
}

struct Length_attribute
{
  const char* name;
  bool non_negative, auto_allowed;
};

const std::vector<Length_attribute>& length_attributes(Element_kind kind)
{
  static const std::vector<Length_attribute> none, rect = {{"x", false, false},    {"y", false, false},
                                                           {"width", true, true},  {"height", true, true},
                                                           {"rx", true, true},     {"ry", true, true}},
                                                   circle = {{"cx", false, false}, {"cy", false, false}, {"r", true, false}},
                                                   ellipse = {{"cx", false, false}, {"cy", false, false},
                                                              {"rx", true, true},   {"ry", true, true}},
                                                   line = {{"x1", false, false}, {"y1", false, false},
                                                           {"x2", false, false}, {"y2", false, false}},
                                                   viewport = {{"x", false, false},   {"y", false, false},
                                                               {"width", true, true}, {"height", true, true}};
  switch(kind) {
  case Element_kind::rect: return rect;
  case Element_kind::circle: return circle;
  case Element_kind::ellipse: return ellipse;
  case Element_kind::line: return line;
  case Element_kind::use:
  case Element_kind::svg: return viewport;
  default: return none;
  }
}

// Reads the attributes of one start tag into its element, the lengths in the order of
// length_attributes().  Returns the id a <use> refers to ("" if it has no href).
std::string read_attributes(const Located_text& in, Element& e, const std::vector<Attribute>& attributes)
{
  const std::string& s = in.text();
  const std::string tag = "<" + e.name + ">";
  const std::vector<Length_attribute>& lengths = length_attributes(e.kind);
  e.lengths.resize(lengths.size());
  std::string display, visibility, style_display, style_visibility;
  const Attribute* href = nullptr;
  for(const Attribute& a : attributes) {
    auto no_entity = [&](const char* what) { // character references are not decoded
      const std::size_t amp = s.find('&', a.begin);
      if(amp < a.end) in.fail(amp, std::string("character and entity references in ") + what + " are not supported");
    };
    if(a.name == "transform") {
      e.transform = parse_transform(in, a.begin, a.end);
      e.transformed = true;
      e.transform_at = a.begin;
    } else if(a.name == "display") {
      display = keyword(s, a.begin, a.end);
    } else if(a.name == "visibility") {
      visibility = keyword(s, a.begin, a.end);
    } else if(a.name == "style") {
      style_display = style_property(s, a.begin, a.end, "display");
      style_visibility = style_property(s, a.begin, a.end, "visibility");
    } else if(e.kind == Element_kind::path && a.name == "d") {
      no_entity("path data");
      e.path = parse_path_data(in, a.begin, a.end);
      e.has_d = true;
      e.d_at = a.begin;
    } else if((e.kind == Element_kind::polyline || e.kind == Element_kind::polygon) && a.name == "points") {
      no_entity("points");
      const std::vector<double> v = parse_number_list(in, a.begin, a.end, "'points' of " + tag, "the end of the points");
      if(v.size() % 2 != 0)
        in.fail(a.end, "'points' of " + tag + " has an odd count of numbers (" + std::to_string(v.size()) +
                           "): the last point has no y");
      for(std::size_t i = 0; i < v.size(); i += 2) e.points.emplace_back(v[i], v[i + 1]);
    } else if(e.kind == Element_kind::use && (a.name == "href" || (!href && local_name(a.name) == "href"))) {
      href = &a; // href wins over xlink:href (SVG 2)
    } else if((e.kind == Element_kind::svg || e.kind == Element_kind::symbol) && a.name == "viewBox") {
      e.view_box = parse_view_box(in, a.begin, a.end);
    } else if((e.kind == Element_kind::svg || e.kind == Element_kind::symbol) && a.name == "preserveAspectRatio") {
      e.aspect = parse_aspect_ratio(in, a.begin, a.end);
    } else {
      for(std::size_t k = 0; k < lengths.size(); ++k)
        if(a.name == lengths[k].name) {
          const std::string what = "'" + a.name + "' of " + tag;
          e.lengths[k] = parse_length(in, a.begin, a.end, what, lengths[k].auto_allowed);
          if(lengths[k].non_negative && e.lengths[k].value < 0) in.fail(e.lengths[k].at, what + " is negative");
        }
    }
  }
  // The style attribute's declarations win over the presentation attributes.
  if(!style_display.empty()) display = style_display;
  if(!style_visibility.empty()) visibility = style_visibility;
  e.display_none = display == "none";
  if(visibility == "visible") e.visibility = 1;
  if(visibility == "hidden" || visibility == "collapse") e.visibility = 0;
  if(!href) return "";
  if(href->end == href->begin || s[href->begin] != '#' || href->end - href->begin == 1)
    in.fail(href->begin, "the <" + e.name + "> refers to '" + s.substr(href->begin, href->end - href->begin) +
                             "': only elements of the same file ('#id') are read");
  e.href_at = href->begin;
  e.href = s.substr(href->begin, href->end - href->begin);
  return e.href.substr(1);
}

// What drawing an element makes, at most: itself, its segments, and what its children and its
// target draw (saturated at `limit`: a few references can multiply a file's content
// exponentially).  Hidden elements and their content count 1.
std::size_t measure(const Svg_document& d, const Element& e, std::size_t limit)
{
  auto add = [&](std::size_t a, std::size_t b) { return std::min(limit, a + std::min(limit, b)); };
  auto hidden = [](const Element& x) { return x.display_none || x.kind == Element_kind::not_rendered; };
  std::size_t n = 1;
  for(const Bezier_contour& c : e.path) n = add(n, c.segments.size());
  if(e.kind >= Element_kind::rect) n = add(n, e.points.size() + 8); // a shape's segments (a rect's: 8 at most)
  for(std::size_t child : e.children) {
    const Element& c = d.elements[child];
    n = add(n, hidden(c) || c.kind == Element_kind::symbol ? 1 : c.drawn_size);
  }
  if(e.target != no_element) n = add(n, hidden(d.elements[e.target]) ? 1 : d.elements[e.target].drawn_size);
  return n;
}

// Refuses a cycle of references, and measures every element: a depth-first walk over children
// and <use> targets, from every element, finds an element again while it is still being walked
// (a cycle), or finishes it after everything it draws.
void refuse_cycles(const Located_text& in, Svg_document& d, std::size_t limit)
{
  std::vector<Element>& el = d.elements;
  std::vector<char> state(el.size(), 0); // 0: not seen, 1: being walked, 2: done
  std::vector<std::pair<std::size_t, std::size_t>> stack; // an element and its next edge
  for(std::size_t root = 0; root < el.size(); ++root) {
    if(state[root] != 0) continue;
    stack.emplace_back(root, 0);
    state[root] = 1;
    while(!stack.empty()) {
      const std::size_t e = stack.back().first, edge = stack.back().second++;
      std::size_t next = no_element;
      if(edge < el[e].children.size()) next = el[e].children[edge];
      else if(edge == el[e].children.size() && el[e].target != no_element) next = el[e].target;
      else {
        state[e] = 2;
        el[e].drawn_size = measure(d, el[e], limit);
        stack.pop_back();
        continue;
      }
      if(state[next] == 2) continue;
      if(state[next] == 0) {
        state[next] = 1;
        stack.emplace_back(next, 0);
        continue;
      }
      // A cycle: report the <use> on it whose reference was followed last.
      std::size_t use = e;
      for(std::size_t k = stack.size(); k-- > 0;) {
        const Element& u = el[stack[k].first];
        if(u.kind == Element_kind::use && stack[k].second > u.children.size()) {
          use = stack[k].first;
          break;
        }
      }
      const Element& u = el[use];
      bool ancestor = false;
      for(std::size_t a = use; a != no_element && !ancestor; a = el[a].parent) ancestor = a == u.target;
      in.fail(u.href_at, "the <" + u.name + "> refers to '" + u.href + "'" +
                             (ancestor ? ", which contains it: a cycle"
                                       : ", which draws this <" + u.name + "> again through other references: a cycle"));
    }
  }
}

} // namespace

Svg_document read_svg_markup(const Located_text& in)
{
  const std::string& s = in.text();
  Svg_document d;
  std::vector<std::size_t> open; // the open elements, outermost first
  std::unordered_map<std::string, std::size_t> ids; // the first element with each id
  std::vector<std::pair<std::size_t, std::string>> references; // <use> elements and the ids they name
  std::size_t at = 0;
  // Skips to the end of a construct opened at `start`, or fails naming what is unterminated.
  auto skip_to = [&](std::size_t start, const char* close, const char* what) {
    const std::size_t e = s.find(close, start);
    if(e == std::string::npos) in.fail(start, std::string("unterminated ") + what);
    at = e + std::strlen(close);
  };
  std::vector<Attribute> attributes;
  while((at = s.find('<', at)) != std::string::npos) {
    const std::size_t start = at;
    if(starts_with(s, at, "<!--")) { skip_to(start, "-->", "comment '<!--'"); continue; }
    if(starts_with(s, at, "<![CDATA[")) { skip_to(start, "]]>", "CDATA section"); continue; }
    if(starts_with(s, at, "<?")) { skip_to(start, "?>", "processing instruction '<?'"); continue; }
    if(starts_with(s, at, "<!")) { skip_to(start, ">", "tag"); continue; }
    if(starts_with(s, at, "</")) { // closes the innermost open element of that name (others: tolerated)
      std::size_t i = at + 2;
      while(i < s.size() && !is_space(s[i]) && s[i] != '>') ++i;
      const std::string name = s.substr(at + 2, i - at - 2);
      skip_to(start, ">", "tag");
      for(std::size_t k = open.size(); k-- > 0;)
        if(d.elements[open[k]].name == name) {
          open.resize(k);
          break;
        }
      continue;
    }
    // An element's start tag: its name, then attributes up to '>' or '/>'.
    std::size_t i = at + 1;
    while(i < s.size() && !is_space(s[i]) && s[i] != '>' && s[i] != '/') ++i;
    Element e;
    e.name = s.substr(at + 1, i - at - 1);
    if(e.name.empty()) in.fail(start, "a '<' that starts no tag");
    e.kind = kind_of(local_name(e.name));
    e.at = start;
    attributes.clear();
    bool self_closed = false;
    for(;;) {
      while(i < s.size() && is_space(s[i])) ++i;
      if(i >= s.size()) in.fail(start, "unterminated tag <" + e.name + " (no '>' before the end of the file)");
      if(s[i] == '>' || starts_with(s, i, "/>")) {
        self_closed = s[i] == '/';
        at = i + (self_closed ? 2 : 1);
        break;
      }
      const std::size_t name_at = i;
      while(i < s.size() && !is_space(s[i]) && s[i] != '=' && s[i] != '>' && s[i] != '/') ++i;
      const std::string attribute = s.substr(name_at, i - name_at);
      if(attribute.empty()) in.fail(name_at, "unexpected '" + std::string(1, s[name_at]) + "' in tag <" + e.name + ">");
      while(i < s.size() && is_space(s[i])) ++i;
      if(i >= s.size() || s[i] != '=') in.fail(name_at, "attribute '" + attribute + "' of <" + e.name + "> has no value");
      ++i;
      while(i < s.size() && is_space(s[i])) ++i;
      if(i >= s.size() || (s[i] != '"' && s[i] != '\''))
        in.fail(i, "the value of attribute '" + attribute + "' is not quoted");
      const std::size_t value_end = s.find(s[i], i + 1);
      if(value_end == std::string::npos) in.fail(i, "unterminated value of attribute '" + attribute + "'");
      for(const Attribute& a : attributes)
        if(a.name == attribute) in.fail(name_at, "attribute '" + attribute + "' is given twice in <" + e.name + ">");
      attributes.push_back({attribute, name_at, i + 1, value_end});
      i = value_end + 1;
    }
    const std::size_t index = d.elements.size();
    const std::string reference = read_attributes(in, e, attributes);
    for(const Attribute& a : attributes)
      if(a.name == "id") ids.emplace(s.substr(a.begin, a.end - a.begin), index);
    if(!reference.empty()) references.emplace_back(index, reference);
    e.parent = open.empty() ? no_element : open.back();
    (open.empty() ? d.top : d.elements[open.back()].children).push_back(index);
    d.elements.push_back(std::move(e));
    if(!self_closed) open.push_back(index);
  }
  for(const auto& r : references) {
    const auto target = ids.find(r.second);
    Element& use = d.elements[r.first];
    if(target == ids.end())
      in.fail(use.href_at, "the <" + use.name + "> refers to '#" + r.second + "', and no element has that id");
    use.target = target->second;
  }
  // What a <use> draws, and everything inside it, may be drawn again.
  std::vector<std::size_t> stack;
  for(const auto& r : references) stack.push_back(d.elements[r.first].target);
  while(!stack.empty()) {
    Element& e = d.elements[stack.back()];
    stack.pop_back();
    if(e.shared) continue;
    e.shared = true;
    stack.insert(stack.end(), e.children.begin(), e.children.end());
  }
  refuse_cycles(in, d, max_use_expansion + 1);
  return d;
}

} // namespace svg_internal
} // namespace Spline_approximation
} // namespace CGAL
