// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What Cairo draws over the surface: streamlines and fur strokes (hidden where the surface
// covers them), arrows and n-fold glyphs on a screen grid, the marks of singular vertices,
// the colour bar and text.

#include "field_renderer_impl.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace CGAL {
namespace Tangent_vector_fields {

using namespace internal::render;

namespace {

std::string format_number(double x)
{
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", x);
  return buffer;
}

} // namespace

void Field_renderer::Impl::draw_lines(cairo_t* cr, const Frame_buffers& fb, const Line_set& set) const
{
  const Line_style& st = set.style;
  const int bands = st.taper ? 4 : 1;
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for(int band = 0; band < bands; ++band)
  {
    cairo_new_path(cr);
    bool any = false;
    for(const Streamline& s : set.lines)
    {
      const double total = st.taper ? std::max(s.length(), 1e-300) : 1;
      double walked = 0;
      bool pen_down = false;
      for(std::size_t i = 0; i + 1 < s.points.size(); ++i)
      {
        const double length = std::sqrt(dot(sub(s.points[i + 1], s.points[i]), sub(s.points[i + 1], s.points[i])));
        const int f = s.faces[i];
        const auto a = to_samples(s.points[i]);
        const auto b = to_samples(s.points[i + 1]);
        const int pieces = std::max(1, static_cast<int>(std::ceil(std::hypot(b[0] - a[0], b[1] - a[1]))));
        for(int k = 0; k < pieces; ++k)
        {
          const double u0 = double(k) / pieces, u1 = double(k + 1) / pieces, um = (u0 + u1) / 2;
          const bool in_band =
              !st.taper || static_cast<int>((walked + um * length) / total * bands) == band ||
              (band == bands - 1 && (walked + um * length) / total >= 1);
          const double key = a[2] + um * (b[2] - a[2]);
          const bool show = in_band && visible(fb, a[0] + um * (b[0] - a[0]), a[1] + um * (b[1] - a[1]), key, f,
                                               depth_tolerance(f, key));
          if(!show)
          {
            pen_down = false;
            continue;
          }
          if(!pen_down) cairo_move_to(cr, (a[0] + u0 * (b[0] - a[0])) / ss, (a[1] + u0 * (b[1] - a[1])) / ss);
          cairo_line_to(cr, (a[0] + u1 * (b[0] - a[0])) / ss, (a[1] + u1 * (b[1] - a[1])) / ss);
          pen_down = true;
          any = true;
        }
        walked += length;
      }
    }
    if(!any) continue;
    const double fade = st.taper ? 1 - band / double(bands) : 1;
    cairo_set_line_width(cr, st.width * (st.taper ? 0.25 + 0.75 * fade : 1));
    set_colour(cr, st.colour, st.opacity * (st.taper ? 0.35 + 0.65 * fade : 1));
    cairo_stroke(cr);
  }
}

// The grid cells' centres (output pixels) where the surface is seen, with its face and point there.
std::vector<Glyph_site> Field_renderer::Impl::glyph_sites(const Frame_buffers& fb, double spacing) const
{
  const Intrinsic_mesh& M = *mesh;
  std::vector<Glyph_site> sites;
  for(double y = spacing / 2; y < options.height; y += spacing)
    for(double x = spacing / 2; x < options.width - legend_width(); x += spacing)
    {
      const int sx = static_cast<int>(x * ss), sy = static_cast<int>(y * ss);
      const std::size_t i = static_cast<std::size_t>(sy) * fb.w + sx;
      const int f = fb.face[i];
      if(f < 0) continue;
      const std::array<double, 3> w = barycentric(fb, i);
      const auto& t = M.face_vertices(f);
      V3 p{{0, 0, 0}};
      for(int k = 0; k < 3; ++k) p = add(p, scaled(M.position(t[k]), w[k]));
      sites.push_back({x, y, f, p});
    }
  return sites;
}

// The screen direction of the unit tangent vector (a, b) (frame coordinates of face f) at
// the surface point p, and its foreshortening; false if it points along the view.
bool Field_renderer::Impl::screen_direction(int f, const V3& p, double a, double b, Screen_direction& d) const
{
  const Intrinsic_mesh& M = *mesh;
  const V3 v = M.from_frame(f, a, b);
  const double h = 1e-3 * M.mean_edge_length();
  const auto pa = to_samples(p);
  const auto pb = to_samples(add(p, scaled(v, h)));
  const double dx = (pb[0] - pa[0]) / ss, dy = (pb[1] - pa[1]) / ss;
  const double screen = std::hypot(dx, dy);
  if(!(screen > 0)) return false;
  d.foreshortening = std::min(1., screen / (h * scale));
  d.ux = dx / screen;
  d.uy = dy / screen;
  return true;
}

// Arrows (symmetry 1) and n-fold glyphs share the grid, the scale and the screen
// directions; they differ only in the marks: a shaft with a head, or n spokes.
void Field_renderer::Impl::draw_glyphs(cairo_t* cr, const Frame_buffers& fb, const Arrow_set& set) const
{
  const Intrinsic_mesh& M = *mesh;
  const Arrow_style& st = set.style;
  const int n = st.symmetry;
  // Lengths relative to the 95th percentile of the magnitudes (longer arrows are
  // clamped): a few very strong faces would otherwise shrink all other arrows.
  std::vector<double> magnitudes(M.number_of_faces());
  for(int f = 0; f < M.number_of_faces(); ++f) magnitudes[f] = std::hypot(set.field[2 * f], set.field[2 * f + 1]);
  const std::size_t k = static_cast<std::size_t>(0.95 * (magnitudes.size() - 1));
  std::nth_element(magnitudes.begin(), magnitudes.begin() + k, magnitudes.end());
  double largest = magnitudes[k];
  if(!(largest > 0)) largest = *std::max_element(magnitudes.begin(), magnitudes.end());
  if(!(largest > 0)) return;
  const double spacing = std::max(st.spacing, 4.);
  cairo_new_path(cr);
  std::vector<std::array<double, 6>> heads;
  for(const Glyph_site& site : glyph_sites(fb, spacing))
  {
    const int f = site.face;
    const double x = site.x, y = site.y;
    const double magnitude = std::hypot(set.field[2 * f], set.field[2 * f + 1]);
    if(!(magnitude > 0)) continue;
    // The whole length of a mark along a direction with this foreshortening.
    const auto length_along = [&](double foreshortening) {
      return 0.85 * spacing * foreshortening * (st.scale_by_magnitude ? std::min(1., magnitude / largest) : 1);
    };
    Screen_direction d;
    if(n == 1)
    {
      if(!screen_direction(f, site.point, set.field[2 * f] / magnitude, set.field[2 * f + 1] / magnitude, d)) continue;
      const double length = length_along(d.foreshortening);
      if(length < 1.5) continue;
      const double ux = d.ux, uy = d.uy;
      const double x0 = x - ux * length / 2, y0 = y - uy * length / 2;
      const double x1 = x + ux * length / 2, y1 = y + uy * length / 2;
      const double head = std::min(0.35 * length, 3 + 2.5 * st.width);
      cairo_move_to(cr, x0, y0);
      cairo_line_to(cr, x1 - ux * head * 0.8, y1 - uy * head * 0.8);
      heads.push_back({x1, y1, x1 - ux * head - uy * head * 0.45, y1 - uy * head + ux * head * 0.45,
                       x1 - ux * head + uy * head * 0.45, y1 - uy * head - ux * head * 0.45});
      continue;
    }
    // The spokes start from the vector at an angle in [-pi/n, pi/n], so the glyph is the
    // same whichever of the n vectors the field holds.
    const double first = std::remainder(std::atan2(set.field[2 * f + 1], set.field[2 * f]), 2 * M_PI / n);
    for(int j = 0; j < n; ++j)
    {
      const double angle = first + 2 * M_PI * j / n;
      if(!screen_direction(f, site.point, std::cos(angle), std::sin(angle), d)) continue;
      const double length = length_along(d.foreshortening);
      if(length < 1.5) continue;
      // A spoke is half an arrow's length: the two spokes of a line field make a segment
      // as long as the arrow of the same vector, centred in the cell like it.
      cairo_move_to(cr, x, y);
      cairo_line_to(cr, x + d.ux * length / 2, y + d.uy * length / 2);
    }
  }
  set_colour(cr, st.colour, st.opacity);
  cairo_set_line_width(cr, st.width);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_stroke(cr);
  for(const auto& hd : heads)
  {
    cairo_move_to(cr, hd[0], hd[1]);
    cairo_line_to(cr, hd[2], hd[3]);
    cairo_line_to(cr, hd[4], hd[5]);
    cairo_close_path(cr);
  }
  cairo_fill(cr);
}

void Field_renderer::Impl::draw_singularities(cairo_t* cr, const Frame_buffers& fb, const Singularity_set& set) const
{
  const Singularity_style& st = set.style;
  const double font = std::max(10., 2.4 * st.radius);
  for(const auto& mark : set.marks)
  {
    const int v = mark[0], k = mark[1], f = mark[2];
    const auto q = to_samples(mesh->position(v));
    if(!visible(fb, q[0], q[1], q[2], f, depth_tolerance(f, q[2]))) continue;
    const double x = q[0] / ss, y = q[1] / ss;
    const double r = st.radius * std::sqrt(std::abs(k)); // area proportional to |k|
    const Colour& c = k > 0 ? st.positive : st.negative;
    cairo_new_path(cr);
    cairo_arc(cr, x, y, r, 0, 2 * M_PI);
    set_colour(cr, c, st.opacity);
    if(st.outline_width > 0)
    {
      cairo_fill_preserve(cr);
      set_colour(cr, st.outline, st.opacity);
      cairo_set_line_width(cr, st.outline_width);
      cairo_stroke(cr);
    }
    else
      cairo_fill(cr);
    if(!st.labels) continue;
    std::string label = (k > 0 ? "+" : "") + std::to_string(k);
    if(set.n > 1) label += "/" + std::to_string(set.n);
    set_colour(cr, c, st.opacity);
    draw_text(cr, label, x + r + 0.25 * font, y + 0.35 * font, font, 0, &st.outline, 2 * std::max(st.outline_width, 1.));
  }
}

// With a halo: the text outlined in that colour first, so that it reads on any surface.
void Field_renderer::Impl::draw_text(cairo_t* cr, const std::string& text, double x, double y, double size, double align,
                                     const Colour* halo, double halo_width) const
{
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  cairo_text_extents_t e;
  cairo_text_extents(cr, text.c_str(), &e);
  cairo_move_to(cr, x - align * (e.width + e.x_bearing), y);
  if(!halo)
  {
    cairo_show_text(cr, text.c_str());
    return;
  }
  cairo_pattern_t* fill = cairo_pattern_reference(cairo_get_source(cr));
  cairo_text_path(cr, text.c_str());
  set_colour(cr, *halo, 1);
  cairo_set_line_width(cr, halo_width);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_stroke_preserve(cr);
  cairo_set_source(cr, fill);
  cairo_fill(cr);
  cairo_pattern_destroy(fill);
}

Colour Field_renderer::Impl::text_colour() const
{
  const Colour& bg = options.background;
  const double luminance = 0.2126 * bg.r + 0.7152 * bg.g + 0.0722 * bg.b;
  return luminance > 0.5 ? Colour{0.1, 0.1, 0.1} : Colour{0.92, 0.92, 0.92};
}

void Field_renderer::Impl::draw_legend(cairo_t* cr) const
{
  const double font = std::max(11., options.height / 55.);
  const double bar_w = std::max(14., options.width / 70.);
  const double bar_h = 0.6 * options.height;
  const double x = options.width - legend_width() + 0.25 * legend_width();
  const double y = 0.2 * options.height;
  // A vertical gradient through 33 stops of the map (smooth in PNG, a vector gradient in SVG).
  cairo_pattern_t* gradient = cairo_pattern_create_linear(0, y + bar_h, 0, y);
  for(int k = 0; k <= 32; ++k)
  {
    const Colour c = colour_at(colouring.map, k / 32.0);
    cairo_pattern_add_color_stop_rgb(gradient, k / 32.0, c.r, c.g, c.b);
  }
  cairo_rectangle(cr, x, y, bar_w, bar_h);
  cairo_set_source(cr, gradient);
  cairo_fill(cr);
  cairo_pattern_destroy(gradient);
  const Colour tc = text_colour();
  set_colour(cr, tc, 1);
  cairo_set_line_width(cr, 1);
  cairo_rectangle(cr, x, y, bar_w, bar_h);
  cairo_stroke(cr);
  const double tx = x + bar_w + 0.4 * font;
  draw_text(cr, format_number(range_max), tx, y + 0.35 * font, font, 0);
  draw_text(cr, format_number(range_min), tx, y + bar_h + 0.35 * font, font, 0);
  if(range_min < 0 && range_max > 0 && colouring.symmetric)
    draw_text(cr, "0", tx, y + bar_h * range_max / (range_max - range_min) + 0.35 * font, font, 0);
  if(colouring.logarithmic) // the middle value tells the scale
    draw_text(cr, format_number(std::sqrt(range_min * range_max)), tx, y + bar_h / 2 + 0.35 * font, font, 0);
  if(!colouring.label.empty()) draw_text(cr, colouring.label, x + bar_w / 2, y - 0.9 * font, font, 0.5);
}

} // namespace Tangent_vector_fields
} // namespace CGAL
