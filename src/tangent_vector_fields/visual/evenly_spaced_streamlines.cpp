// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Evenly spaced streamlines (Jobard and Lefer 1997, on the surface): seeds beside the
// accepted streamlines and at random points, kept apart by a uniform grid of samples;
// for an n-field, every family of lines at its own spacing (the hatching).

#include "streamline_proximity.h"
#include "streamline_walker.h"

#include <CGAL/Tangent_vector_fields/errors.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <string>
#include <utility>

namespace CGAL {
namespace Tangent_vector_fields {
namespace internal {

namespace {
// Streamlines an unlimited call may fill a surface with (area / separation^2).
const double max_expected_streamlines = 1e7;
} // namespace

std::vector<Streamline> evenly_spaced_streamlines(const Streamline_walker& walker, const Evenly_spaced_options& o)
{
  const double separation = walker.to_absolute(o.separation, o.separation_unit);
  if(!(separation > 0) || !std::isfinite(separation))
    throw Invalid_input("evenly spaced streamlines: the separation must be positive");
  if(!(o.test_ratio > 0 && o.test_ratio <= 1))
    throw Invalid_input("evenly spaced streamlines: test_ratio must lie in (0, 1]");
  if(o.tracing.branch != 0)
    throw Invalid_input("evenly spaced streamlines: tracing.branch must be 0 (every family is traced)");
  if(!(o.minimum_length_ratio >= 0) || !std::isfinite(o.minimum_length_ratio))
    throw Invalid_input("evenly spaced streamlines: minimum_length_ratio must be finite and non-negative");
  if(o.maximum_streamlines < 0)
    throw Invalid_input("evenly spaced streamlines: maximum_streamlines must not be negative (0: no limit)");
  check_streamline_options(o.tracing);
  // The streamlines fill the surface: about area / separation^2 of them, each sampled every
  // quarter separation.  Far more than any picture holds means a separation in the wrong
  // unit: it would run for ever, and even a few lines would exhaust the memory with samples.
  const double expected_lines = walker.surface->total_area / (separation * separation);
  if(!(expected_lines <= max_expected_streamlines))
    throw Invalid_input("evenly spaced streamlines: the separation is too small for the surface (about " +
                        short_number(expected_lines) + " streamlines would fill it, at most 1e7)");
  const double test_distance = o.test_ratio * separation;
  const double sample_step = test_distance / 2;
  const double seed_distance = 0.9 * separation;
  const double closure = std::max(test_distance, o.tracing.loop_closure_tolerance * walker.mesh->mean_edge_length());
  const Family_test family(walker.n);

  Sample_grid grid(separation, walker.surface->box_min);
  std::mt19937_64 gen(o.random_seed);
  const long random_candidates = static_cast<long>(std::ceil(4 * expected_lines)) + 16;

  std::vector<Streamline> result;
  std::deque<std::pair<int, std::vector<Segment_record>>> queue; // accepted lines to seed beside
  auto seed_is_free = [&](const V3& p, const V3& tangent) {
    return !grid.any_within(p, seed_distance,
                            [&](const Sample_grid::Sample& s) { return family.same(s.tangent, tangent); });
  };
  auto full = [&]() { return o.maximum_streamlines > 0 && static_cast<int>(result.size()) >= o.maximum_streamlines; };

  // A streamline from `seed` along its branch, kept if it is long enough.
  auto try_seed = [&](const Position& seed) {
    if(full() || !(walker.face(seed.face).magnitude > o.tracing.zero_field_tolerance * walker.maximum_magnitude))
      return;
    const V3 tangent = walker.unit_tangent(seed.face, seed.branch);
    if(!seed_is_free(seed.point, tangent)) return;
    const int id = static_cast<int>(result.size());
    const double self_gap = 3 * test_distance;
    Separation_test forward{&grid, family, id, 1, test_distance, self_gap, sample_step};
    Separation_test backward{&grid, family, id, -1, test_distance, self_gap, sample_step};
    grid.insert(seed.point, id, 0, tangent);
    std::vector<Segment_record> segments;
    Streamline line = walker.trace(seed, o.tracing, closure, &forward, &backward, true, &segments);
    if(line.length() < o.minimum_length_ratio * separation || line.points.size() < 2)
    {
      grid.remove_line(id);
      return;
    }
    result.push_back(std::move(line));
    queue.emplace_back(id, std::move(segments));
  };

  // Candidates beside an accepted line: from points spaced by the separation along
  // it, walk across the field (J v and -J v) for one separation on the surface; the
  // candidate continues the line's family (the branch the walk across has matched).
  auto seed_beside = [&](const std::vector<Segment_record>& segments) {
    double along = 0;
    double next = 0.5 * separation;
    No_proximity none;
    for(const Segment_record& r : segments)
    {
      while(next <= along + r.length && !full())
      {
        const double u = (next - along) / r.length;
        Position p = walker.start_position(
            r.face,
            {r.start[0] + u * (r.end[0] - r.start[0]), r.start[1] + u * (r.end[1] - r.start[1]),
             r.start[2] + u * (r.end[2] - r.start[2])},
            r.branch);
        for(double sign : {1., -1.})
        {
          Walk_settings s = walker.settings(o.tracing, sign);
          s.rotated = true;
          s.maximum_length = separation;
          const Walk side = walker.walk(p, s, none);
          if(side.stop == Streamline_stop::maximum_length)
          {
            Position c = side.end;
            c.entered_edge = -1;
            c.corner = -1;
            c.branch = walker.family_branch(c.branch);
            try_seed(c);
          }
        }
        next += separation;
      }
      along += r.length;
    }
  };

  // Each random point seeds every family: the first number_of_families(n) vectors of its
  // face are one of each.
  for(long c = 0; c < random_candidates && !full(); ++c)
  {
    const Position p = walker.random_position(gen);
    for(int j = 0; j < number_of_families(walker.n) && !full(); ++j)
    {
      Position q = p;
      q.branch = j;
      try_seed(q);
      while(!queue.empty() && !full())
      {
        const std::vector<Segment_record> segments = std::move(queue.front().second);
        queue.pop_front();
        seed_beside(segments);
      }
    }
  }
  return result;
}

} // namespace internal
} // namespace Tangent_vector_fields
} // namespace CGAL
