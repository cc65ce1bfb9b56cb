// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The renderer's state and its parts (private to src/visual): the camera, the z-buffer and
// the overlays to draw.  field_renderer.cpp holds the public class, the colour maps and the
// composition of a picture; field_raster.cpp the camera, the rasteriser, the shading and the
// visibility test; field_overlays.cpp what Cairo draws on top (lines, arrows and glyphs, singularities, legend,
// text).

#ifndef CGAL_TANGENT_VECTOR_FIELDS_SRC_VISUAL_FIELD_RENDERER_IMPL_H
#define CGAL_TANGENT_VECTOR_FIELDS_SRC_VISUAL_FIELD_RENDERER_IMPL_H

#include <CGAL/Tangent_vector_fields/Field_renderer.h>

#include <cairo.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {
namespace internal {
namespace render {

typedef std::array<double, 3> V3;

inline V3 sub(const V3& a, const V3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline V3 add(const V3& a, const V3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline V3 scaled(const V3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
inline double dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline V3 cross(const V3& a, const V3& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline V3 normalised(const V3& a)
{
  const double n = std::sqrt(dot(a, a));
  return n > 0 ? scaled(a, 1 / n) : a;
}

struct Camera_frame
{
  V3 centre, right, up, forward; // forward: from the camera into the scene
  bool perspective = false;
  double eye_distance = 0;
  // Screen position (before framing) and depth key of a point: smaller key = nearer.
  std::array<double, 3> project(const V3& p) const
  {
    const V3 d = sub(p, centre);
    const double x = dot(d, right), y = dot(d, up), z = dot(d, forward);
    if(!perspective) return {x, y, z};
    const double zc = std::max(eye_distance + z, 1e-9 * eye_distance);
    return {x * eye_distance / zc, y * eye_distance / zc, -1 / zc};
  }
  // Distance from the eye along the view axis (perspective) for a depth key.
  double camera_depth(double key) const { return perspective ? -1 / key : 0; }
};

struct Frame_buffers
{
  int w = 0, h = 0; // supersampled size
  std::vector<float> key;
  std::vector<int> face;
  std::vector<float> b1, b2; // screen-space barycentric coordinates of corners 1 and 2
};

struct Line_set
{
  std::vector<Streamline> lines;
  Line_style style;
};

struct Arrow_set
{
  Eigen::VectorXd field;
  Arrow_style style;
};

// Marks of singular vertices: (vertex, k, a face around the vertex) each.
struct Singularity_set
{
  std::vector<std::array<int, 3>> marks;
  int n = 1;
  Singularity_style style;
};

// A cell of the arrows' screen grid where the surface is seen: its centre (output pixels),
// the face and the surface point there.
struct Glyph_site
{
  double x, y;
  int face;
  V3 point;
};

// A tangent direction on the screen: unit direction (output pixels, y down) and
// foreshortening (1 parallel to the screen, towards 0 along the view).
struct Screen_direction
{
  double ux = 0, uy = 0, foreshortening = 0;
};

inline void set_colour(cairo_t* cr, const Colour& c, double alpha) { cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha); }

} // namespace render
} // namespace internal

struct Field_renderer::Impl
{
  typedef internal::render::V3 V3;
  typedef internal::render::Camera_frame Camera_frame;
  typedef internal::render::Frame_buffers Frame_buffers;
  typedef internal::render::Line_set Line_set;
  typedef internal::render::Arrow_set Arrow_set;
  typedef internal::render::Singularity_set Singularity_set;
  typedef internal::render::Glyph_site Glyph_site;
  typedef internal::render::Screen_direction Screen_direction;

  std::shared_ptr<const Intrinsic_mesh> mesh;
  Render_options options;
  std::vector<double> values;
  bool per_vertex = false;
  Scalar_colouring colouring;
  double range_min = std::numeric_limits<double>::quiet_NaN(), range_max = range_min;
  std::vector<Line_set> line_sets;
  std::vector<Arrow_set> arrow_sets;
  std::vector<Singularity_set> singularity_sets;
  std::vector<V3> vertex_normals;

  // Derived at render time.
  mutable Camera_frame camera;
  mutable double scale = 1, offset_x = 0, offset_y = 0, centre_x = 0, centre_y = 0; // framing (output pixels)
  mutable int ss = 1;

  explicit Impl(std::shared_ptr<const Intrinsic_mesh> m, const Render_options& o);

  bool has_legend() const { return options.legend && !values.empty(); }
  int legend_width() const { return has_legend() ? std::max(110, options.width / 9) : 0; }

  // field_renderer.cpp
  void set_values(std::vector<double> v, bool vertices, const Scalar_colouring& c);
  Colour value_colour(double x) const;
  void compose(cairo_t* cr) const;
  void check_options() const; // image size, sampling, camera: before any drawing

  // field_raster.cpp
  void set_up_camera() const;
  std::array<double, 3> to_samples(const V3& p) const;
  Frame_buffers rasterise() const;
  std::array<double, 3> barycentric(const Frame_buffers& fb, std::size_t i) const;
  Colour shade(const Frame_buffers& fb, std::size_t i) const;
  cairo_surface_t* surface_image(const Frame_buffers& fb) const;
  bool visible(const Frame_buffers& fb, double x, double y, double key, int face, double tolerance) const;
  double depth_tolerance(int f, double key) const;

  // field_overlays.cpp
  void draw_lines(cairo_t* cr, const Frame_buffers& fb, const Line_set& set) const;
  std::vector<Glyph_site> glyph_sites(const Frame_buffers& fb, double spacing) const;
  bool screen_direction(int f, const V3& p, double a, double b, Screen_direction& d) const;
  void draw_glyphs(cairo_t* cr, const Frame_buffers& fb, const Arrow_set& set) const;
  void draw_singularities(cairo_t* cr, const Frame_buffers& fb, const Singularity_set& set) const;
  void draw_text(cairo_t* cr, const std::string& text, double x, double y, double size, double align,
                 const Colour* halo = nullptr, double halo_width = 0) const;
  Colour text_colour() const;
  void draw_legend(cairo_t* cr) const;
};

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
