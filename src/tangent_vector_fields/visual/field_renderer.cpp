// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A small software rasteriser (z-buffer, deferred shading, supersampling) for the
// surface, and Cairo for the lines, arrows, colour bar and the PNG/SVG files.  This file:
// the public class, the colour maps and the composition of a picture.

#include "field_renderer_impl.h"

#include <CGAL/Tangent_vector_fields/errors.h>

#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace Tangent_vector_fields {

using namespace internal::render;

namespace {

// Stops of the colour maps (sRGB, 0..255), interpolated linearly.
const unsigned char viridis_stops[][3] = {{68, 1, 84},    {72, 40, 120},  {62, 74, 137},  {49, 104, 142},
                                          {38, 130, 142}, {31, 158, 137}, {53, 183, 121}, {109, 205, 89},
                                          {180, 222, 44}, {253, 231, 37}};
const unsigned char cool_warm_stops[][3] = {{59, 76, 192},   {98, 130, 234},  {141, 176, 254},
                                            {184, 208, 249}, {221, 221, 221}, {245, 196, 173},
                                            {244, 154, 123}, {222, 96, 77},   {180, 4, 38}};

template <std::size_t N>
Colour interpolate(const unsigned char (&stops)[N][3], double t)
{
  const double x = std::min(std::max(t, 0.), 1.) * (N - 1);
  const std::size_t i = std::min(static_cast<std::size_t>(x), N - 2);
  const double u = x - i;
  return {((1 - u) * stops[i][0] + u * stops[i + 1][0]) / 255, ((1 - u) * stops[i][1] + u * stops[i + 1][1]) / 255,
          ((1 - u) * stops[i][2] + u * stops[i + 1][2]) / 255};
}

} // namespace

Colour colour_at(Colour_map map, double t)
{
  switch(map)
  {
  case Colour_map::viridis: return interpolate(viridis_stops, t);
  case Colour_map::cool_warm: return interpolate(cool_warm_stops, t);
  case Colour_map::greys:
  {
    const double g = 0.12 + 0.83 * std::min(std::max(t, 0.), 1.);
    return {g, g, g};
  }
  }
  return {0, 0, 0};
}

Field_renderer::Impl::Impl(std::shared_ptr<const Intrinsic_mesh> m, const Render_options& o)
  : mesh(std::move(m)), options(o)
{
  const Intrinsic_mesh& M = *mesh;
  vertex_normals.assign(M.number_of_vertices(), V3{{0, 0, 0}});
  for(int f = 0; f < M.number_of_faces(); ++f)
    for(int v : M.face_vertices(f)) vertex_normals[v] = add(vertex_normals[v], scaled(M.normal(f), M.face_area(f)));
  for(V3& n : vertex_normals) n = normalised(n);
}

void Field_renderer::Impl::set_values(std::vector<double> v, bool vertices, const Scalar_colouring& c)
{
  const std::size_t n = vertices ? mesh->number_of_vertices() : mesh->number_of_faces();
  if(v.size() != n)
    throw Invalid_input(std::string("renderer: expected one value per ") + (vertices ? "vertex" : "face") + " (" +
                        std::to_string(n) + "), got " + std::to_string(v.size()));
  if(!(c.clip_fraction >= 0 && c.clip_fraction < 0.5))
    throw Invalid_input("renderer: clip_fraction must lie in [0, 0.5)");
  if(c.logarithmic && c.symmetric) throw Invalid_input("renderer: a logarithmic colour scale cannot be symmetric");
  if(c.logarithmic && (c.minimum <= 0 || c.maximum <= 0))
    throw Invalid_input("renderer: the range of a logarithmic colour scale must be positive");
  values = std::move(v);
  per_vertex = vertices;
  colouring = c;
  // The automatic range: quantiles of the finite values (of vertices in faces; positive
  // ones on a logarithmic scale).
  std::vector<double> finite;
  for(std::size_t i = 0; i < values.size(); ++i)
    if(std::isfinite(values[i]) && !(vertices && mesh->is_isolated_vertex(static_cast<int>(i))) &&
       !(c.logarithmic && !(values[i] > 0)))
      finite.push_back(values[i]);
  double lo = c.logarithmic ? 1 : 0, hi = c.logarithmic ? 10 : 1;
  if(!finite.empty())
  {
    std::sort(finite.begin(), finite.end());
    const std::size_t k = static_cast<std::size_t>(c.clip_fraction * (finite.size() - 1));
    lo = finite[k];
    hi = finite[finite.size() - 1 - k];
  }
  if(c.symmetric)
  {
    const double m = std::max(std::abs(lo), std::abs(hi));
    lo = -m;
    hi = m;
  }
  if(std::isfinite(c.minimum)) lo = c.minimum;
  if(std::isfinite(c.maximum)) hi = c.maximum;
  // A range within rounding of one value (the magnitudes of a unit field) would show the
  // rounding errors as colours: it is widened about the value as if it were constant.
  const bool constant = !(hi - lo > 1e-9 * std::max(std::abs(lo), std::abs(hi)));
  if(constant && c.logarithmic)
  {
    const double a = std::min(lo, hi), b = std::max(lo, hi);
    lo = a / (1 + 1e-3);
    hi = b * (1 + 1e-3);
  }
  else if(constant)
  {
    const double pad = std::max(std::abs(lo) * 1e-3, 1e-30);
    lo -= pad;
    hi += pad;
  }
  range_min = lo;
  range_max = hi;
}

Colour Field_renderer::Impl::value_colour(double x) const
{
  if(!std::isfinite(x)) return {0.5, 0.5, 0.5};
  if(colouring.logarithmic) // values <= 0 take the bottom colour
    return colour_at(colouring.map, x > 0 ? std::log(x / range_min) / std::log(range_max / range_min) : 0);
  return colour_at(colouring.map, (x - range_min) / (range_max - range_min));
}

void Field_renderer::Impl::compose(cairo_t* cr) const
{
  ss = std::min(std::max(options.supersampling, 1), 4);
  set_up_camera();
  const Frame_buffers fb = rasterise();
  cairo_surface_t* image = surface_image(fb);
  cairo_set_source_surface(cr, image, 0, 0);
  cairo_paint(cr);
  cairo_surface_destroy(image);
  for(const Line_set& set : line_sets) draw_lines(cr, fb, set);
  for(const Arrow_set& set : arrow_sets) draw_glyphs(cr, fb, set);
  for(const Singularity_set& set : singularity_sets) draw_singularities(cr, fb, set);
  if(has_legend()) draw_legend(cr);
  if(!options.title.empty())
  {
    set_colour(cr, text_colour(), 1);
    const double font = std::max(12., options.height / 40.);
    draw_text(cr, options.title, 0.6 * font, 1.4 * font, font, 0);
  }
}

void Field_renderer::Impl::check_options() const
{
  if(options.width < 16 || options.height < 16 || options.width > 16384 || options.height > 16384)
    throw Invalid_input("renderer: image size must be between 16 and 16384 pixels");
  if(options.supersampling < 1 || options.supersampling > 4)
    throw Invalid_input("renderer: supersampling must be 1 to 4 (got " + std::to_string(options.supersampling) + ")");
  // A NaN or infinite camera setting makes every projected point NaN: an empty picture, or
  // pixel coordinates that no integer holds.
  const Camera& c = options.camera;
  bool finite = std::isfinite(c.azimuth) && std::isfinite(c.elevation) && std::isfinite(c.field_of_view) &&
                std::isfinite(options.ambient) && std::isfinite(options.specular);
  for(int i = 0; i < 3; ++i) finite = finite && std::isfinite(c.view_direction[i]) && std::isfinite(c.up[i]);
  if(!finite) throw Invalid_input("renderer: the camera and lighting settings must be finite numbers");
  if(!(c.zoom > 0) || !std::isfinite(c.zoom)) throw Invalid_input("renderer: the zoom must be positive and finite");
  if(!(c.margin >= 0 && c.margin < 0.5)) throw Invalid_input("renderer: the margin must lie in [0, 0.5)");
}

Field_renderer::Field_renderer(std::shared_ptr<const Intrinsic_mesh> mesh, const Render_options& options)
  : impl_(std::make_unique<Impl>(std::move(mesh), options))
{}
Field_renderer::~Field_renderer() = default;
Field_renderer::Field_renderer(Field_renderer&&) noexcept = default;
Field_renderer& Field_renderer::operator=(Field_renderer&&) noexcept = default;

const Intrinsic_mesh& Field_renderer::mesh() const { return *impl_->mesh; }
Render_options& Field_renderer::options() { return impl_->options; }
const Render_options& Field_renderer::options() const { return impl_->options; }

void Field_renderer::colour_faces(std::vector<double> values, const Scalar_colouring& colouring)
{
  impl_->set_values(std::move(values), false, colouring);
}

void Field_renderer::colour_vertices(std::vector<double> values, const Scalar_colouring& colouring)
{
  impl_->set_values(std::move(values), true, colouring);
}

void Field_renderer::clear_colours()
{
  impl_->values.clear();
  impl_->range_min = impl_->range_max = std::numeric_limits<double>::quiet_NaN();
}

std::pair<double, double> Field_renderer::colour_range() const { return {impl_->range_min, impl_->range_max}; }

void Field_renderer::add_streamlines(std::vector<Streamline> lines, const Line_style& style)
{
  for(const Streamline& s : lines)
  {
    if(s.faces.size() != s.points.size()) throw Invalid_input("renderer: a streamline needs one face per point");
    for(int f : s.faces)
      if(f < 0 || f >= impl_->mesh->number_of_faces()) throw Invalid_input("renderer: a streamline has a bad face index");
  }
  impl_->line_sets.push_back({std::move(lines), style});
}

void Field_renderer::add_arrows(const Eigen::VectorXd& field, const Arrow_style& style)
{
  if(field.size() != 2 * static_cast<Eigen::Index>(impl_->mesh->number_of_faces()))
    throw Invalid_input("renderer: the field needs 2 frame coordinates per face");
  if(!field.allFinite()) throw Invalid_input("renderer: the field has non-finite entries");
  if(style.symmetry < 1)
    throw Invalid_input("renderer: the symmetry of glyphs must be at least 1, not " + std::to_string(style.symmetry));
  impl_->arrow_sets.push_back({field, style});
}

void Field_renderer::add_glyphs(const Eigen::VectorXd& vectors, int n, Arrow_style style)
{
  style.symmetry = n;
  add_arrows(vectors, style);
}

void Field_renderer::add_singularities(const std::vector<std::pair<int, int>>& vertex_k, int n,
                                       const Singularity_style& style)
{
  const Intrinsic_mesh& M = *impl_->mesh;
  if(n < 1) throw Invalid_input("renderer: the symmetry of singularities must be at least 1, not " + std::to_string(n));
  if(!(style.radius > 0) || !std::isfinite(style.radius))
    throw Invalid_input("renderer: the radius of singularity marks must be positive");
  // A face around each vertex: the visibility test takes the samples of the faces around it.
  std::vector<int> face_of(M.number_of_vertices(), -1);
  for(int f = M.number_of_faces() - 1; f >= 0; --f)
    for(int v : M.face_vertices(f)) face_of[v] = f;
  Singularity_set set;
  set.n = n;
  set.style = style;
  for(const auto& vk : vertex_k)
  {
    const int v = vk.first;
    if(v < 0 || v >= M.number_of_vertices())
      throw Invalid_input("renderer: singular vertex " + std::to_string(v) + " is not a vertex of the mesh (0 to " +
                          std::to_string(M.number_of_vertices() - 1) + ")");
    if(face_of[v] < 0) throw Invalid_input("renderer: singular vertex " + std::to_string(v) + " lies in no face");
    if(vk.second != 0) set.marks.push_back({v, vk.second, face_of[v]});
  }
  impl_->singularity_sets.push_back(std::move(set));
}

void Field_renderer::clear_overlays()
{
  impl_->line_sets.clear();
  impl_->arrow_sets.clear();
  impl_->singularity_sets.clear();
}

void Field_renderer::write_png(const std::string& filename) const
{
  impl_->check_options();
  cairo_surface_t* target = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, impl_->options.width, impl_->options.height);
  cairo_t* cr = cairo_create(target);
  try
  {
    impl_->compose(cr);
  }
  catch(...)
  {
    cairo_destroy(cr);
    cairo_surface_destroy(target);
    throw;
  }
  cairo_destroy(cr);
  const cairo_status_t status = cairo_surface_write_to_png(target, filename.c_str());
  cairo_surface_destroy(target);
  if(status != CAIRO_STATUS_SUCCESS)
    throw Invalid_input("cannot write '" + filename + "': " + cairo_status_to_string(status));
}

void Field_renderer::write_svg(const std::string& filename) const
{
  impl_->check_options();
  cairo_surface_t* target = cairo_svg_surface_create(filename.c_str(), impl_->options.width, impl_->options.height);
  if(cairo_surface_status(target) != CAIRO_STATUS_SUCCESS)
  {
    cairo_surface_destroy(target);
    throw Invalid_input("cannot write '" + filename + "'");
  }
  cairo_t* cr = cairo_create(target);
  try
  {
    impl_->compose(cr);
  }
  catch(...)
  {
    cairo_destroy(cr);
    cairo_surface_destroy(target);
    throw;
  }
  cairo_destroy(cr);
  cairo_surface_finish(target);
  const cairo_status_t status = cairo_surface_status(target);
  cairo_surface_destroy(target);
  if(status != CAIRO_STATUS_SUCCESS)
    throw Invalid_input("cannot write '" + filename + "': " + cairo_status_to_string(status));
}


} // namespace Tangent_vector_fields
} // namespace CGAL
