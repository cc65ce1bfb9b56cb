// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A small software rasteriser (z-buffer, deferred shading, supersampling) for the
// surface, and Cairo for the lines, arrows, colour bar and the PNG/SVG files.

#include <CGAL/Tangent_vector_fields/Field_renderer.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

namespace CGAL {
namespace Tangent_vector_fields {

namespace {

typedef std::array<double, 3> V3;

V3 sub(const V3& a, const V3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
V3 add(const V3& a, const V3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
V3 scaled(const V3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
double dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V3 cross(const V3& a, const V3& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
V3 normalised(const V3& a)
{
  const double n = std::sqrt(dot(a, a));
  return n > 0 ? scaled(a, 1 / n) : a;
}

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

void set_colour(cairo_t* cr, const Colour& c, double alpha) { cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha); }

std::string format_number(double x)
{
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", x);
  return buffer;
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

struct Field_renderer::Impl
{
  std::shared_ptr<const Intrinsic_mesh> mesh;
  Render_options options;
  std::vector<double> values;
  bool per_vertex = false;
  Scalar_colouring colouring;
  double range_min = std::numeric_limits<double>::quiet_NaN(), range_max = range_min;
  std::vector<Line_set> line_sets;
  std::vector<Arrow_set> arrow_sets;
  std::vector<V3> vertex_normals;

  // Derived at render time.
  mutable Camera_frame camera;
  mutable double scale = 1, offset_x = 0, offset_y = 0, centre_x = 0, centre_y = 0; // framing (output pixels)
  mutable int ss = 1;

  explicit Impl(std::shared_ptr<const Intrinsic_mesh> m, const Render_options& o) : mesh(std::move(m)), options(o)
  {
    const Intrinsic_mesh& M = *mesh;
    vertex_normals.assign(M.number_of_vertices(), V3{{0, 0, 0}});
    for(int f = 0; f < M.number_of_faces(); ++f)
      for(int v : M.face_vertices(f)) vertex_normals[v] = add(vertex_normals[v], scaled(M.normal(f), M.face_area(f)));
    for(V3& n : vertex_normals) n = normalised(n);
  }

  bool has_legend() const { return options.legend && !values.empty(); }
  int legend_width() const { return has_legend() ? std::max(110, options.width / 9) : 0; }

  void set_values(std::vector<double> v, bool vertices, const Scalar_colouring& c)
  {
    const std::size_t n = vertices ? mesh->number_of_vertices() : mesh->number_of_faces();
    if(v.size() != n)
      throw Invalid_input(std::string("renderer: expected one value per ") + (vertices ? "vertex" : "face") + " (" +
                          std::to_string(n) + "), got " + std::to_string(v.size()));
    if(!(c.clip_fraction >= 0 && c.clip_fraction < 0.5))
      throw Invalid_input("renderer: clip_fraction must lie in [0, 0.5)");
    values = std::move(v);
    per_vertex = vertices;
    colouring = c;
    // The automatic range: quantiles of the finite values (of vertices in faces).
    std::vector<double> finite;
    for(std::size_t i = 0; i < values.size(); ++i)
      if(std::isfinite(values[i]) && !(vertices && mesh->is_isolated_vertex(static_cast<int>(i))))
        finite.push_back(values[i]);
    double lo = 0, hi = 1;
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
    if(!(hi > lo))
    {
      const double pad = std::max(std::abs(lo) * 1e-3, 1e-30);
      lo -= pad;
      hi += pad;
    }
    range_min = lo;
    range_max = hi;
  }

  Colour value_colour(double x) const
  {
    if(!std::isfinite(x)) return {0.5, 0.5, 0.5};
    return colour_at(colouring.map, (x - range_min) / (range_max - range_min));
  }

  void set_up_camera() const
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
  std::array<double, 3> to_samples(const V3& p) const
  {
    const auto q = camera.project(p);
    return {(offset_x + scale * (q[0] - centre_x)) * ss, (offset_y - scale * (q[1] - centre_y)) * ss, q[2]};
  }

  Frame_buffers rasterise() const
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
  std::array<double, 3> barycentric(const Frame_buffers& fb, std::size_t i) const
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
  Colour shade(const Frame_buffers& fb, std::size_t i) const
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
  cairo_surface_t* surface_image(const Frame_buffers& fb) const
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
  bool visible(const Frame_buffers& fb, double x, double y, double key, int face, double tolerance) const
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
  double depth_tolerance(int f, double key) const
  {
    const double world_per_sample = 1 / (scale * ss) * (camera.perspective ? camera.camera_depth(key) / camera.eye_distance : 1);
    const double slope = 1 / std::max(std::abs(dot(mesh->normal(f), camera.forward)), 0.15);
    const double tolerance = 2 * world_per_sample * slope;
    if(!camera.perspective) return tolerance;
    const double z = camera.camera_depth(key);
    return tolerance / (z * z);
  }

  void draw_lines(cairo_t* cr, const Frame_buffers& fb, const Line_set& set) const
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

  void draw_arrows(cairo_t* cr, const Frame_buffers& fb, const Arrow_set& set) const
  {
    const Intrinsic_mesh& M = *mesh;
    const Arrow_style& st = set.style;
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
        const double magnitude = std::hypot(set.field[2 * f], set.field[2 * f + 1]);
        if(!(magnitude > 0)) continue;
        const V3 v = M.from_frame(f, set.field[2 * f] / magnitude, set.field[2 * f + 1] / magnitude);
        // Screen direction and foreshortening of the unit vector v.
        const double h = 1e-3 * M.mean_edge_length();
        const auto a = to_samples(p);
        const auto b = to_samples(add(p, scaled(v, h)));
        const double dx = (b[0] - a[0]) / ss, dy = (b[1] - a[1]) / ss;
        const double screen = std::hypot(dx, dy);
        if(!(screen > 0)) continue;
        const double foreshortening = std::min(1., screen / (h * scale));
        const double length =
            0.85 * spacing * foreshortening * (st.scale_by_magnitude ? std::min(1., magnitude / largest) : 1);
        if(length < 1.5) continue;
        const double ux = dx / screen, uy = dy / screen;
        const double x0 = x - ux * length / 2, y0 = y - uy * length / 2;
        const double x1 = x + ux * length / 2, y1 = y + uy * length / 2;
        const double head = std::min(0.35 * length, 3 + 2.5 * st.width);
        cairo_move_to(cr, x0, y0);
        cairo_line_to(cr, x1 - ux * head * 0.8, y1 - uy * head * 0.8);
        heads.push_back({x1, y1, x1 - ux * head - uy * head * 0.45, y1 - uy * head + ux * head * 0.45,
                         x1 - ux * head + uy * head * 0.45, y1 - uy * head - ux * head * 0.45});
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

  void draw_text(cairo_t* cr, const std::string& text, double x, double y, double size, double align) const
  {
    cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, size);
    cairo_text_extents_t e;
    cairo_text_extents(cr, text.c_str(), &e);
    cairo_move_to(cr, x - align * (e.width + e.x_bearing), y);
    cairo_show_text(cr, text.c_str());
  }

  Colour text_colour() const
  {
    const Colour& bg = options.background;
    const double luminance = 0.2126 * bg.r + 0.7152 * bg.g + 0.0722 * bg.b;
    return luminance > 0.5 ? Colour{0.1, 0.1, 0.1} : Colour{0.92, 0.92, 0.92};
  }

  void draw_legend(cairo_t* cr) const
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
    if(!colouring.label.empty()) draw_text(cr, colouring.label, x + bar_w / 2, y - 0.9 * font, font, 0.5);
  }

  void compose(cairo_t* cr) const
  {
    ss = std::min(std::max(options.supersampling, 1), 4);
    set_up_camera();
    const Frame_buffers fb = rasterise();
    cairo_surface_t* image = surface_image(fb);
    cairo_set_source_surface(cr, image, 0, 0);
    cairo_paint(cr);
    cairo_surface_destroy(image);
    for(const Line_set& set : line_sets) draw_lines(cr, fb, set);
    for(const Arrow_set& set : arrow_sets) draw_arrows(cr, fb, set);
    if(has_legend()) draw_legend(cr);
    if(!options.title.empty())
    {
      set_colour(cr, text_colour(), 1);
      const double font = std::max(12., options.height / 40.);
      draw_text(cr, options.title, 0.6 * font, 1.4 * font, font, 0);
    }
  }

  void check_size() const
  {
    if(options.width < 16 || options.height < 16 || options.width > 16384 || options.height > 16384)
      throw Invalid_input("renderer: image size must be between 16 and 16384 pixels");
  }
};

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
  impl_->arrow_sets.push_back({field, style});
}

void Field_renderer::clear_overlays()
{
  impl_->line_sets.clear();
  impl_->arrow_sets.clear();
}

void Field_renderer::write_png(const std::string& filename) const
{
  impl_->check_size();
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
  impl_->check_size();
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
