// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The SVG document drawn into contours in viewport coordinates: every element's transform, the
// viewports of <svg> (width, height, viewBox, preserveAspectRatio) and of a <symbol> drawn by a
// <use>, a <use>'s x and y, display and visibility, and percentages resolved against the
// viewport they are drawn in.  Paths were parsed with the markup; basic shapes are made here.

#include "svg_document.h"

#include <cmath>
#include <limits>

namespace CGAL {
namespace Spline_approximation {
namespace svg_internal {

namespace {

const std::size_t max_depth = 256; // nesting, through <use> too: bounds the recursion
const double unknown = std::numeric_limits<double>::quiet_NaN();

enum class Axis { x, y, diagonal };

class Renderer
{
public:
  Renderer(const Located_text& in, Svg_document& d, Svg_paths& out) : in_(in), d_(d), out_(out) {}

  void run()
  {
    const Context top;
    for(std::size_t e : d_.top) draw(e, top, 0, nullptr);
  }

private:
  struct Context
  {
    Eigen::Affine2d to_viewport = Eigen::Affine2d::Identity();
    bool transformed = false; // to_viewport is not the identity (skipped then: coordinates untouched)
    // The nearest viewport's size in its user units (percentages refer to it); NaN: not given.
    double viewport_width = unknown, viewport_height = unknown;
    bool visible = true;              // the inherited visibility
    bool in_svg = false;              // an <svg> inside is nested (its x and y apply)
    bool in_use = false;              // drawn by a <use> (counted there)
  };

  // A length in user units: `absent` where not given; a percentage of the viewport, NaN where
  // the viewport's size is unknown and `soft`, else refused.
  double resolve(const Length& l, Axis axis, const Context& c, double absent, bool soft = false) const
  {
    if(l.kind == Length::absent) return absent;
    if(l.kind == Length::user) return l.value;
    const double w = c.viewport_width, h = c.viewport_height;
    const double side = axis == Axis::x ? w : axis == Axis::y ? h : std::sqrt((w * w + h * h) / 2);
    if(std::isnan(side) && !soft)
      in_.fail(l.at, "a percentage of the viewport, whose size the document does not give (no 'width' and "
                     "'height', nor a 'viewBox', on the outermost <svg>)");
    return l.value / 100 * side;
  }

  // A viewport's width or height: 100 % where not given.
  double size(const Length& l, Axis axis, const Context& c) const
  {
    Length full;
    full.kind = Length::percent;
    full.value = 100;
    return resolve(l.kind == Length::absent ? full : l, axis, c, 0, true);
  }

  void compose(Context& c, const Eigen::Affine2d& m, std::size_t at, const std::string& what) const
  {
    c.to_viewport = c.to_viewport * m; // m applies first: it is the inner one
    c.transformed = true;
    if(!c.to_viewport.matrix().allFinite())
      in_.fail(at, what + ", composed with those of the elements around it, is beyond double range");
  }

  void emit(Bezier_contour contour, const Context& c, std::size_t at, const std::string& what)
  {
    Bezier_contour m = c.transformed ? transformed(contour, c.to_viewport) : std::move(contour);
    for(const Bezier_segment& s : m.segments) {
      // An arc's points are within |centre| + |axis_u| + |axis_v|: finite, so are its samples.
      const Eigen::RowVector2d reach = s.arc.center.cwiseAbs() + s.arc.axis_u.cwiseAbs() + s.arc.axis_v.cwiseAbs();
      if(!s.control_points.allFinite() || !reach.allFinite()) in_.fail(at, what + " beyond double range");
    }
    out_.contours.push_back(std::move(m));
  }

  // `use`: the <use> drawing this element, if it is its target (a <symbol> is drawn only so).
  void draw(std::size_t index, const Context& outer, std::size_t depth, const Element* use)
  {
    Element& e = d_.elements[index];
    if(depth > max_depth)
      in_.fail(e.at, "elements nested more than " + std::to_string(max_depth) + " deep (counting what <use> draws)");
    if(e.display_none || e.kind == Element_kind::not_rendered) return;
    if(e.kind == Element_kind::symbol && !use) return;
    Context c = outer;
    if(e.visibility >= 0) c.visible = e.visibility == 1;
    if(e.transformed) compose(c, e.transform, e.transform_at, "the transform");
    switch(e.kind) {
    case Element_kind::svg:
      if(!enter_svg(e, c, use)) return;
      break;
    case Element_kind::symbol: // the <use>'s width and height (100 % by default) are its viewport
      if(!enter_viewport(e, c, 0, 0, size(use->lengths[2], Axis::x, c), size(use->lengths[3], Axis::y, c), false))
        return;
      break;
    case Element_kind::use:
      draw_use(e, c, depth);
      return;
    case Element_kind::path:
      if(e.has_d && c.visible) {
        ++out_.path_elements;
        for(Bezier_contour& p : e.path) // drawn once unless a <use> may draw it: moved, not copied
          emit(e.shared ? p : std::move(p), c, e.d_at, "the path's transformed coordinates are");
      }
      return;
    case Element_kind::container:
      break;
    default:
      draw_shape(e, c);
      return;
    }
    for(std::size_t child : e.children) draw(child, c, depth + 1, nullptr);
  }

  // The referenced element drawn as if it were the <use>'s only child, moved by x and y after
  // the <use>'s own transform (SVG 2, 5.6).
  void draw_use(const Element& e, Context c, std::size_t depth)
  {
    if(e.target == no_element) return; // no href: nothing to draw
    const double x = resolve(e.lengths[0], Axis::x, c, 0);
    const double y = resolve(e.lengths[1], Axis::y, c, 0);
    if(x != 0 || y != 0) compose(c, Eigen::Affine2d(Eigen::Translation2d(x, y)), e.at, "the translation by x and y");
    if(!c.in_use) { // what this <use> draws was measured with the markup, nested <use> elements included
      const Element& t = d_.elements[e.target];
      expansion_ += t.display_none || t.kind == Element_kind::not_rendered ? 1 : t.drawn_size;
      if(expansion_ > max_use_expansion)
        in_.fail(e.href_at, "the <use> elements draw more than " + std::to_string(max_use_expansion) +
                                " elements and segments in all (refused as a file that multiplies its content)");
      c.in_use = true;
    }
    draw(e.target, c, depth + 1, &e);
  }

  // An <svg>'s viewport: where nested, at x, y and sized by width and height (100 % by default;
  // a <use> drawing it may give others).  The outermost one's x and y do not apply, and its
  // size, where not given in absolute units, comes from the viewBox (a percentage refers to a
  // window, which a file does not have).
  bool enter_svg(const Element& e, Context& c, const Element* use)
  {
    const Length& width = use && use->lengths[2].kind != Length::absent ? use->lengths[2] : e.lengths[2];
    const Length& height = use && use->lengths[3].kind != Length::absent ? use->lengths[3] : e.lengths[3];
    const bool outermost = !c.in_svg;
    c.in_svg = true;
    if(!outermost)
      return enter_viewport(e, c, resolve(e.lengths[0], Axis::x, c, 0), resolve(e.lengths[1], Axis::y, c, 0),
                            size(width, Axis::x, c), size(height, Axis::y, c), false);
    double w = width.kind == Length::user ? width.value : unknown;
    double h = height.kind == Length::user ? height.value : unknown;
    if(e.view_box && e.view_box->width > 0 && e.view_box->height > 0) {
      const View_box& b = *e.view_box;
      if(std::isnan(w) && std::isnan(h)) {
        w = b.width;
        h = b.height;
      } else if(std::isnan(w)) {
        w = h * b.width / b.height; // the viewBox's aspect ratio
      } else if(std::isnan(h)) {
        h = w * b.height / b.width;
      }
    }
    return enter_viewport(e, c, 0, 0, w, h, true);
  }

  // The viewBox of `e`, if any, mapped into the viewport (x, y, w, h), which becomes the one its
  // content's percentages refer to.  False where a zero size disables the element.
  bool enter_viewport(const Element& e, Context& c, double x, double y, double w, double h, bool outermost)
  {
    Eigen::Affine2d m(Eigen::Translation2d(x, y));
    if(e.view_box && e.view_box->width > 0 && e.view_box->height > 0 && w > 0 && h > 0)
      m = view_box_transform(*e.view_box, e.aspect, x, y, w, h);
    if(outermost && !recorded_) {
      recorded_ = true;
      out_.viewport_width = std::isnan(w) ? 0 : w;
      out_.viewport_height = std::isnan(h) ? 0 : h;
      out_.user_to_viewport = m;
    }
    if(w == 0 || h == 0) return false;
    if(e.view_box) {
      if(e.view_box->width == 0 || e.view_box->height == 0) return false;
      if(std::isnan(w) || std::isnan(h))
        in_.fail(e.view_box->at, "the viewBox of <" + e.name + "> needs the width and height of its viewport, "
                                 "which are percentages of a viewport whose size the document does not give");
      c.viewport_width = e.view_box->width;
      c.viewport_height = e.view_box->height;
    } else {
      c.viewport_width = w;
      c.viewport_height = h;
    }
    if(!m.matrix().isIdentity(0)) compose(c, m, e.view_box ? e.view_box->at : e.at, "the viewport's map");
    return true;
  }

  void draw_shape(const Element& e, const Context& c)
  {
    if(!c.visible) return;
    ++out_.shape_elements;
    const std::vector<Length>& l = e.lengths;
    auto optional = [&](const Length& length, Axis axis) -> std::optional<double> {
      if(length.kind == Length::absent) return std::nullopt;
      return resolve(length, axis, c, 0);
    };
    std::optional<Bezier_contour> outline;
    switch(e.kind) {
    case Element_kind::rect: {
      const double x = resolve(l[0], Axis::x, c, 0), y = resolve(l[1], Axis::y, c, 0);
      const double w = resolve(l[2], Axis::x, c, 0), h = resolve(l[3], Axis::y, c, 0);
      const std::optional<double> rx = optional(l[4], Axis::x), ry = optional(l[5], Axis::y);
      outline = rect_outline(x, y, w, h, rx, ry);
      break;
    }
    case Element_kind::circle: {
      const double cx = resolve(l[0], Axis::x, c, 0), cy = resolve(l[1], Axis::y, c, 0);
      const double r = resolve(l[2], Axis::diagonal, c, 0);
      outline = ellipse_outline(cx, cy, r, r);
      break;
    }
    case Element_kind::ellipse: { // SVG 2: one radius given (the other auto) serves for both
      const double cx = resolve(l[0], Axis::x, c, 0), cy = resolve(l[1], Axis::y, c, 0);
      const std::optional<double> rx = optional(l[2], Axis::x), ry = optional(l[3], Axis::y);
      outline = ellipse_outline(cx, cy, rx.value_or(ry.value_or(0)), ry.value_or(rx.value_or(0)));
      break;
    }
    case Element_kind::line: {
      const double x1 = resolve(l[0], Axis::x, c, 0), y1 = resolve(l[1], Axis::y, c, 0);
      const double x2 = resolve(l[2], Axis::x, c, 0), y2 = resolve(l[3], Axis::y, c, 0);
      outline = line_outline(x1, y1, x2, y2);
      break;
    }
    default: // <polyline>, <polygon>
      outline = polyline_outline(e.points, e.kind == Element_kind::polygon);
      break;
    }
    if(outline) emit(std::move(*outline), c, e.at, "the <" + e.name + ">'s coordinates in the viewport are");
  }

  const Located_text& in_;
  Svg_document& d_;
  Svg_paths& out_;
  std::size_t expansion_ = 0;
  bool recorded_ = false;
};

} // namespace

void render_svg(const Located_text& in, Svg_document& document, Svg_paths& out)
{
  Renderer(in, document, out).run();
}

} // namespace svg_internal
} // namespace Spline_approximation
} // namespace CGAL
