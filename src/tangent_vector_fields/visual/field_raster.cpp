// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The surface: the camera and its framing, the z-buffer rasteriser, the shading and the
// test that tells whether a point of a line is hidden by the surface.

#include "field_renderer_impl.h"

#include <CGAL/Tangent_vector_fields/errors.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace CGAL {
namespace Tangent_vector_fields {

using namespace internal::render;

void Field_renderer::Impl::set_up_camera() const
{
  const Intrinsic_mesh& M = *mesh;
  const Camera& c = options.camera;
  V3 lo{{1e300, 1e300, 1e300}}, hi{{-1e300, -1e300, -1e300}};
  for(int v = 0; v < M.number_of_vertices(); ++v)
  {
    if(M.is_isolated_vertex(v)) continue;
    for(int i = 0; i < 3; ++i)
    {
      lo[i] = std::min(lo[i], M.position(v)[i]);
      hi[i] = std::max(hi[i], M.position(v)[i]);
    }
  }
  camera.centre = scaled(add(lo, hi), 0.5);
  const double radius = std::max(0.5 * std::sqrt(dot(sub(hi, lo), sub(hi, lo))), 1e-300);

  V3 up = normalised(c.up);
  if(!(dot(up, up) > 0.5)) throw Invalid_input("renderer: the camera's up vector is zero");
  V3 forward;
  if(dot(c.view_direction, c.view_direction) > 0)
    forward = normalised(c.view_direction);
  else
  {
    V3 front{{0, 0, 1}};
    for(const V3& axis : {V3{{0, 0, 1}}, V3{{1, 0, 0}}, V3{{0, 1, 0}}})
      if(std::abs(dot(axis, up)) < 0.9)
      {
        front = axis;
        break;
      }
    front = normalised(sub(front, scaled(up, dot(front, up))));
    const V3 side = cross(up, front);
    const double az = c.azimuth * M_PI / 180, el = c.elevation * M_PI / 180;
    const V3 eye = add(scaled(add(scaled(front, std::cos(az)), scaled(side, std::sin(az))), std::cos(el)),
                       scaled(up, std::sin(el)));
    forward = scaled(eye, -1);
  }
  V3 right = cross(forward, up);
  if(!(dot(right, right) > 1e-12)) // looking along the up vector
    right = cross(forward, std::abs(forward[0]) < 0.9 ? V3{{1, 0, 0}} : V3{{0, 1, 0}});
  camera.right = normalised(right);
  camera.forward = forward;
  camera.up = cross(camera.right, forward);
  camera.perspective = c.projection == Projection::perspective;
  const double half_angle = std::min(std::max(c.field_of_view, 1.), 150.) * M_PI / 360;
  camera.eye_distance = radius / std::sin(half_angle);

  // Framing: the projected vertices fill the image minus the margin and the legend.
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for(int v = 0; v < M.number_of_vertices(); ++v)
  {
    if(M.is_isolated_vertex(v)) continue;
    const auto p = camera.project(M.position(v));
    x0 = std::min(x0, p[0]);
    x1 = std::max(x1, p[0]);
    y0 = std::min(y0, p[1]);
    y1 = std::max(y1, p[1]);
  }
  const double usable_w = (options.width - legend_width()) * (1 - 2 * c.margin);
  const double usable_h = options.height * (1 - 2 * c.margin);
  const double extent = std::max({x1 - x0, y1 - y0, 1e-300 * radius});
  scale = c.zoom * std::min(usable_w / std::max(x1 - x0, 1e-12 * extent), usable_h / std::max(y1 - y0, 1e-12 * extent));
  centre_x = (x0 + x1) / 2;
  centre_y = (y0 + y1) / 2;
  offset_x = (options.width - legend_width()) / 2.0;
  offset_y = options.height / 2.0;
}

// Position in supersampled pixels, and depth key.
std::array<double, 3> Field_renderer::Impl::to_samples(const V3& p) const
{
  const auto q = camera.project(p);
  return {(offset_x + scale * (q[0] - centre_x)) * ss, (offset_y - scale * (q[1] - centre_y)) * ss, q[2]};
}

Frame_buffers Field_renderer::Impl::rasterise() const
{
  const Intrinsic_mesh& M = *mesh;
  Frame_buffers fb;
  fb.w = options.width * ss;
  fb.h = options.height * ss;
  const std::size_t n = static_cast<std::size_t>(fb.w) * fb.h;
  fb.key.assign(n, std::numeric_limits<float>::infinity());
  fb.face.assign(n, -1);
  fb.b1.assign(n, 0);
  fb.b2.assign(n, 0);
  std::vector<std::array<double, 3>> projected(M.number_of_vertices());
  for(int v = 0; v < M.number_of_vertices(); ++v)
    if(!M.is_isolated_vertex(v)) projected[v] = to_samples(M.position(v));
  for(int f = 0; f < M.number_of_faces(); ++f)
  {
    const auto& t = M.face_vertices(f);
    const auto& a = projected[t[0]];
    const auto& b = projected[t[1]];
    const auto& c = projected[t[2]];
    const double area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    if(!(std::abs(area) > 0)) continue;
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min({a[0], b[0], c[0]}) - 0.5)));
    const int x1 = std::min(fb.w - 1, static_cast<int>(std::ceil(std::max({a[0], b[0], c[0]}) - 0.5)));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min({a[1], b[1], c[1]}) - 0.5)));
    const int y1 = std::min(fb.h - 1, static_cast<int>(std::ceil(std::max({a[1], b[1], c[1]}) - 0.5)));
    const double inv = 1 / area;
    for(int y = y0; y <= y1; ++y)
    {
      const double py = y + 0.5;
      for(int x = x0; x <= x1; ++x)
      {
        const double px = x + 0.5;
        const double w1 = ((px - a[0]) * (c[1] - a[1]) - (py - a[1]) * (c[0] - a[0])) * inv;
        const double w2 = ((b[0] - a[0]) * (py - a[1]) - (b[1] - a[1]) * (px - a[0])) * inv;
        const double w0 = 1 - w1 - w2;
        if(w0 < 0 || w1 < 0 || w2 < 0) continue;
        const double key = w0 * a[2] + w1 * b[2] + w2 * c[2];
        const std::size_t i = static_cast<std::size_t>(y) * fb.w + x;
        if(key < fb.key[i])
        {
          fb.key[i] = static_cast<float>(key);
          fb.face[i] = f;
          fb.b1[i] = static_cast<float>(w1);
          fb.b2[i] = static_cast<float>(w2);
        }
      }
    }
  }
  return fb;
}

// Perspective-correct barycentric coordinates of a sample.
std::array<double, 3> Field_renderer::Impl::barycentric(const Frame_buffers& fb, std::size_t i) const
{
  std::array<double, 3> w = {1. - fb.b1[i] - fb.b2[i], fb.b1[i], fb.b2[i]};
  if(camera.perspective)
  {
    const auto& t = mesh->face_vertices(fb.face[i]);
    double s = 0;
    for(int k = 0; k < 3; ++k)
    {
      const double z = -1 / camera.project(mesh->position(t[k]))[2]; // camera depth of the corner
      w[k] /= z;
      s += w[k];
    }
    for(double& x : w) x /= s;
  }
  return w;
}

// Shaded colour of a covered sample.
Colour Field_renderer::Impl::shade(const Frame_buffers& fb, std::size_t i) const
{
  const Intrinsic_mesh& M = *mesh;
  const int f = fb.face[i];
  const auto& t = M.face_vertices(f);
  const std::array<double, 3> w = barycentric(fb, i);
  Colour base = options.surface;
  if(!values.empty())
    base = value_colour(per_vertex ? w[0] * values[t[0]] + w[1] * values[t[1]] + w[2] * values[t[2]] : values[f]);
  V3 n = M.normal(f);
  if(options.smooth_shading)
  {
    const V3 s = add(add(scaled(vertex_normals[t[0]], w[0]), scaled(vertex_normals[t[1]], w[1])),
                     scaled(vertex_normals[t[2]], w[2]));
    if(dot(s, n) > 0.2 * std::sqrt(dot(s, s))) n = normalised(s); // keep the face normal at creases
  }
  const V3 view = scaled(camera.forward, -1); // towards the camera
  if(dot(n, view) < 0) n = scaled(n, -1);      // two-sided
  const V3 key_light = normalised(add(add(scaled(camera.right, -0.45), scaled(camera.up, 0.65)), view));
  const double diffuse = 0.72 * std::max(0., dot(n, key_light)) + 0.28 * std::max(0., dot(n, view));
  const double light = options.ambient + (1 - options.ambient) * diffuse;
  const V3 half = normalised(add(key_light, view));
  const double highlight = options.specular * std::pow(std::max(0., dot(n, half)), 40);
  return {std::min(1., base.r * light + highlight), std::min(1., base.g * light + highlight),
          std::min(1., base.b * light + highlight)};
}

// The surface image at output resolution (ARGB32, opaque), averaged over the samples.
cairo_surface_t* Field_renderer::Impl::surface_image(const Frame_buffers& fb) const
{
  cairo_surface_t* image = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, options.width, options.height);
  if(cairo_surface_status(image) != CAIRO_STATUS_SUCCESS)
    throw Invalid_input("renderer: cannot create an image of " + std::to_string(options.width) + " x " +
                        std::to_string(options.height));
  cairo_surface_flush(image);
  unsigned char* data = cairo_image_surface_get_data(image);
  const int stride = cairo_image_surface_get_stride(image);
  const Colour& bg = options.background;
  const double samples = ss * ss;
  for(int y = 0; y < options.height; ++y)
  {
    std::uint32_t* row = reinterpret_cast<std::uint32_t*>(data + static_cast<std::size_t>(y) * stride);
    for(int x = 0; x < options.width; ++x)
    {
      double r = 0, g = 0, b = 0;
      for(int sy = 0; sy < ss; ++sy)
        for(int sx = 0; sx < ss; ++sx)
        {
          const std::size_t i = static_cast<std::size_t>(y * ss + sy) * fb.w + (x * ss + sx);
          const Colour c = fb.face[i] >= 0 ? shade(fb, i) : bg;
          r += c.r;
          g += c.g;
          b += c.b;
        }
      auto byte = [&](double v) { return static_cast<std::uint32_t>(std::lround(std::min(std::max(v / samples, 0.), 1.) * 255)); };
      row[x] = 0xff000000u | (byte(r) << 16) | (byte(g) << 8) | byte(b);
    }
  }
  cairo_surface_mark_dirty(image);
  return image;
}

// True if the surface seen at (x, y) (samples) is at depth `key` there: the sample
// or one of its 8 neighbours shows the same face, a face sharing a vertex with it,
// or a surface within the depth tolerance.
bool Field_renderer::Impl::visible(const Frame_buffers& fb, double x, double y, double key, int face, double tolerance) const
{
  const int cx = static_cast<int>(std::floor(x)), cy = static_cast<int>(std::floor(y));
  const auto& corners = mesh->face_vertices(face);
  for(int dy = -1; dy <= 1; ++dy)
    for(int dx = -1; dx <= 1; ++dx)
    {
      const int px = cx + dx, py = cy + dy;
      if(px < 0 || py < 0 || px >= fb.w || py >= fb.h) continue;
      const std::size_t i = static_cast<std::size_t>(py) * fb.w + px;
      const int g = fb.face[i];
      if(g < 0) continue;
      if(key <= fb.key[i] + tolerance) return true;
      for(int u : mesh->face_vertices(g))
        if(u == corners[0] || u == corners[1] || u == corners[2]) return true;
    }
  return false;
}

// Depth tolerance for a point on face `f` with depth key `key`: two samples' worth
// of depth at the face's slope (at most 1/0.15 of a sample's size).
double Field_renderer::Impl::depth_tolerance(int f, double key) const
{
  const double world_per_sample = 1 / (scale * ss) * (camera.perspective ? camera.camera_depth(key) / camera.eye_distance : 1);
  const double slope = 1 / std::max(std::abs(dot(mesh->normal(f), camera.forward)), 0.15);
  const double tolerance = 2 * world_per_sample * slope;
  if(!camera.perspective) return tolerance;
  const double z = camera.camera_depth(key);
  return tolerance / (z * z);
}

} // namespace Tangent_vector_fields
} // namespace CGAL
