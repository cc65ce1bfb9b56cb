// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The exact optimum of a closed polyline (degree 1, periodic), by dynamic programming.
//
// A closed polyline has no first vertex: the vertex x0 at its first knot j0 belongs to the first
// segment and to the closing one.  With j0 fixed, the value at node i is a function of two
// vertices, x0 and x_i: the least squared error over the samples from j0 to node i, a minimum
// of quadratics a00 |x0|^2 + 2 a01 x0.x_i + a11 |x_i|^2 + b0.x0 + b1.x_i + c (one per surviving
// path; isotropic in the D coordinates, so a 2 x 2 matrix each).  A step eliminates the previous
// vertex in closed form, as in the open DP; the closing segment ends at j0 one period on, where
// x_i = x0 is substituted and x0 minimised out.
//
// Which j0: an optimum of two knots or more (fewer is a constant, tried apart) has a knot in
// every arc of candidates that one segment cannot span within the bound, since a segment is an
// affine function of t whose error is at least the least-squares line's on the samples it covers.
// The shortest such arc [s, s + w) is found first; j0 runs over it as the first knot in the arc,
// the other knots over the rest of the circle (before s one period on).
//
// Pruning, all of it exact (a path is dropped only where it provably cannot be part of an answer
// within the bound: the heuristic's objective in penalty mode, the budget n rms^2 in bound mode):
// - a lower bound on what follows node i: the restriction of the closed polyline to the samples
//   from node i to j0 one period on is an open polyline with free end vertices, whose least cost
//   an open DP run backwards gives for every node at once (closed_curve_bounds.cpp);
// - a path is dropped where another lies below it wherever it is within the bound less that lower
//   bound (closed_curve_pairs.cpp): comparing everywhere, x0's dimensions keep lists long.

#include "closed_curve_dp.h"

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Spline_approximation {
namespace internal {
namespace {

using namespace closed_dp;

// Where a pushed path goes: the list at node u (none: not wanted), the bounds on its completion
// with at most r more knots, and the most the whole path may be worth.
struct Target
{
  Pair_quadratics* list = nullptr;
  const Completion_bounds* rest = nullptr;
  Index u = 0;
  std::size_t r = 0;
  double bound = 0;
};

// Pushes the paths Q at node `from` to the nodes from + 1 .. last (target(u)), each charged
// `knot_cost`, and closes them at node `end` (none if negative) with close(value, index).
// Q null: the start, the one-knot path at `from` worth `start_cost`.  Nothing is pushed past a
// segment that cannot be within `bound` on its own.  `tag` is stored as the new paths' origin.
template <class To, class Close>
void push(const Circle& circle, const Pair_quadratics* Q, Index from, Index last, Index end, double start_cost,
          double knot_cost, double bound, int tag, To target, Close close)
{
  if(Q && Q->size() == 0) return;
  const std::size_t count = Q ? Q->size() : 1, D = std::size_t(circle.D);
  Segment_sums sums = circle.sums_from(from, true);
  std::vector<double> nb(2 * D), record(Pair_record::size(D));
  Segment s;
  for(Index u = from + 1;; ++u) {
    const bool closing = u > last;
    if(closing && end < 0) break;
    const Index node = closing ? end : u;
    circle.reach(sums, node);
    // Every later node spans these samples and more.
    if(sums.line_error() > bound + 1e-9 * sums.pp) break;
    const Target to = closing ? Target() : target(u);
    if(!closing && !to.list) continue;
    s.set(sums, circle.gap(from, node));
    circle.count_work(count);
    for(std::size_t k = 0; k < count; ++k) {
      double n00, n01, n11, nc;
      if(!Q) { // the first segment itself, in (x0, x)
        n00 = s.al, n01 = s.be, n11 = s.ga, nc = s.q + start_cost;
        for(std::size_t d = 0; d < D; ++d) nb[d] = -2 * s.u[d], nb[D + d] = -2 * s.v[d];
      } else { // the previous vertex y minimised out: y = -(2 a01 x0 + 2 be x + B) / (2 A)
        const double* q = Q->record(k, D);
        const double* b = q + 5;
        const double A = q[2] + s.al, a01 = q[1];
        const bool solve = A > 0; // else y touches no sample: it drops out
        double B2 = 0;
        for(std::size_t d = 0; d < D; ++d) {
          const double B = b[D + d] - 2 * s.u[d];
          B2 += B * B;
          nb[d] = solve ? b[d] - (a01 / A) * B : b[d];
          nb[D + d] = -2 * s.v[d] - (solve ? (s.be / A) * B : 0.0);
        }
        n00 = q[0] - (solve ? a01 * a01 / A : 0.0);
        n01 = solve ? -a01 * s.be / A : 0.0;
        n11 = s.ga - (solve ? s.be * s.be / A : 0.0);
        nc = q[3] + s.q - (solve ? B2 / (4 * A) : 0.0);
      }
      if(closing) { // x = x0, then x0 minimised out
        const double a = n00 + 2 * n01 + n11;
        double s2 = 0;
        for(std::size_t d = 0; d < D; ++d) s2 += (nb[d] + nb[D + d]) * (nb[d] + nb[D + d]);
        close(a > 0 ? nc - s2 / (4 * a) : nc, k);
        continue;
      }
      Pair_record::make(n00, n01, n11, nb.data(), nc + knot_cost, D, record.data());
      const double limit = to.bound - to.rest->at(u, to.r);
      if(record[4] > limit || to.rest->exceeds(u, to.r, record.data(), to.bound)) continue;
      add_pair(circle, *to.list, record.data(), limit, tag, Q ? int(k) : -1);
    }
    if(closing) break;
  }
}

// The knots of the path ending at (node, index), node k being candidate j0 + k: lists(back,
// node) is the list of that node `back` steps before the end.  Candidate indices in [0, m),
// increasing.
template <class Lists>
std::vector<std::size_t> knots_of(const Lists& lists, Index j0, Index m, int node, int index)
{
  std::vector<std::size_t> kept;
  for(std::size_t back = 0;; ++back) {
    kept.push_back(std::size_t((j0 + node) % m));
    if(node == 0) break;
    const Pair_quadratics& Q = lists(back, node);
    const int next = Q.from_node[std::size_t(index)];
    index = Q.from_index[std::size_t(index)];
    node = next;
  }
  std::sort(kept.begin(), kept.end());
  return kept;
}

// The best path closing at the end, among those of one start j0.
struct Best_closing
{
  double value = std::numeric_limits<double>::infinity();
  int node = -1, index = -1;
};

// Penalty mode: the least squared error + lambda * #knots, below `best` (the heuristic's answer
// or the constant).
Spline_fit least_objective(const Problem& p, const Circle& circle, double lambda, double slack, Spline_fit best)
{
  const Index m = circle.m;
  double bound = best.objective + slack;
  const auto [s, w] = knot_arc(circle, bound);
  double best_value = std::numeric_limits<double>::infinity();
  std::vector<std::size_t> best_kept;
  for(Index j0 = s; j0 < s + w; ++j0) {
    const Index nodes = s + m - j0; // node k is candidate j0 + k, up to the last before s one period on
    std::vector<Pair_quadratics> V(static_cast<std::size_t>(nodes));
    const Completion_bounds rest(circle, j0, s + m - 1, j0 + m, lambda, 0, bound);
    Best_closing closing;
    for(Index k = 0; k < nodes; ++k)
      push(circle, k == 0 ? nullptr : &V[std::size_t(k)], j0 + k, s + m - 1, k == 0 ? -1 : j0 + m, lambda, lambda,
           bound, int(k), [&](Index u) { return Target{&V[std::size_t(u - j0)], &rest, u, 0, bound}; },
           [&](double value, std::size_t index) {
             if(value < closing.value) closing = {value, int(k), int(index)};
           });
    if(closing.value < best_value) {
      best_value = closing.value;
      bound = std::min(bound, best_value + slack); // later starts need only beat it
      auto lists = [&](std::size_t, int node) -> const Pair_quadratics& { return V[std::size_t(node)]; };
      best_kept = knots_of(lists, j0, m, closing.node, closing.index);
    }
  }
  if(best_kept.empty()) return best; // nothing beat the heuristic beyond roundoff
  Spline_fit fit = finish(p, best_kept, lambda);
  return fit.objective <= best.objective ? fit : best;
}

// Bound mode: the fewest knots with the squared error within `budget`, then the least error;
// `best` (meeting the bound) caps the knot count.
Spline_fit fewest_knots(const Problem& p, const Goal& goal, const Circle& circle, double budget, double slack,
                        Spline_fit best)
{
  const Index m = circle.m;
  // A list per candidate and knot count, twice (the completions', the paths'): past this many the
  // memory alone (tens of bytes each, empty) would be the limit.
  constexpr double most_lists = double(std::size_t(1) << 22);
  if(double(best.kept.size()) * double(m) > most_lists)
    throw Invalid_input("spline fit: the dynamic programming optimum of this closed curve is not computable here (" +
                        std::to_string(best.kept.size()) + " knots may be needed over " + std::to_string(m) +
                        " candidates: a list per candidate and knot count); use fewer candidate knots");
  const double bound = budget + slack;
  const auto [s, w] = knot_arc(circle, bound);
  for(Index j0 = s; j0 < s + w; ++j0) {
    const Index nodes = s + m - j0;
    // Paths at a node after j0 have two knots or more: at most best.kept.size() - 2 follow.
    const Completion_bounds rest(circle, j0, s + m - 1, j0 + m, 0.0, best.kept.size() - 1, bound);
    // layers[L][k]: paths of L + 2 knots (j0 and L + 1 more) ending at node k.
    std::vector<std::vector<Pair_quadratics>> layers;
    for(std::size_t K = 1; K <= best.kept.size(); ++K) {
      // Layer K - 1 (K + 1 knots) from layer K - 2 (the start for K = 1); the paths of layer
      // K - 2 closed, with K knots.
      layers.emplace_back(static_cast<std::size_t>(nodes));
      const bool extend = K < best.kept.size(); // paths of more knots than the best cannot win
      Best_closing closing;
      for(Index k = 0; k < (K == 1 ? 1 : nodes); ++k)
        push(circle, K == 1 ? nullptr : &layers[K - 2][std::size_t(k)], j0 + k, s + m - 1, K == 1 ? -1 : j0 + m, 0.0,
             0.0, bound, int(k),
             [&](Index u) {
               if(!extend) return Target();
               return Target{&layers[K - 1][std::size_t(u - j0)], &rest, u, best.kept.size() - (K + 1), bound};
             },
             [&](double value, std::size_t index) {
               if(value < closing.value) closing = {value, int(k), int(index)};
             });
      if(closing.value <= bound) {
        const std::size_t top = K - 2; // the closed paths' layer
        auto lists = [&](std::size_t back, int node) -> const Pair_quadratics& {
          return layers[top - back][std::size_t(node)];
        };
        Spline_fit fit = finish(p, knots_of(lists, j0, m, closing.node, closing.index), goal.lambda);
        // Within the budget up to roundoff: the refit decides (its errors are the ones reported).
        if(goal.met(fit)) {
          if(better(fit, best, goal)) best = std::move(fit);
          break;
        }
      }
      bool alive = false;
      for(const Pair_quadratics& Q : layers[K - 1]) alive = alive || Q.size() > 0;
      if(!alive) break;
    }
  }
  return best;
}

// The heuristic answer the DP starts from (its bound): greedy removal, from the coarse-to-fine
// start on many candidates as fit_spline's default does (from every candidate it would take
// minutes on a hundred thousand), then relocated.
Spline_fit heuristic_answer(const Problem& p, const Goal& goal)
{
  constexpr Eigen::Index coarse_start_above = 4096;
  if(p.candidates.size() <= coarse_start_above) return relocate_and_remove(p, goal, greedy_removal(p, goal));
  const std::vector<std::size_t> start = coarse_start(p, goal, 0.5);
  return relocate_and_remove(p, goal, greedy_removal(p, goal, &start));
}

} // namespace

Spline_fit closed_dynamic_programming(const Problem& p, const Goal& goal, std::size_t work_limit)
{
  const Circle circle(p, work_limit);
  // Slack on the pruning bounds so that roundoff never prunes the optimum itself; the heuristics'
  // objectives are sums over the samples as given, the DP's over the centred ones.
  const double slack = 1e-9 * circle.centred_squared_norm() + 1e-12 * p.samples->squaredNorm();
  const Spline_fit constant = finish(p, {}, goal.lambda); // no knot or one: a constant either way
  if(circle.m < 2) return constant;
  if(!goal.is_bound()) {
    Spline_fit heuristic = heuristic_answer(p, goal);
    return least_objective(p, circle, goal.lambda, slack,
                           constant.objective <= heuristic.objective ? constant : std::move(heuristic));
  }
  // The heuristic's knot count caps the layers; nothing meets the bound if every candidate does not.
  if(goal.met(constant)) return constant;
  Spline_fit best = heuristic_answer(p, goal);
  if(!goal.met(best)) {
    std::vector<std::size_t> every(static_cast<std::size_t>(circle.m));
    for(std::size_t i = 0; i < every.size(); ++i) every[i] = i;
    best = finish(p, every, goal.lambda);
    if(!goal.met(best)) return best;
  }
  const double budget = double(p.t.size()) * *goal.rms_error * *goal.rms_error;
  return fewest_knots(p, goal, circle, budget, slack, std::move(best));
}

} // namespace internal
} // namespace Spline_approximation
} // namespace CGAL
