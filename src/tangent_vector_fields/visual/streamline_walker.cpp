// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The exact walk from face to face in barycentric coordinates of each face's 2D layout,
// with the branch of an n-field matched in every face entered, and its stops.

#include "streamline_walker.h"
#include "streamline_proximity.h"

#include <CGAL/Tangent_vector_fields/errors.h>

#include <string>
#include <utility>

namespace CGAL {
namespace Tangent_vector_fields {
namespace internal {

V2 Streamline_walker::carried_across(int f, int g, int e, const V2& v) const
{
  const auto& ev = mesh->edge_vertices(e);
  const Face_data& F = face(f);
  const Face_data& G = face(g);
  const V2& fa = F.corner[local_corner(f, ev[0])];
  const V2& fb = F.corner[local_corner(f, ev[1])];
  const V2& ga = G.corner[local_corner(g, ev[0])];
  const V2& gb = G.corner[local_corner(g, ev[1])];
  const V2 edge_f = {fb[0] - fa[0], fb[1] - fa[1]};
  const V2 edge_g = {gb[0] - ga[0], gb[1] - ga[1]};
  // In complex numbers: edge_g * conj(edge_f) * v.
  const double c = dot2(edge_f, v), s = cross2(edge_f, v);
  return {edge_g[0] * c - edge_g[1] * s, edge_g[1] * c + edge_g[0] * s};
}

std::pair<int, int> Streamline_walker::face_leaving_vertex(int v, int exclude, const V3& incoming,
                                                           const V3& reference, const Walk_settings& s) const
{
  int best = -1, best_branch = 0;
  double best_alignment = -infinity;
  const Walker_surface& S = *surface;
  for(int i = S.vertex_face_start[v]; i < S.vertex_face_start[v + 1]; ++i)
  {
    const int g = S.vertex_faces[i];
    if(g == exclude || !(face(g).magnitude > s.zero_threshold)) continue;
    const int m = local_corner(g, v);
    const int branch = n == 1 ? 0 : matching_branch(g, mesh->to_frame(g, reference));
    const V2 d = direction(g, branch, s);
    const Face_data& G = face(g);
    if(!(dot2(G.gradient[(m + 1) % 3], d) > 0 && dot2(G.gradient[(m + 2) % 3], d) > 0)) continue;
    const V3 w = mesh->from_frame(g, d[0], d[1]);
    const double alignment = dot3(w, incoming);
    if(alignment > best_alignment)
    {
      best_alignment = alignment;
      best = g;
      best_branch = branch;
    }
  }
  return {best, best_branch};
}

Streamline_stop Streamline_walker::stop_at_vertex(int v, const Walk_settings& s) const
{
  bool any_field = false;
  const Walker_surface& S = *surface;
  for(int i = S.vertex_face_start[v]; i < S.vertex_face_start[v + 1]; ++i)
    any_field = any_field || face(S.vertex_faces[i]).magnitude > s.zero_threshold;
  if(!any_field) return Streamline_stop::zero_field;
  return S.boundary_vertex[v] ? Streamline_stop::boundary : Streamline_stop::sink_vertex;
}

template <class Proximity>
Walk Streamline_walker::walk(Position pos, const Walk_settings& s, Proximity& proximity) const
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
  int last_branch = pos.branch; // the branch of the last segment
  bool left_seed_face = false;

  // A walk starting on a vertex first picks its face: the one its face's branch leads
  // into best (the face itself if it can).
  if(pos.corner >= 0)
  {
    const int v = mesh->face_vertices(pos.face)[pos.corner];
    if(singular_vertex[v])
    {
      w.stop = Streamline_stop::singular_vertex;
      w.end = pos;
      return w;
    }
    V3 incoming{{0, 0, 0}}, reference{{0, 0, 0}};
    if(face(pos.face).magnitude > s.zero_threshold)
    {
      const V2 d = direction(pos.face, pos.branch, s);
      const V2 u = field_vector(pos.face, pos.branch);
      incoming = mesh->from_frame(pos.face, d[0], d[1]);
      reference = mesh->from_frame(pos.face, u[0], u[1]);
    }
    const std::pair<int, int> g = face_leaving_vertex(v, -1, incoming, reference, s);
    if(g.first < 0)
    {
      w.stop = stop_at_vertex(v, s);
      w.end = pos;
      return w;
    }
    pos.face = g.first;
    pos.branch = g.second;
    place_on_corner(pos, local_corner(g.first, v));
  }

  for(int iteration = 0;; ++iteration)
  {
    if(iteration >= s.maximum_segments)
    {
      w.stop = Streamline_stop::maximum_segments;
      break;
    }
    const int f = pos.face;
    const Face_data& F = face(f);
    if(!(F.magnitude > s.zero_threshold))
    {
      w.stop = Streamline_stop::zero_field;
      break;
    }
    const V2 d = direction(f, pos.branch, s);
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
    if(s.check_closure && f == s.seed_face && left_seed_face && same_line(pos.branch, s.seed_branch))
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
    const V3 tangent = next_sample <= w.length + t ? unit_tangent(f, pos.branch) : V3{{0, 0, 0}};
    while(next_sample <= w.length + t)
    {
      const double u = next_sample - w.length;
      const Barycentric b = normalised(
          {pos.beta[0] + u * rate[0], pos.beta[1] + u * rate[1], pos.beta[2] + u * rate[2]});
      const V3 p = point_of(f, b);
      if(proximity.too_close(p, next_sample, tangent))
      {
        t = u;
        stop = Streamline_stop::too_close;
        break;
      }
      good.points = w.points.size();
      good.position.face = f;
      good.position.branch = pos.branch;
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
      if(s.keep_segments) w.segments.push_back({f, pos.branch, pos.beta, next.beta, t});
      w.length += t;
      last_branch = pos.branch;
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
      // On a vertex: stop at a singularity, else continue in a face the field leaves the
      // vertex into.
      const int v = mesh->face_vertices(f)[pos.corner];
      if(singular_vertex[v])
      {
        w.stop = Streamline_stop::singular_vertex;
        break;
      }
      const V2 u = field_vector(f, pos.branch);
      const std::pair<int, int> g =
          face_leaving_vertex(v, f, mesh->from_frame(f, d[0], d[1]), mesh->from_frame(f, u[0], u[1]), s);
      if(g.first < 0)
      {
        w.stop = stop_at_vertex(v, s);
        break;
      }
      pos.face = g.first;
      pos.branch = g.second;
      place_on_corner(pos, local_corner(g.first, v));
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
      // The branch beyond the edge: the vector of g closest to the one followed in f.
      if(n > 1) pos.branch = matching_branch(g, carried_across(f, g, e, field_vector(f, pos.branch)));
      pos.face = g;
      pos.beta = {0, 0, 0};
      pos.beta[local_corner(g, ev[0])] = 1 - edge_parameter;
      pos.beta[local_corner(g, ev[1])] = edge_parameter;
      pos.entered_edge = j;
    }
    if(pos.face != s.seed_face) left_seed_face = true;
  }
  if(w.stop == Streamline_stop::sink_edge || w.stop == Streamline_stop::sink_vertex ||
     w.stop == Streamline_stop::stalled)
    end_at_singular_vertex(w, pos, last_branch, s);
  w.end = pos;
  // A walk that came too close to another streamline is cut back to its last good
  // sample; so is one that stopped for another reason (a sink, the boundary) but
  // whose end beyond the last sample is too close.
  const V3 end_tangent =
      step < infinity && w.length > good.length ? unit_tangent(w.faces.back(), last_branch) : V3{{0, 0, 0}};
  if(step < infinity && w.length > good.length &&
     (w.stop == Streamline_stop::too_close || proximity.near(w.points.back(), w.length, end_tangent)))
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
        w.segments.push_back(
            {good.position.face, good.position.branch, good.segment_start, good.position.beta, partial});
    }
    w.length = good.length;
    w.end = good.position;
    w.stop = Streamline_stop::too_close;
  }
  else if(step < infinity && w.length > good.length)
    proximity.record(w.points.back(), w.length, end_tangent); // the end beyond the last sample
  return w;
}

bool Streamline_walker::end_at_singular_vertex(Walk& w, Position& pos, int& last_branch, const Walk_settings& s) const
{
  if(singular_list.empty()) return false;
  // The faces that hold the end point: where the walk is and where its last segment ran
  // (they differ after a sink edge, whose point is on their shared edge).
  const int candidates[2] = {pos.face, w.faces.empty() ? -1 : w.faces.back()};
  int best_face = -1, best_vertex = -1;
  double best_distance = infinity;
  for(int f : candidates)
  {
    if(f < 0) continue;
    for(int v : mesh->face_vertices(f))
      if(singular_vertex[v] && distance3(mesh->position(v), pos.point) < best_distance)
      {
        best_distance = distance3(mesh->position(v), pos.point);
        best_face = f;
        best_vertex = v;
      }
  }
  // The length limit holds for this segment too: beyond it the walk keeps its stop.
  if(best_face < 0 || w.length + best_distance > s.maximum_length) return false;
  // The end point in barycentric coordinates of the chosen face: it lies on the corners
  // the face shares with `pos.face` (all three if it is that face).
  Barycentric start{{0, 0, 0}};
  for(int k = 0; k < 3; ++k)
  {
    const int m = local_corner(pos.face, mesh->face_vertices(best_face)[k]);
    if(m >= 0) start[k] = pos.beta[m];
  }
  start = normalised(start);
  Position end;
  end.face = best_face;
  end.branch = best_face == pos.face ? pos.branch : last_branch;
  place_on_corner(end, local_corner(best_face, best_vertex));
  if(best_distance > 0)
  {
    w.points.push_back(end.point);
    w.faces.push_back(best_face);
    if(s.keep_segments) w.segments.push_back({best_face, end.branch, start, end.beta, best_distance});
    w.length += best_distance;
    last_branch = end.branch;
  }
  w.stop = Streamline_stop::singular_vertex;
  pos = end;
  return true;
}

Walk_settings Streamline_walker::settings(const Streamline_options& o, double sign, double zero_reference) const
{
  check_streamline_options(o);
  Walk_settings s;
  s.sign = sign;
  const double l = to_absolute(o.maximum_length, o.length_unit);
  s.maximum_length = l > 0 ? l : infinity;
  s.maximum_segments = o.maximum_segments;
  s.zero_threshold = o.zero_field_tolerance * (zero_reference >= 0 ? zero_reference : maximum_magnitude);
  return s;
}

Streamline Streamline_walker::join(const Walk* backward, const Walk& forward, const Position& seed)
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
  line.faces.push_back(segment_faces.empty() ? seed.face : segment_faces.back());
  line.branch = seed.branch;
  line.forward_stop = forward.stop;
  line.closed = forward.stop == Streamline_stop::closed_loop;
  return line;
}

template <class Proximity>
Streamline Streamline_walker::trace(const Position& start, const Streamline_options& o, double closure_tolerance,
                                     Proximity* forward_proximity, Proximity* backward_proximity, bool keep_segments,
                                     std::vector<Segment_record>* segments, double zero_reference) const
{
  No_proximity none;
  Walk forward, backward;
  if(o.forward)
  {
    Walk_settings s = settings(o, 1, zero_reference);
    s.check_closure = closure_tolerance > 0;
    s.seed_face = start.face;
    s.seed_branch = start.branch;
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
    Walk_settings s = settings(o, -1, zero_reference);
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
        segments->push_back({r.face, r.branch, r.end, r.start, r.length});
      }
    segments->insert(segments->end(), forward.segments.begin(), forward.segments.end());
  }
  return join(do_backward ? &backward : nullptr, forward, start);
}

// The walks run without proximity test (single streamlines, fur, walks across the
// field) and with the separation test (evenly spaced streamlines).
template Walk Streamline_walker::walk(Position, const Walk_settings&, No_proximity&) const;
template Walk Streamline_walker::walk(Position, const Walk_settings&, Separation_test&) const;
template Streamline Streamline_walker::trace(const Position&, const Streamline_options&, double, No_proximity*,
                                             No_proximity*, bool, std::vector<Segment_record>*, double) const;
template Streamline Streamline_walker::trace(const Position&, const Streamline_options&, double, Separation_test*,
                                             Separation_test*, bool, std::vector<Segment_record>*, double) const;

} // namespace internal
} // namespace Tangent_vector_fields
} // namespace CGAL
