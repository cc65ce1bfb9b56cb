// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The separation test of evenly spaced streamlines (private to src/visual): samples of
// the accepted streamlines in a uniform grid, and the test a walk runs at each sample,
// family by family for n-fields.

#ifndef CGAL_TANGENT_VECTOR_FIELDS_SRC_VISUAL_STREAMLINE_PROXIMITY_H
#define CGAL_TANGENT_VECTOR_FIELDS_SRC_VISUAL_STREAMLINE_PROXIMITY_H

#include "streamline_walker.h"

#include <cstdint>
#include <unordered_map>

namespace CGAL {
namespace Tangent_vector_fields {
namespace internal {

// Uniform grid of sample points of streamlines, keyed by cell.
class Sample_grid
{
public:
  struct Sample
  {
    V3 point;
    int line;
    double arc; // signed arc length from the seed of its line
    V3 tangent; // unit vector of the field's branch the line follows there
  };

  Sample_grid(double cell, const V3& origin) : cell_(cell), origin_(origin) {}

  void insert(const V3& p, int line, double arc, const V3& tangent)
  {
    const std::uint64_t key = key_of(cell_of(p));
    cells_[key].push_back(static_cast<int>(samples_.size()));
    samples_.push_back({p, line, arc, tangent});
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

// Whether two streamlines near each other belong to the same family of an n-field, from
// their directions there: the n vectors of a face form n/2 families of lines for even n
// (a vector and its opposite are the same line), n families for odd n, 2 pi / n apart; two
// directions are of one family if they are closer than half that, pi / n (up to sign for
// even n).  Branch numbers cannot tell, since each face numbers its vectors from its own
// first one, and a streamline that turns around a singularity changes family.  With one
// family (vector fields, line fields) every streamline counts.
struct Family_test
{
  explicit Family_test(int n) : n(n), cos_half_gap(std::cos(M_PI / n)) {}
  bool same(const V3& a, const V3& b) const
  {
    if(number_of_families(n) == 1) return true;
    const double c = dot3(a, b);
    return (n % 2 == 0 ? std::abs(c) : c) > cos_half_gap;
  }
  int n;
  double cos_half_gap;
};

// The proximity test of the streamline being traced in evenly spaced seeding: against the
// samples of its own family only, so that the families of an n-field cross each other.
struct Separation_test
{
  Sample_grid* grid;
  Family_test family;
  int line;
  double sign;     // +1 forward (arcs >= 0), -1 backward
  double test_distance;
  double self_gap; // own samples closer than this in arc length are its own neighbourhood
  double sample_step;

  double step() const { return sample_step; }
  // True if `p`, reached after `walked`, is too close to another streamline or to a
  // distant part of this one.
  bool near(const V3& p, double walked, const V3& tangent) const
  {
    const double arc = sign * walked;
    const bool forward = sign > 0;
    return grid->any_within(p, test_distance, [&](const Sample_grid::Sample& s) {
      if(!family.same(s.tangent, tangent)) return false;
      if(s.line != line) return true;
      if(std::abs(s.arc - arc) < self_gap) return false;
      // While the forward part runs, its first samples are left to the loop-closure test.
      if(forward && s.arc >= 0 && s.arc < self_gap) return false;
      return true;
    });
  }
  void record(const V3& p, double walked, const V3& tangent) { grid->insert(p, line, sign * walked, tangent); }
  // The test at a sample; a sample that passes is recorded.
  bool too_close(const V3& p, double walked, const V3& tangent)
  {
    if(near(p, walked, tangent)) return true;
    grid->insert(p, line, sign * walked, tangent);
    return false;
  }
};

} // namespace internal
} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
