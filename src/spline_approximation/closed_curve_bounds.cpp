// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The closed-curve dynamic programming's bounds (see exact_optimum_closed.cpp): the arc that
// must hold a knot, and the least cost of what follows a node, by an open DP run backwards
// (quadratics in one vertex, as in exact_optimum.cpp), itself pruned by a cruder bound on what
// precedes the node (one line per segment, no vertex shared).

#include "closed_curve_dp.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace CGAL {
namespace Spline_approximation {
namespace internal {
namespace closed_dp {

Circle::Circle(const Problem& p, std::size_t work_limit)
  : n(p.t.size()), m(p.candidates.size()), D(p.samples->cols()),
    X_((p.samples->rowwise() - p.samples->colwise().mean()).transpose()), t_(p.t), c_(p.candidates),
    first_(std::size_t(m)), work_limit_(work_limit)
{
  for(Index u = 0; u < m; ++u)
    first_[std::size_t(u)] = Index(std::lower_bound(t_.data(), t_.data() + n, c_[Eigen::Index(u)]) - t_.data());
}

double Circle::gap(Index from, Index to) const
{
  const Index pf = floor_div(from, m), pt = floor_div(to, m);
  return (c_[Eigen::Index(to - pt * m)] - c_[Eigen::Index(from - pf * m)]) + double(pt - pf);
}

Segment_sums Circle::sums_from(Index start, bool forward) const
{
  return Segment_sums(std::size_t(D), start, first_sample(start) - (forward ? 0 : 1), forward);
}

void Circle::reach(Segment_sums& sums, Index end) const
{
  if(sums.count > 0) sums.move_end(sums.forward ? gap(sums.end, end) : gap(end, sums.end));
  sums.end = end;
  const Index stop = first_sample(end) - (sums.forward ? 0 : 1); // backward: down to the sample at end
  const Index visits = sums.forward ? stop - sums.next : sums.next - stop;
  sample_visits_ += std::size_t(std::max<Index>(visits, 0)) + 3; // a step (its bookkeeping, the line's error) as 3 samples
  if(sample_visits_ > work_limit_)
    throw Invalid_input("spline fit: the dynamic programming optimum of this closed curve is not computable here "
                        "(more than " + std::to_string(work_limit_) + " sample visits: long segments fit "
                        "within the bound and many candidates may start the curve); use fewer candidate knots");
  if(visits <= 0) return;
  // t of sample r minus candidate u, the whole periods apart added last: no roundoff on t within a period.
  auto offset = [&](Index r, Index u) {
    const Index pr = floor_div(r, n), pu = floor_div(u, m);
    return (t_[Eigen::Index(r - pr * n)] - c_[Eigen::Index(u - pu * m)]) + double(pr - pu);
  };
  for(Index r = sums.next; r != stop; r += sums.forward ? 1 : -1) {
    const double from_start = offset(r, sums.start), from_end = offset(r, end);
    sums.add(sums.forward ? from_start : -from_start, sums.forward ? -from_end : from_end,
             X_.col(Eigen::Index(r - floor_div(r, n) * n)).data());
  }
  sums.next = stop;
}

void Circle::count_work(std::size_t units) const
{
  work_ += units;
  if(work_ > work_limit_)
    throw Invalid_input("spline fit: the dynamic programming optimum of this closed curve is not computable here "
                        "(more than " + std::to_string(work_limit_) + " path comparisons); use fewer candidate knots");
}

std::pair<Index, Index> knot_arc(const Circle& circle, double bound)
{
  Index best_s = 0, best_w = circle.m;
  // Starts h apart miss the shortest arc by less than h (an arc holding one that must hold a knot
  // must too): a coarse pass, then one with h a sixteenth of the arc found, so that the search
  // costs about 32 m steps, not m times the arc.
  for(int pass = 0; pass < 2; ++pass) {
    const Index h = std::max<Index>(1, best_w / 16);
    for(Index s = 0; s < circle.m && best_w > 1; s += h) {
      // A segment over no knot of [s, s + w) spans the samples from candidate s - 1 to s + w; it
      // joins two distinct knots, so w <= m - 2.
      Segment_sums sums = circle.sums_from(s - 1, true);
      for(Index w = 1; w < best_w && w <= circle.m - 2; ++w) {
        circle.reach(sums, s + w);
        if(sums.line_error() > bound + 1e-9 * sums.pp) {
          best_s = s, best_w = w;
          break;
        }
      }
    }
  }
  return {best_s, best_w};
}

namespace {

typedef Vertex_quadratics Quadratics;

// Adds the quadratic unless it is worth more than `limit` everywhere or another lies below it
// wherever it is within `limit` (the only place a path through it can matter: any completion
// costs at least what `limit` leaves), and drops the old ones it lies below likewise.
void add(const Circle& circle, Quadratics& Q, double a, const double* b, double c, double limit)
{
  const std::size_t D = std::size_t(circle.D);
  if(vertex_minimum(a, b, c, D) > limit) return;
  auto below = [&](double pa, const double* pb, double pc, double qa, const double* qb, double qc) {
    return vertex_below_where_within(pa, pb, pc, qa, qb, qc, limit, D);
  };
  for(std::size_t r = 0; r < Q.size(); ++r)
    if(below(Q.a[r], &Q.b[D * r], Q.c[r], a, b, c)) {
      circle.count_work(r + 1);
      return;
    }
  std::size_t w = 0;
  for(std::size_t r = 0; r < Q.size(); ++r) {
    if(below(a, b, c, Q.a[r], &Q.b[D * r], Q.c[r])) continue;
    Q.a[w] = Q.a[r]; Q.c[w] = Q.c[r];
    std::copy_n(&Q.b[D * r], D, &Q.b[D * w]);
    ++w;
  }
  Q.a.resize(w); Q.c.resize(w); Q.b.resize(D * w);
  Q.a.push_back(a); Q.c.push_back(c);
  Q.b.insert(Q.b.end(), b, b + D);
  circle.count_work(2 * Q.size());
}

// The least cost from j0 to each node u in (j0, last] of a fit by one line per segment, each
// segment's error its line's: a lower bound for the polyline on the same knots.  [q][u - j0]:
// with at most q knots strictly between j0 and u if layered (`layers` of them), any number if not.
std::vector<std::vector<double>> line_prefix_bounds(const Circle& circle, Index j0, Index last, double knot_cost,
                                                    std::size_t layers, double bound)
{
  const std::size_t L = std::max<std::size_t>(layers, 1), N = std::size_t(last - j0 + 1);
  const double none = std::numeric_limits<double>::infinity();
  std::vector<std::vector<double>> F(L, std::vector<double>(N, none));
  for(Index v = j0; v < last; ++v) {
    const std::size_t i = std::size_t(v - j0);
    double least_here = v == j0 ? knot_cost : none;
    for(std::size_t q = 0; q < L; ++q) least_here = std::min(least_here, F[q][i]);
    if(least_here > bound) continue;
    Segment_sums sums = circle.sums_from(v, true);
    for(Index u = v + 1; u <= last; ++u) {
      circle.reach(sums, u);
      const double e = sums.line_error();
      if(least_here + e > bound + 1e-9 * sums.pp) break; // and every longer segment
      const std::size_t to = std::size_t(u - j0);
      if(v == j0) F[0][to] = std::min(F[0][to], knot_cost + e + knot_cost);
      else
        for(std::size_t q = 0; q < L; ++q) {
          const std::size_t up = layers > 0 ? q + 1 : 0;
          if(up < L) F[up][to] = std::min(F[up][to], F[q][i] + e + knot_cost);
        }
    }
  }
  for(std::size_t q = 1; q < L; ++q)
    for(std::size_t i = 0; i < N; ++i) F[q][i] = std::min(F[q][i], F[q - 1][i]); // at most q
  return F;
}

} // namespace

Completion_bounds::Completion_bounds(const Circle& circle, Index j0, Index last, Index end, double knot_cost,
                                     std::size_t layers, double bound)
  : circle_(circle), j0_(j0), layered_(layers > 0), D_(std::size_t(circle.D))
{
  const std::size_t L = std::max<std::size_t>(layers, 1), D = D_, N = std::size_t(last - j0 + 1);
  // The backward DP keeps only what a path from j0 could complete within the bound: its value
  // plus the prefix's line bound at most `bound`.  Layered, r knots inside after u leave at most
  // layers - 1 - r between j0 and u (layers = the most knots - 1).
  const std::vector<std::vector<double>> prefix = line_prefix_bounds(circle, j0, last, knot_cost, layers, bound);
  auto limit = [&](std::size_t r, Index u) { return bound - prefix[layered_ ? L - 1 - r : 0][std::size_t(u - j0)]; };
  // lists[r][v - j0]: the open polylines from node v to the end (r knots strictly inside if
  // layered), as quadratics in the vertex at v; the end's at index 0 (j0 is no node here).
  std::vector<std::vector<Quadratics>>& lists = lists_;
  lists.assign(L, std::vector<Quadratics>(N));
  auto at = [&](std::size_t r, Index v) -> Quadratics& { return lists[r][std::size_t(v == end ? 0 : v - j0)]; };
  at(0, end).a = {0};
  at(0, end).c = {0};
  at(0, end).b.assign(D, 0.0);
  std::vector<double> nb(D);
  Segment seg;
  for(Index v = end; v > j0 + 1; v = v == end ? last : v - 1) // no knot between last and the end
    for(std::size_t r = 0; r < L; ++r) {
      const Quadratics& Q = at(r, v);
      if(Q.size() == 0) continue;
      // The knot at v counts unless v is the end; layered, it moves the paths one layer up.
      const double cost = v == end ? 0.0 : knot_cost;
      const std::size_t up = layered_ && v != end ? r + 1 : r;
      if(up >= L) continue;
      Segment_sums sums = circle.sums_from(v, false);
      for(Index u = v - 1; u > j0; --u) { // the segment from u to v, walked backwards
        circle.reach(sums, u);
        if(sums.line_error() > bound + 1e-9 * sums.pp) break; // and every longer one
        if(u > last) continue; // not a knot: the segment goes on
        seg.set(sums, circle.gap(u, v)); // its start vertex is v's: x_v eliminated
        circle.count_work(Q.size());
        for(std::size_t k = 0; k < Q.size(); ++k) {
          const double* b = &Q.b[D * k];
          const double A = Q.a[k] + seg.al;
          double B2 = 0;
          for(std::size_t d = 0; d < D; ++d) {
            const double B = b[d] - 2 * seg.u[d];
            B2 += B * B;
            nb[d] = -2 * seg.v[d] - (A > 0 ? (seg.be / A) * B : 0.0);
          }
          const double na = seg.ga - (A > 0 ? seg.be * seg.be / A : 0.0);
          const double nc = Q.c[k] + seg.q - (A > 0 ? B2 / (4 * A) : 0.0) + cost;
          add(circle, at(up, u), na, nb.data(), nc, limit(up, u));
        }
      }
    }
  const double none = std::numeric_limits<double>::infinity();
  least_.assign(L, std::vector<double>(N, none));
  for(std::size_t r = 0; r < L; ++r)
    for(std::size_t i = 1; i < N; ++i) {
      const Quadratics& Q = lists[r][i];
      for(std::size_t k = 0; k < Q.size(); ++k)
        least_[r][i] = std::min(least_[r][i], vertex_minimum(Q.a[k], &Q.b[D * k], Q.c[k], D));
      if(r > 0) least_[r][i] = std::min(least_[r][i], least_[r - 1][i]); // at most r knots
    }
}

bool Completion_bounds::exceeds(Index u, std::size_t r, const double* record, double bound) const
{
  const std::size_t D = D_, i = std::size_t(u - j0_);
  const double* b = record + 5;
  double sum[16]; // b1 plus the completion's linear term, for D <= 16 (else no test)
  if(D > 16) return false;
  for(std::size_t layer = 0; layer <= (layered_ ? r : 0); ++layer) {
    const Vertex_quadratics& Q = lists_[layer][i];
    circle_.count_work(Q.size());
    for(std::size_t k = 0; k < Q.size(); ++k) {
      for(std::size_t d = 0; d < D; ++d) sum[d] = b[D + d] + Q.b[D * k + d];
      if(!(pair_minimum(record[0], record[1], record[2] + Q.a[k], b, sum, record[3] + Q.c[k], D) > bound)) return false;
    }
  }
  return true;
}

} // namespace closed_dp
} // namespace internal
} // namespace Spline_approximation
} // namespace CGAL
