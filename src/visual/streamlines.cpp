// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Exact streamlines of piecewise-constant fields: a walk from face to face in
// barycentric coordinates of each face's 2D layout, evenly spaced seeding with a
// uniform grid of samples, and fur strokes.

#include <CGAL/Tangent_vector_fields/Streamline_tracer.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <random>
#include <string>
#include <unordered_map>
#include <utility>

namespace CGAL {
namespace Tangent_vector_fields {

namespace {

typedef std::array<double, 2> V2;
typedef std::array<double, 3> V3;
typedef std::array<double, 3> Barycentric;

const double infinity = std::numeric_limits<double>::infinity();
// A barycentric coordinate at most this small at the end of a segment puts the point on the vertex.
const double vertex_snap = 1e-12;
// This many consecutive segments shorter than 1e-12 mean edge lengths: the trace has stalled.
const int stalled_count = 64;

double dot2(const V2& a, const V2& b) { return a[0] * b[0] + a[1] * b[1]; }
double cross2(const V2& a, const V2& b) { return a[0] * b[1] - a[1] * b[0]; }
double dot3(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V3 sub3(const V3& a, const V3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double distance3(const V3& a, const V3& b) { return std::sqrt(dot3(sub3(a, b), sub3(a, b))); }

// Clamps to non-negative and normalises to sum 1.
Barycentric normalised(Barycentric b)
{
  double s = 0;
  for(double& x : b)
  {
    x = std::max(x, 0.);
    s += x;
  }
  if(!(s > 0)) return {1. / 3, 1. / 3, 1. / 3};
  for(double& x : b) x /= s;
  return b;
}

// Where a walk is: a face, barycentric coordinates in it, and whether the point is
// on the edge it came through (local index) or on a vertex (local corner).
struct Position
{
  int face = -1;
  Barycentric beta{{1. / 3, 1. / 3, 1. / 3}};
  int entered_edge = -1; // local edge of `face` the walk entered through
  int corner = -1;       // local corner of `face` the point sits on
  V3 point{{0, 0, 0}};
};

// One straight piece of a walk, for seeding beside accepted streamlines.
struct Segment_record
{
  int face;
  Barycentric start, end;
  double length;
};

struct Walk_settings
{
  double sign = 1;       // +1 along the field, -1 against it
  bool rotated = false;  // follow J v instead of v (walking across the streamlines)
  double maximum_length = infinity;
  int maximum_segments = 100000;
  double zero_threshold = 0;
  // Loop closure (forward walks from a seed).
  bool check_closure = false;
  int seed_face = -1;
  V2 seed_layout{{0, 0}};
  double closure_tolerance = 0;
  bool keep_segments = false;
};

struct Walk
{
  std::vector<V3> points; // starts with the start point
  std::vector<int> faces; // one per segment
  std::vector<Segment_record> segments;
  Streamline_stop stop = Streamline_stop::none;
  Position end;
  double length = 0;
};

// No proximity test: samples are never taken.
struct No_proximity
{
  double step() const { return infinity; }
  bool too_close(const V3&, double) { return false; }
  bool near(const V3&, double) const { return false; }
  void record(const V3&, double) {}
};

// Uniform grid of sample points of streamlines, keyed by cell.
class Sample_grid
{
public:
  struct Sample
  {
    V3 point;
    int line;
    double arc; // signed arc length from the seed of its line
  };

  Sample_grid(double cell, const V3& origin) : cell_(cell), origin_(origin) {}

  void insert(const V3& p, int line, double arc)
  {
    const std::uint64_t key = key_of(cell_of(p));
    cells_[key].push_back(static_cast<int>(samples_.size()));
    samples_.push_back({p, line, arc});
    keys_.push_back(key);
  }

  // Removes the samples of `line`, which must be the last ones inserted.
  void remove_line(int line)
  {
    while(!samples_.empty() && samples_.back().line == line)
    {
      std::vector<int>& c = cells_[keys_.back()];
      c.pop_back();
      samples_.pop_back();
      keys_.pop_back();
    }
  }

  // True if a sample accepted by `counts` lies closer than `radius` (at most one cell) to `p`.
  template <class Predicate>
  bool any_within(const V3& p, double radius, const Predicate& counts) const
  {
    const std::array<long, 3> c = cell_of(p);
    const double r2 = radius * radius;
    for(long i = c[0] - 1; i <= c[0] + 1; ++i)
      for(long j = c[1] - 1; j <= c[1] + 1; ++j)
        for(long k = c[2] - 1; k <= c[2] + 1; ++k)
        {
          const auto it = cells_.find(key_of({i, j, k}));
          if(it == cells_.end()) continue;
          for(int s : it->second)
          {
            const Sample& q = samples_[s];
            const V3 d = sub3(q.point, p);
            if(dot3(d, d) < r2 && counts(q)) return true;
          }
        }
    return false;
  }

private:
  std::array<long, 3> cell_of(const V3& p) const
  {
    return {static_cast<long>(std::floor((p[0] - origin_[0]) / cell_)),
            static_cast<long>(std::floor((p[1] - origin_[1]) / cell_)),
            static_cast<long>(std::floor((p[2] - origin_[2]) / cell_))};
  }
  static std::uint64_t key_of(const std::array<long, 3>& c)
  {
    const std::uint64_t m = (1u << 21) - 1;
    return ((static_cast<std::uint64_t>(c[0]) & m) << 42) | ((static_cast<std::uint64_t>(c[1]) & m) << 21) |
           (static_cast<std::uint64_t>(c[2]) & m);
  }

  double cell_;
  V3 origin_;
  std::unordered_map<std::uint64_t, std::vector<int>> cells_;
  std::vector<Sample> samples_;
  std::vector<std::uint64_t> keys_;
};

// The proximity test of the streamline being traced in evenly spaced seeding.
struct Separation_test
{
  Sample_grid* grid;
  int line;
  double sign;     // +1 forward (arcs >= 0), -1 backward
  double test_distance;
  double self_gap; // own samples closer than this in arc length are its own neighbourhood
  double sample_step;

  double step() const { return sample_step; }
  // True if `p`, reached after `walked`, is too close to another streamline or to a
  // distant part of this one.
  bool near(const V3& p, double walked) const
  {
    const double arc = sign * walked;
    const bool forward = sign > 0;
    return grid->any_within(p, test_distance, [&](const Sample_grid::Sample& s) {
      if(s.line != line) return true;
      if(std::abs(s.arc - arc) < self_gap) return false;
      // While the forward part runs, its first samples are left to the loop-closure test.
      if(forward && s.arc >= 0 && s.arc < self_gap) return false;
      return true;
    });
  }
  void record(const V3& p, double walked) { grid->insert(p, line, sign * walked); }
  // The test at a sample; a sample that passes is recorded.
  bool too_close(const V3& p, double walked)
  {
    if(near(p, walked)) return true;
    grid->insert(p, line, sign * walked);
    return false;
  }
};

} // namespace

const char* to_string(Streamline_stop stop)
{
  switch(stop)
  {
  case Streamline_stop::none: return "none";
  case Streamline_stop::boundary: return "boundary";
  case Streamline_stop::zero_field: return "zero_field";
  case Streamline_stop::sink_edge: return "sink_edge";
  case Streamline_stop::sink_vertex: return "sink_vertex";
  case Streamline_stop::maximum_length: return "maximum_length";
  case Streamline_stop::maximum_segments: return "maximum_segments";
  case Streamline_stop::closed_loop: return "closed_loop";
  case Streamline_stop::too_close: return "too_close";
  case Streamline_stop::stalled: return "stalled";
  }
  return "unknown";
}

double Streamline::length() const
{
  double l = 0;
  for(std::size_t i = 1; i < points.size(); ++i) l += distance3(points[i - 1], points[i]);
  return l;
}

struct Streamline_tracer::Impl
{
  struct Face_data
  {
    std::array<V2, 3> corner; // the 2D layout
    std::array<V2, 3> gradient; // gradients of the barycentric coordinates
    V2 direction;               // the field (frame coordinates = layout coordinates)
    double magnitude;
  };

  std::shared_ptr<const Intrinsic_mesh> mesh;
  std::vector<Face_data> faces;
  std::vector<int> vertex_face_start, vertex_faces; // faces around each vertex (CSR)
  std::vector<char> boundary_vertex;
  double maximum_magnitude = 0;
  double diagonal = 0;
  V3 box_min{{0, 0, 0}};
  double total_area = 0;

  Impl(std::shared_ptr<const Intrinsic_mesh> m, const Eigen::VectorXd& field) : mesh(std::move(m))
  {
    const Intrinsic_mesh& M = *mesh;
    const int nf = M.number_of_faces();
    if(field.size() != 2 * static_cast<Eigen::Index>(nf))
      throw Invalid_input("streamlines: the field has " + std::to_string(field.size()) +
                          " frame coordinates, the mesh needs " + std::to_string(2 * nf));
    if(!field.allFinite()) throw Invalid_input("streamlines: the field has non-finite entries");
    faces.resize(nf);
    for(int f = 0; f < nf; ++f)
    {
      Face_data& F = faces[f];
      const double l2 = M.face_edge_length(f, 2);
      F.corner = {V2{{0, 0}}, V2{{l2, 0}}, M.corner2_layout(f)};
      const double twice_area = l2 * F.corner[2][1];
      for(int k = 0; k < 3; ++k)
      {
        const V2& a = F.corner[(k + 1) % 3];
        const V2& b = F.corner[(k + 2) % 3];
        F.gradient[k] = {(a[1] - b[1]) / twice_area, (b[0] - a[0]) / twice_area};
      }
      F.direction = {field[2 * f], field[2 * f + 1]};
      F.magnitude = std::hypot(F.direction[0], F.direction[1]);
      maximum_magnitude = std::max(maximum_magnitude, F.magnitude);
      total_area += M.face_area(f);
    }

    const int nv = M.number_of_vertices();
    vertex_face_start.assign(nv + 1, 0);
    for(int f = 0; f < nf; ++f)
      for(int v : M.face_vertices(f)) ++vertex_face_start[v + 1];
    for(int v = 0; v < nv; ++v) vertex_face_start[v + 1] += vertex_face_start[v];
    vertex_faces.resize(vertex_face_start[nv]);
    std::vector<int> fill(vertex_face_start.begin(), vertex_face_start.end() - 1);
    for(int f = 0; f < nf; ++f)
      for(int v : M.face_vertices(f)) vertex_faces[fill[v]++] = f;

    boundary_vertex.assign(nv, 0);
    for(int e = 0; e < M.number_of_edges(); ++e)
      if(M.is_boundary_edge(e))
        for(int v : M.edge_vertices(e)) boundary_vertex[v] = 1;

    V3 lo{{infinity, infinity, infinity}}, hi{{-infinity, -infinity, -infinity}};
    for(int v = 0; v < nv; ++v)
    {
      if(M.is_isolated_vertex(v)) continue;
      for(int i = 0; i < 3; ++i)
      {
        lo[i] = std::min(lo[i], M.position(v)[i]);
        hi[i] = std::max(hi[i], M.position(v)[i]);
      }
    }
    box_min = lo;
    diagonal = distance3(lo, hi);
  }

  double to_absolute(double value, Length_unit unit) const
  {
    switch(unit)
    {
    case Length_unit::absolute: return value;
    case Length_unit::mean_edge_length: return value * mesh->mean_edge_length();
    case Length_unit::bounding_box_diagonal: return value * diagonal;
    }
    return value;
  }

  V2 direction(int f, const Walk_settings& s) const
  {
    const Face_data& F = faces[f];
    const double k = s.sign / F.magnitude;
    if(s.rotated) return {-k * F.direction[1], k * F.direction[0]};
    return {k * F.direction[0], k * F.direction[1]};
  }

  V3 point_of(int f, const Barycentric& b) const
  {
    const auto& t = mesh->face_vertices(f);
    const V3& p0 = mesh->position(t[0]);
    const V3& p1 = mesh->position(t[1]);
    const V3& p2 = mesh->position(t[2]);
    return {b[0] * p0[0] + b[1] * p1[0] + b[2] * p2[0], b[0] * p0[1] + b[1] * p1[1] + b[2] * p2[1],
            b[0] * p0[2] + b[1] * p1[2] + b[2] * p2[2]};
  }

  V2 layout_of(int f, const Barycentric& b) const
  {
    const Face_data& F = faces[f];
    return {b[1] * F.corner[1][0] + b[2] * F.corner[2][0], b[2] * F.corner[2][1]};
  }

  int local_corner(int f, int v) const
  {
    const auto& t = mesh->face_vertices(f);
    return t[0] == v ? 0 : (t[1] == v ? 1 : (t[2] == v ? 2 : -1));
  }

  // The face around vertex `v` (other than `exclude`) into which the walk continues
  // from the vertex: its direction must point strictly into the face; among several,
  // the one closest to `incoming` (a 3D direction, or zero).  -1 if none.
  int face_leaving_vertex(int v, int exclude, const V3& incoming, const Walk_settings& s) const
  {
    int best = -1;
    double best_alignment = -infinity;
    for(int i = vertex_face_start[v]; i < vertex_face_start[v + 1]; ++i)
    {
      const int g = vertex_faces[i];
      if(g == exclude || !(faces[g].magnitude > s.zero_threshold)) continue;
      const int m = local_corner(g, v);
      const V2 d = direction(g, s);
      const Face_data& G = faces[g];
      if(!(dot2(G.gradient[(m + 1) % 3], d) > 0 && dot2(G.gradient[(m + 2) % 3], d) > 0)) continue;
      const V3 w = mesh->from_frame(g, d[0], d[1]);
      const double alignment = dot3(w, incoming);
      if(alignment > best_alignment)
      {
        best_alignment = alignment;
        best = g;
      }
    }
    return best;
  }

  // Why a walk that cannot leave vertex `v` stops: all faces there have no field, or
  // the field leaves the surface (a boundary vertex), or the vertex is a sink.
  Streamline_stop stop_at_vertex(int v, const Walk_settings& s) const
  {
    bool any_field = false;
    for(int i = vertex_face_start[v]; i < vertex_face_start[v + 1]; ++i)
      any_field = any_field || faces[vertex_faces[i]].magnitude > s.zero_threshold;
    if(!any_field) return Streamline_stop::zero_field;
    return boundary_vertex[v] ? Streamline_stop::boundary : Streamline_stop::sink_vertex;
  }

  // Puts `pos` on corner `m` of its face.
  void place_on_corner(Position& pos, int m) const
  {
    pos.beta = {0, 0, 0};
    pos.beta[m] = 1;
    pos.corner = m;
    pos.entered_edge = -1;
    pos.point = mesh->position(mesh->face_vertices(pos.face)[m]);
  }

  // Walks from `start` until a stop.  `proximity` is sampled every `proximity.step()`
  // of walked length and ends the walk when it reports a point too close.
  template <class Proximity>
  Walk walk(Position pos, const Walk_settings& s, Proximity& proximity) const
  {
    Walk w;
    w.points.push_back(pos.point);
    const double step = proximity.step();
    double next_sample = step;
    // The last point that passed the proximity test (the start, or a sample), where the
    // walk is cut back to if its end turns out to be too close to another streamline.
    struct
    {
      std::size_t points = 1;
      Position position;
      Barycentric segment_start{{0, 0, 0}};
      double segment_start_length = 0, length = 0;
    } good;
    good.position = pos;
    const double tiny = 1e-12 * mesh->mean_edge_length();
    int tiny_run = 0;
    bool left_seed_face = false;

    // A walk starting on a vertex first picks its face.
    if(pos.corner >= 0)
    {
      const int v = mesh->face_vertices(pos.face)[pos.corner];
      const int g = face_leaving_vertex(v, -1, V3{{0, 0, 0}}, s);
      if(g < 0)
      {
        w.stop = stop_at_vertex(v, s);
        w.end = pos;
        return w;
      }
      pos.face = g;
      place_on_corner(pos, local_corner(g, v));
    }

    for(int iteration = 0;; ++iteration)
    {
      if(iteration >= s.maximum_segments)
      {
        w.stop = Streamline_stop::maximum_segments;
        break;
      }
      const int f = pos.face;
      const Face_data& F = faces[f];
      if(!(F.magnitude > s.zero_threshold))
      {
        w.stop = Streamline_stop::zero_field;
        break;
      }
      const V2 d = direction(f, s);
      const std::array<double, 3> rate = {dot2(F.gradient[0], d), dot2(F.gradient[1], d), dot2(F.gradient[2], d)};
      if(pos.entered_edge >= 0 && !(rate[pos.entered_edge] > 0))
      {
        w.stop = Streamline_stop::sink_edge;
        break;
      }
      // Exit: the first barycentric coordinate to reach zero.
      double t = infinity;
      int exit = -1;
      for(int k = 0; k < 3; ++k)
        if(rate[k] < 0)
        {
          const double tk = pos.beta[k] / -rate[k];
          if(tk < t)
          {
            t = tk;
            exit = k;
          }
        }
      if(exit < 0) // cannot happen for a non-zero direction; guards against NaN
      {
        w.stop = Streamline_stop::zero_field;
        break;
      }

      Streamline_stop stop = Streamline_stop::none;
      if(w.length + t >= s.maximum_length)
      {
        t = std::max(0., s.maximum_length - w.length);
        stop = Streamline_stop::maximum_length;
      }
      if(s.check_closure && f == s.seed_face && left_seed_face)
      {
        const V2 p0 = layout_of(f, pos.beta);
        const V2 q = {s.seed_layout[0] - p0[0], s.seed_layout[1] - p0[1]};
        const double along = dot2(q, d);
        if(along >= 0 && along <= t && std::abs(cross2(d, q)) <= s.closure_tolerance)
        {
          t = along;
          stop = Streamline_stop::closed_loop;
        }
      }
      // Proximity samples at multiples of `step` of the walked length.
      while(next_sample <= w.length + t)
      {
        const double u = next_sample - w.length;
        const Barycentric b = normalised(
            {pos.beta[0] + u * rate[0], pos.beta[1] + u * rate[1], pos.beta[2] + u * rate[2]});
        const V3 p = point_of(f, b);
        if(proximity.too_close(p, next_sample))
        {
          t = u;
          stop = Streamline_stop::too_close;
          break;
        }
        good.points = w.points.size();
        good.position.face = f;
        good.position.beta = b;
        good.position.point = p;
        good.position.entered_edge = good.position.corner = -1;
        good.segment_start = pos.beta;
        good.segment_start_length = w.length;
        good.length = next_sample;
        next_sample += step;
      }

      Position next = pos;
      next.entered_edge = -1;
      next.corner = -1;
      next.beta = {pos.beta[0] + t * rate[0], pos.beta[1] + t * rate[1], pos.beta[2] + t * rate[2]};
      bool crossing = false;
      double edge_parameter = 0;
      if(stop == Streamline_stop::none)
      {
        next.beta[exit] = 0;
        next.beta = normalised(next.beta);
        crossing = true;
        for(int j = 0; j < 3; ++j)
          if(j != exit && next.beta[j] <= vertex_snap)
          {
            place_on_corner(next, 3 - exit - j);
            crossing = false;
            break;
          }
        if(crossing)
        {
          // The point is stored by its parameter along the edge, from the edge's first
          // vertex: both faces compute the same 3D point from it.
          const int e = mesh->face_edges(f)[exit];
          const auto& ev = mesh->edge_vertices(e);
          const int a = local_corner(f, ev[0]), b = local_corner(f, ev[1]);
          edge_parameter = next.beta[b] / (next.beta[a] + next.beta[b]);
          const V3& pa = mesh->position(ev[0]);
          const V3& pb = mesh->position(ev[1]);
          next.point = {pa[0] + edge_parameter * (pb[0] - pa[0]), pa[1] + edge_parameter * (pb[1] - pa[1]),
                        pa[2] + edge_parameter * (pb[2] - pa[2])};
        }
      }
      else
      {
        next.beta = normalised(next.beta);
        next.point = point_of(f, next.beta);
      }

      if(t > 0)
      {
        w.points.push_back(next.point);
        w.faces.push_back(f);
        if(s.keep_segments) w.segments.push_back({f, pos.beta, next.beta, t});
        w.length += t;
      }
      tiny_run = t < tiny ? tiny_run + 1 : 0;
      pos = next;
      if(stop != Streamline_stop::none)
      {
        w.stop = stop;
        break;
      }
      if(tiny_run >= stalled_count)
      {
        w.stop = Streamline_stop::stalled;
        break;
      }

      if(pos.corner >= 0)
      {
        // On a vertex: continue in a face the field leaves the vertex into.
        const int v = mesh->face_vertices(f)[pos.corner];
        const int g = face_leaving_vertex(v, f, mesh->from_frame(f, d[0], d[1]), s);
        if(g < 0)
        {
          w.stop = stop_at_vertex(v, s);
          break;
        }
        pos.face = g;
        place_on_corner(pos, local_corner(g, v));
      }
      else
      {
        const int e = mesh->face_edges(f)[exit];
        if(mesh->is_boundary_edge(e))
        {
          pos.entered_edge = exit; // stays in f, on the boundary edge
          w.stop = Streamline_stop::boundary;
          break;
        }
        const auto& ef = mesh->edge_faces(e);
        const int g = ef[0] == f ? ef[1] : ef[0];
        const auto& ev = mesh->edge_vertices(e);
        int j = 0;
        while(mesh->face_edges(g)[j] != e) ++j;
        pos.face = g;
        pos.beta = {0, 0, 0};
        pos.beta[local_corner(g, ev[0])] = 1 - edge_parameter;
        pos.beta[local_corner(g, ev[1])] = edge_parameter;
        pos.entered_edge = j;
      }
      if(pos.face != s.seed_face) left_seed_face = true;
    }
    w.end = pos;
    // A walk that came too close to another streamline is cut back to its last good
    // sample; so is one that stopped for another reason (a sink, the boundary) but
    // whose end beyond the last sample is too close.
    if(step < infinity && w.length > good.length &&
       (w.stop == Streamline_stop::too_close || proximity.near(w.points.back(), w.length)))
    {
      w.points.resize(good.points);
      w.faces.resize(good.points - 1);
      if(s.keep_segments) w.segments.resize(good.points - 1);
      const double partial = good.length - good.segment_start_length;
      if(partial > 0)
      {
        w.points.push_back(good.position.point);
        w.faces.push_back(good.position.face);
        if(s.keep_segments)
          w.segments.push_back({good.position.face, good.segment_start, good.position.beta, partial});
      }
      w.length = good.length;
      w.end = good.position;
      w.stop = Streamline_stop::too_close;
    }
    else if(step < infinity && w.length > good.length)
      proximity.record(w.points.back(), w.length); // the end beyond the last sample
    return w;
  }

  Position start_position(int face, const Barycentric& beta) const
  {
    Position pos;
    pos.face = face;
    pos.beta = normalised(beta);
    for(int k = 0; k < 3; ++k)
      if(pos.beta[k] >= 1 - vertex_snap)
      {
        place_on_corner(pos, k);
        return pos;
      }
    pos.point = point_of(face, pos.beta);
    return pos;
  }

  Walk_settings settings(const Streamline_options& o, double sign) const
  {
    Walk_settings s;
    s.sign = sign;
    const double l = to_absolute(o.maximum_length, o.length_unit);
    s.maximum_length = l > 0 ? l : infinity;
    s.maximum_segments = std::max(1, o.maximum_segments);
    s.zero_threshold = o.zero_field_tolerance * maximum_magnitude;
    return s;
  }

  // Joins a backward and a forward walk from the same seed into one streamline
  // running along the field.
  static Streamline join(const Walk* backward, const Walk& forward, int seed_face)
  {
    Streamline line;
    std::vector<int> segment_faces;
    if(backward)
    {
      for(std::size_t i = backward->points.size(); i-- > 1;) line.points.push_back(backward->points[i]);
      for(std::size_t i = backward->faces.size(); i-- > 0;) segment_faces.push_back(backward->faces[i]);
      line.backward_stop = backward->stop;
    }
    line.seed_index = line.points.size();
    line.points.insert(line.points.end(), forward.points.begin(), forward.points.end());
    segment_faces.insert(segment_faces.end(), forward.faces.begin(), forward.faces.end());
    line.faces = segment_faces;
    line.faces.push_back(segment_faces.empty() ? seed_face : segment_faces.back());
    line.forward_stop = forward.stop;
    line.closed = forward.stop == Streamline_stop::closed_loop;
    return line;
  }

  template <class Proximity>
  Streamline trace(const Position& start, const Streamline_options& o, double closure_tolerance,
                   Proximity* forward_proximity, Proximity* backward_proximity, bool keep_segments,
                   std::vector<Segment_record>* segments) const
  {
    No_proximity none;
    Walk forward, backward;
    if(o.forward)
    {
      Walk_settings s = settings(o, 1);
      s.check_closure = closure_tolerance > 0;
      s.seed_face = start.face;
      s.seed_layout = layout_of(start.face, start.beta);
      s.closure_tolerance = closure_tolerance;
      s.keep_segments = keep_segments;
      forward = forward_proximity ? walk(start, s, *forward_proximity) : walk(start, s, none);
    }
    else
      forward.points.push_back(start.point);
    const bool do_backward = o.backward && forward.stop != Streamline_stop::closed_loop;
    if(do_backward)
    {
      Walk_settings s = settings(o, -1);
      s.keep_segments = keep_segments;
      backward = backward_proximity ? walk(start, s, *backward_proximity) : walk(start, s, none);
    }
    if(segments)
    {
      segments->clear();
      if(do_backward)
        for(std::size_t i = backward.segments.size(); i-- > 0;)
        {
          const Segment_record& r = backward.segments[i];
          segments->push_back({r.face, r.end, r.start, r.length});
        }
      segments->insert(segments->end(), forward.segments.begin(), forward.segments.end());
    }
    return join(do_backward ? &backward : nullptr, forward, start.face);
  }

  // A random point of the surface, uniform by area.
  Position random_position(std::mt19937_64& gen, const std::vector<double>& cumulative_area) const
  {
    std::uniform_real_distribution<double> u(0, 1);
    const double a = u(gen) * cumulative_area.back();
    int f = static_cast<int>(std::upper_bound(cumulative_area.begin(), cumulative_area.end(), a) -
                             cumulative_area.begin());
    f = std::min(f, static_cast<int>(faces.size()) - 1);
    const double r1 = std::sqrt(u(gen)), r2 = u(gen);
    return start_position(f, {1 - r1, r1 * (1 - r2), r1 * r2});
  }

  std::vector<double> cumulative_areas() const
  {
    std::vector<double> c(faces.size());
    double s = 0;
    for(std::size_t f = 0; f < faces.size(); ++f) c[f] = s += mesh->face_area(static_cast<int>(f));
    return c;
  }

  std::vector<Streamline> evenly_spaced(const Evenly_spaced_options& o) const
  {
    const double separation = to_absolute(o.separation, o.separation_unit);
    if(!(separation > 0) || !std::isfinite(separation))
      throw Invalid_input("evenly spaced streamlines: the separation must be positive");
    if(!(o.test_ratio > 0 && o.test_ratio <= 1))
      throw Invalid_input("evenly spaced streamlines: test_ratio must lie in (0, 1]");
    const double test_distance = o.test_ratio * separation;
    const double sample_step = test_distance / 2;
    const double seed_distance = 0.9 * separation;
    const double closure = std::max(test_distance, o.tracing.loop_closure_tolerance * mesh->mean_edge_length());

    Sample_grid grid(separation, box_min);
    std::mt19937_64 gen(o.random_seed);
    const std::vector<double> cumulative = cumulative_areas();
    const long random_candidates = static_cast<long>(std::ceil(4 * total_area / (separation * separation))) + 16;

    std::vector<Streamline> result;
    std::deque<std::pair<int, std::vector<Segment_record>>> queue; // accepted lines to seed beside
    auto seed_is_free = [&](const V3& p) {
      return !grid.any_within(p, seed_distance, [](const Sample_grid::Sample&) { return true; });
    };
    auto full = [&]() { return o.maximum_streamlines > 0 && static_cast<int>(result.size()) >= o.maximum_streamlines; };

    auto try_seed = [&](const Position& seed) {
      if(full() || !(faces[seed.face].magnitude > o.tracing.zero_field_tolerance * maximum_magnitude)) return;
      if(!seed_is_free(seed.point)) return;
      const int id = static_cast<int>(result.size());
      const double self_gap = 3 * test_distance;
      Separation_test forward{&grid, id, 1, test_distance, self_gap, sample_step};
      Separation_test backward{&grid, id, -1, test_distance, self_gap, sample_step};
      grid.insert(seed.point, id, 0);
      std::vector<Segment_record> segments;
      Streamline line = trace(seed, o.tracing, closure, &forward, &backward, true, &segments);
      if(line.length() < o.minimum_length_ratio * separation || line.points.size() < 2)
      {
        grid.remove_line(id);
        return;
      }
      result.push_back(std::move(line));
      queue.emplace_back(id, std::move(segments));
    };

    // Candidates beside an accepted line: from points spaced by the separation along
    // it, walk across the field (J v and -J v) for one separation on the surface.
    auto seed_beside = [&](const std::vector<Segment_record>& segments) {
      double along = 0;
      double next = 0.5 * separation;
      No_proximity none;
      for(const Segment_record& r : segments)
      {
        while(next <= along + r.length && !full())
        {
          const double u = (next - along) / r.length;
          Position p = start_position(
              r.face, {r.start[0] + u * (r.end[0] - r.start[0]), r.start[1] + u * (r.end[1] - r.start[1]),
                       r.start[2] + u * (r.end[2] - r.start[2])});
          for(double sign : {1., -1.})
          {
            Walk_settings s = settings(o.tracing, sign);
            s.rotated = true;
            s.maximum_length = separation;
            const Walk side = walk(p, s, none);
            if(side.stop == Streamline_stop::maximum_length)
            {
              Position c = side.end;
              c.entered_edge = -1;
              c.corner = -1;
              try_seed(c);
            }
          }
          next += separation;
        }
        along += r.length;
      }
    };

    for(long c = 0; c < random_candidates && !full(); ++c)
    {
      try_seed(random_position(gen, cumulative));
      while(!queue.empty() && !full())
      {
        const std::vector<Segment_record> segments = std::move(queue.front().second);
        queue.pop_front();
        seed_beside(segments);
      }
    }
    return result;
  }

  std::vector<Streamline> fur(const Fur_options& o) const
  {
    const double length = to_absolute(o.length, o.length_unit);
    if(!(length > 0) || !std::isfinite(length)) throw Invalid_input("fur: the stroke length must be positive");
    long count = o.number_of_strokes;
    if(count <= 0)
    {
      if(!(o.density > 0)) throw Invalid_input("fur: give number_of_strokes or a positive density");
      count = static_cast<long>(std::llround(o.density * total_area));
    }
    std::mt19937_64 gen(o.random_seed);
    const std::vector<double> cumulative = cumulative_areas();
    std::vector<Streamline> strokes;
    strokes.reserve(static_cast<std::size_t>(count));
    for(long i = 0; i < count; ++i)
    {
      const Position root = random_position(gen, cumulative);
      Streamline_options t = o.tracing;
      t.forward = true;
      t.backward = false;
      t.length_unit = Length_unit::absolute;
      t.maximum_length = length;
      if(o.scale_length_by_magnitude)
        t.maximum_length = length * faces[root.face].magnitude / std::max(maximum_magnitude, 1e-300);
      t.loop_closure_tolerance = 0;
      if(!(t.maximum_length > 0)) continue;
      No_proximity* none = nullptr;
      Streamline s = trace(root, t, 0, none, none, false, nullptr);
      if(s.points.size() >= 2) strokes.push_back(std::move(s));
    }
    return strokes;
  }
};

Streamline_tracer::Streamline_tracer(std::shared_ptr<const Intrinsic_mesh> mesh, const Eigen::VectorXd& field)
  : impl_(std::make_unique<Impl>(std::move(mesh), field))
{}

Streamline_tracer::~Streamline_tracer() = default;
Streamline_tracer::Streamline_tracer(Streamline_tracer&&) noexcept = default;
Streamline_tracer& Streamline_tracer::operator=(Streamline_tracer&&) noexcept = default;

const Intrinsic_mesh& Streamline_tracer::mesh() const { return *impl_->mesh; }
double Streamline_tracer::bounding_box_diagonal() const { return impl_->diagonal; }
double Streamline_tracer::to_absolute(double value, Length_unit unit) const { return impl_->to_absolute(value, unit); }
double Streamline_tracer::maximum_magnitude() const { return impl_->maximum_magnitude; }

Streamline Streamline_tracer::trace(int face, const std::array<double, 3>& barycentric,
                                    const Streamline_options& options) const
{
  if(face < 0 || face >= impl_->mesh->number_of_faces())
    throw Invalid_input("streamline: face " + std::to_string(face) + " does not exist");
  for(double b : barycentric)
    if(!std::isfinite(b)) throw Invalid_input("streamline: non-finite barycentric coordinates");
  const Position start = impl_->start_position(face, barycentric);
  No_proximity* none = nullptr;
  return impl_->trace(start, options, options.loop_closure_tolerance * impl_->mesh->mean_edge_length(), none,
                      none, false, nullptr);
}

Streamline Streamline_tracer::trace_from_point(int face, const std::array<double, 3>& point,
                                               const Streamline_options& options) const
{
  if(face < 0 || face >= impl_->mesh->number_of_faces())
    throw Invalid_input("streamline: face " + std::to_string(face) + " does not exist");
  // Barycentric coordinates of the projection onto the face's plane, in the face frame.
  const Intrinsic_mesh& M = *impl_->mesh;
  const auto& t = M.face_vertices(face);
  const V3& e1 = M.frame_e1(face);
  const V3& e2 = M.frame_e2(face);
  auto local = [&](const V3& p) {
    const V3 d = sub3(p, M.position(t[0]));
    return V2{{dot3(d, e1), dot3(d, e2)}};
  };
  const V2 a = local(M.position(t[1])), b = local(M.position(t[2])), p = local(point);
  const double det = cross2(a, b);
  Barycentric beta{{1. / 3, 1. / 3, 1. / 3}};
  if(std::abs(det) > 0)
  {
    const double u = cross2(p, b) / det, v = cross2(a, p) / det;
    beta = {1 - u - v, u, v};
  }
  return trace(face, beta, options);
}

std::vector<Streamline> Streamline_tracer::evenly_spaced(const Evenly_spaced_options& options) const
{
  return impl_->evenly_spaced(options);
}

std::vector<Streamline> Streamline_tracer::fur(const Fur_options& options) const { return impl_->fur(options); }

} // namespace Tangent_vector_fields
} // namespace CGAL
