// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Knot relocation and removal for open polylines (degree 1): the local search that takes the
// heuristics' answers to within a few percent of the dynamic programming optimum.
//
// Removal alone cannot move a knot: a knot kept because its neighbours sit a little off the
// data's corners stays kept.  Here every knot slides, one at a time, to the candidate between
// its neighbours where the squared error is least with the two neighbouring vertices held
// (its own vertex optimal in closed form); a least-squares refit of all vertices follows each
// sweep.  Both steps can only lower the squared error.  A knot is then removed, the one whose
// removal costs least with its neighbours held, the rest slide again, and the removal is kept
// if the goal allows it (the bound still met, or the objective lower); a few next-cheapest are
// tried before giving up.
//
// A sweep reads each sample of a knot's two spans once: the moments of the left span (about
// its left end) grow as the trial knot moves right, those of the right span (about its right
// end) are the window's minus what moved.  Moments about a span's own end avoid the
// cancellation of prefix sums over the whole curve at a million samples.

#include <CGAL/Spline_approximation/internal/spline_numerics.h>

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <limits>
#include <numeric>

namespace CGAL {
namespace Spline_approximation {
namespace internal {
namespace {

// Sums over the samples of a span, about the span's end e: count, sum of d = |t - e|, of d^2,
// of P, of d P, of |P|^2.
struct Moments
{
  double n = 0, d1 = 0, d2 = 0, pp = 0;
  Eigen::RowVectorXd p, dp;
  explicit Moments(Eigen::Index D) : p(Eigen::RowVectorXd::Zero(D)), dp(Eigen::RowVectorXd::Zero(D)) {}
  // Adds (sign 1) or removes (-1) the sample at P (coordinates `stride` apart) at distance d.
  void add(double d, const double* P, Eigen::Index stride, double sign = 1)
  {
    n += sign;
    d1 += sign * d;
    d2 += sign * d * d;
    double squared = 0;
    for(Eigen::Index k = 0; k < p.size(); ++k) {
      const double x = P[k * stride];
      p[k] += sign * x;
      dp[k] += sign * d * x;
      squared += x * x;
    }
    pp += sign * squared;
  }
};

// A span's squared error as a quadratic in its end vertices xs (start) and xe (end):
// E - 2 xs.us - 2 xe.ue + ss |xs|^2 + 2 se xs.xe + ee |xe|^2.
struct Span_quadratic
{
  double E = 0, ss = 0, se = 0, ee = 0;
  Eigen::RowVectorXd us, ue;
};

// From moments about the span's start (about_start) or end; h is the span's length.  With
// f = d / h the weight of the far vertex: sum (1-f)^2, sum f (1-f), sum f^2.
void set_span_quadratic(Span_quadratic& q, const Moments& m, double h, bool about_start)
{
  const double f1 = m.d1 / h, f2 = m.d2 / (h * h);
  const double near = m.n - 2 * f1 + f2, cross = f1 - f2, far = f2;
  q.E = m.pp;
  q.se = cross;
  Eigen::RowVectorXd& u_far = about_start ? q.ue : q.us; // assigned in place: no allocation per trial
  Eigen::RowVectorXd& u_near = about_start ? q.us : q.ue;
  u_far = m.dp / h;
  u_near = m.p - u_far;
  q.ss = about_start ? near : far;
  q.ee = about_start ? far : near;
}

Span_quadratic span_quadratic(const Moments& m, double h, bool about_start)
{
  Span_quadratic q;
  set_span_quadratic(q, m, h, about_start);
  return q;
}

// The least squared error over a chain of spans between vertices, some held (the chain's
// ends) and up to three free, minimised over the free ones (a tridiagonal system, the same
// for every coordinate).  `free_at[v]` is the free vertex's index or -1; `held[v]` the value
// of a held one.  Returns +infinity where a free vertex has no sample in its spans.
struct Window
{
  static constexpr int max_free = 3;
  std::vector<Span_quadratic> spans; // span v joins vertex v and v + 1
  std::vector<int> free_at;
  std::vector<Eigen::RowVectorXd> held;
  std::size_t inner = 0; // the first of the two spans at the knot
  mutable Eigen::Matrix<double, 3, Eigen::Dynamic> G; // workspace

  double minimum(Eigen::MatrixXd* solution) const
  {
    Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
    const Eigen::Index D = spans.front().us.size();
    G.setZero(3, D);
    double c = 0;
    int F = 0;
    for(int f : free_at) F = std::max(F, f + 1);
    for(std::size_t v = 0; v < spans.size(); ++v) {
      const Span_quadratic& q = spans[v];
      const int a = free_at[v], b = free_at[v + 1];
      c += q.E;
      if(a >= 0) {
        H(a, a) += q.ss;
        G.row(a) += q.us;
      } else {
        c += -2 * held[v].dot(q.us) + q.ss * held[v].squaredNorm();
      }
      if(b >= 0) {
        H(b, b) += q.ee;
        G.row(b) += q.ue;
      } else {
        c += -2 * held[v + 1].dot(q.ue) + q.ee * held[v + 1].squaredNorm();
      }
      if(a >= 0 && b >= 0) {
        H(a, b) += q.se;
        H(b, a) += q.se;
      } else if(a >= 0) {
        G.row(a) -= q.se * held[v + 1];
      } else if(b >= 0) {
        G.row(b) -= q.se * held[v];
      } else {
        c += 2 * q.se * held[v].dot(held[v + 1]);
      }
    }
    for(int f = 0; f < F; ++f)
      if(!(H(f, f) > 0)) return std::numeric_limits<double>::infinity();
    for(int f = F; f < 3; ++f) H(f, f) = 1; // unused slots: x = 0, no effect on the minimum
    const Eigen::LDLT<Eigen::Matrix3d> ldlt(H); // fixed size: no BLAS call for a 3 x 3
    if(ldlt.info() != Eigen::Success || !(ldlt.vectorD().minCoeff() > 1e-14 * ldlt.vectorD().maxCoeff()))
      return std::numeric_limits<double>::infinity();
    if(solution) solution->resize(F, D);
    double reduction = 0;
    for(Eigen::Index d = 0; d < D; ++d) {
      const Eigen::Vector3d g = G.col(d), x = ldlt.solve(g);
      reduction += x.dot(g);
      if(solution) solution->col(d) = x.head(F);
    }
    return c - reduction; // the minimum of c - 2 x.G + x^T H x is c - G^T H^-1 G
  }
};

class Degree_one_search
{
public:
  Degree_one_search(const Problem& p) : p_(p), P_(*p.samples), D_(P_.cols()) {}

  // First sample at or after parameter u (the last span includes t = 1).
  Eigen::Index first_at(double u) const
  {
    if(u >= 1) return p_.t.size();
    return Eigen::Index(std::lower_bound(p_.t.data(), p_.t.data() + p_.t.size(), u) - p_.t.data());
  }
  double node(const std::vector<std::size_t>& kept, std::ptrdiff_t i) const // i = -1: 0, kept.size(): 1
  {
    if(i < 0) return 0.0;
    if(std::size_t(i) >= kept.size()) return 1.0;
    return p_.candidates[Eigen::Index(kept[std::size_t(i)])];
  }

  // Moments of the samples [j0, j1) about e (d = t - e about a start, e - t about an end).
  Moments moments(Eigen::Index j0, Eigen::Index j1, double e, bool about_start) const
  {
    Moments m(D_);
    for(Eigen::Index j = j0; j < j1; ++j) m.add(about_start ? p_.t[j] - e : e - p_.t[j], &P_(j, 0), P_.rows());
    return m;
  }

  // The window of knot i: vertices A (held, if any), a, u, b (free), B (held, if any); its
  // outer spans [A, a) and [b, B) filled, the two spans at the knot ([a, u), [u, b), from
  // `inner` on) left for the caller.
  Window outer_spans(const std::vector<std::size_t>& kept, const Eigen::MatrixXd& X, std::ptrdiff_t i) const
  {
    const std::ptrdiff_t K = std::ptrdiff_t(kept.size());
    Window w;
    if(i >= 1) { // vertex A = row i - 1
      const double A = node(kept, i - 2), a = node(kept, i - 1);
      w.spans.push_back(span_quadratic(moments(first_at(A), first_at(a), A, true), a - A, true));
      w.free_at.push_back(-1);
      w.held.push_back(X.row(i - 1));
    }
    for(int f = 0; f < 3; ++f) {
      w.free_at.push_back(f);
      w.held.push_back(X.row(i + f));
    }
    if(i + 2 <= K) { // vertex B = row i + 3
      const double b = node(kept, i + 1), B = node(kept, i + 2);
      w.spans.push_back(span_quadratic(moments(first_at(b), first_at(B), b, true), B - b, true));
      w.free_at.push_back(-1);
      w.held.push_back(X.row(i + 3));
    }
    w.inner = i >= 1 ? 1 : 0; // the two spans at the knot, set by the caller
    w.spans.insert(w.spans.begin() + std::ptrdiff_t(w.inner), 2, Span_quadratic());
    return w;
  }

  // One sweep: each knot moved to its best candidate between its neighbours, with its own
  // vertex and its neighbours' re-optimised and the next ones out held (X: the vertices, row
  // r at node r - 1).  Returns whether a knot moved.
  bool sweep(std::vector<std::size_t>& kept, Eigen::MatrixXd& X, std::ptrdiff_t first = 0,
             std::ptrdiff_t last = PTRDIFF_MAX) const
  {
    bool moved = false;
    const std::ptrdiff_t K = std::ptrdiff_t(kept.size());
    Eigen::MatrixXd solution, best_solution;
    for(std::ptrdiff_t i = std::max<std::ptrdiff_t>(first, 0); i < std::min(last, K); ++i) {
      const double a = node(kept, i - 1), b = node(kept, i + 1);
      const Eigen::Index ja = first_at(a), jb = first_at(b);
      Window w = outer_spans(kept, X, i);
      const std::size_t s2 = w.inner;
      const Moments whole = moments(ja, jb, b, false);
      const std::size_t c_first = i == 0 ? 0 : kept[std::size_t(i - 1)] + 1;
      const std::size_t c_end = i + 1 == K ? std::size_t(p_.candidates.size()) : kept[std::size_t(i + 1)];
      const std::size_t current = kept[std::size_t(i)];
      double best = std::numeric_limits<double>::infinity(), here = best;
      std::size_t best_c = current;
      // Evaluates the candidates lo, lo + stride, ... below hi, and the current one, from the
      // moments `from` (the samples before `from.j` moved left: valid for candidates from
      // `from.c` on).  Keeps, for the next level, the moments at the evaluated place before the best.
      struct Place
      {
        std::size_t c;
        Eigen::Index j;
        Moments left, right;
      };
      Place start{c_first, ja, Moments(D_), whole}, before_best = start;
      auto scan = [&](std::size_t lo, std::size_t hi, std::size_t stride, const Place& from) {
        Place at = from, previous = from;
        for(std::size_t c = lo; c < hi;) {
          const double u = p_.candidates[Eigen::Index(c)];
          for(; at.j < jb && p_.t[at.j] < u; ++at.j) {
            at.left.add(p_.t[at.j] - a, &P_(at.j, 0), P_.rows());
            at.right.add(b - p_.t[at.j], &P_(at.j, 0), P_.rows(), -1);
          }
          at.c = c;
          set_span_quadratic(w.spans[s2], at.left, u - a, true);
          set_span_quadratic(w.spans[s2 + 1], at.right, b - u, false);
          const double e = w.minimum(&solution);
          if(c == current) here = e;
          if(e < best) {
            best = e;
            best_c = c;
            best_solution = solution;
            before_best = previous;
          }
          previous = at;
          const std::size_t next = c + stride;
          c = (c < current && current < next) ? current : next;
        }
      };
      // Coarse to fine: at most `per_level` trials per level, each level around the best so far.
      constexpr std::size_t per_level = 64;
      std::size_t lo = c_first, hi = c_end;
      for(Place from = start;;) {
        const std::size_t stride = std::max<std::size_t>(1, (hi - lo + per_level - 1) / per_level);
        scan(lo, hi, stride, from);
        if(stride == 1) break;
        lo = std::max(c_first, best_c >= stride ? best_c - stride + 1 : 0);
        hi = std::min(c_end, best_c + stride);
        from = before_best;
        lo = std::max(lo, from.c); // its moments hold for candidates from its own on
      }
      // Move only for a gain beyond rounding (the window's sums carry relative error ~1e-13).
      if(best_c != current && std::isfinite(best) && !(best >= here - 1e-12 * std::abs(here))) {
        kept[std::size_t(i)] = best_c;
        X.middleRows(i, 3) = best_solution;
        moved = true;
      }
    }
    return moved;
  }

  // The squared error added by removing each knot, its two neighbours' vertices re-optimised
  // and the next ones out held (the same local model as the sweep).
  std::vector<double> removal_costs(const std::vector<std::size_t>& kept, const Eigen::MatrixXd& X) const
  {
    const std::ptrdiff_t K = std::ptrdiff_t(kept.size());
    std::vector<double> cost(kept.size());
    for(std::ptrdiff_t i = 0; i < K; ++i) {
      const double a = node(kept, i - 1), u = node(kept, i), b = node(kept, i + 1);
      const Eigen::Index ja = first_at(a), ju = first_at(u), jb = first_at(b);
      Window w = outer_spans(kept, X, i);
      const std::size_t s2 = w.inner;
      w.spans[s2] = span_quadratic(moments(ja, ju, a, true), u - a, true);
      w.spans[s2 + 1] = span_quadratic(moments(ju, jb, a, true), b - u, true);
      const double with = w.minimum(nullptr);
      // Without the knot: one span from a to b, the knot's vertex gone from the chain.
      w.spans.erase(w.spans.begin() + std::ptrdiff_t(s2) + 1);
      w.spans[s2] = span_quadratic(moments(ja, jb, a, true), b - a, true);
      const std::size_t v = s2 + 1; // the knot's vertex in the chain
      w.free_at.erase(w.free_at.begin() + std::ptrdiff_t(v));
      w.held.erase(w.held.begin() + std::ptrdiff_t(v));
      w.free_at[v] = 1;
      cost[std::size_t(i)] = w.minimum(nullptr) - with;
    }
    return cost;
  }

  // The squared error and max error of the polyline (kept, X) over the samples in [u0, u1).
  std::pair<double, double> errors_between(const std::vector<std::size_t>& kept, const Eigen::MatrixXd& X, double u0,
                                           double u1) const
  {
    double total = 0, largest = 0;
    std::ptrdiff_t span = std::ptrdiff_t(std::lower_bound(kept.begin(), kept.end(), 0, [&](std::size_t c, int) {
                            return p_.candidates[Eigen::Index(c)] <= u0;
                          }) - kept.begin()); // the span [node(span - 1), node(span)) holds u0
    for(Eigen::Index j = first_at(u0), end = first_at(u1); j < end; ++j) {
      const double t = p_.t[j];
      while(t >= node(kept, span) && std::size_t(span) < kept.size()) ++span;
      const double a = node(kept, span - 1), b = node(kept, span);
      const double e = (P_.row(j) - X.row(span) - (t - a) / (b - a) * (X.row(span + 1) - X.row(span))).squaredNorm();
      total += e;
      largest = std::max(largest, e);
    }
    return {total, std::sqrt(largest)};
  }

private:
  const Problem& p_;
  const Eigen::MatrixXd& P_;
  Eigen::Index D_;
};

// Sweeps and refits until the squared error falls by less than 1e-3 relative (later sweeps
// move knots by a candidate or two: they did not change a knot count in our trials) or after eight
// sweeps; the fit returned is a least-squares fit on its knots.
Spline_fit relocated(const Problem& p, const Degree_one_search& search, Spline_fit fit, double lambda)
{
  for(int round = 0; round < 8 && !fit.kept.empty(); ++round) {
    std::vector<std::size_t> kept = fit.kept;
    Eigen::MatrixXd X = fit.spline.control_points;
    if(!search.sweep(kept, X)) break;
    Spline_fit next = finish(p, kept, lambda, Sample_errors::summary_only);
    const bool gain = next.squared_error < fit.squared_error * (1 - 1e-3);
    if(next.squared_error < fit.squared_error) fit = std::move(next);
    if(!gain) break;
  }
  return fit;
}

} // namespace

Spline_fit relocate_and_remove(const Problem& p, const Goal& goal, Spline_fit fit)
{
  if(p.degree != 1 || p.closed || fit.kept.empty()) return fit;
  const Degree_one_search search(p);
  auto acceptable = [&](const Spline_fit& f) { return goal.is_bound() ? goal.met(f) : true; };
  {
    Spline_fit moved = relocated(p, search, fit, goal.lambda);
    if(acceptable(moved) || !acceptable(fit)) fit = std::move(moved);
  }
  if(goal.is_bound() && !goal.met(fit)) return fit; // fewer knots cannot help
  // Each removal is first judged on a local model: the knot's neighbours within `reach` slide
  // (the vertices beyond held), which is itself a polyline on the remaining knots, its error
  // exact where it changed.  Only a removal whose local model meets the goal is refitted
  // globally (which can only lower the squared error): a refused removal costs the samples of
  // a few spans, not a fit of all of them.
  constexpr std::ptrdiff_t reach = 6;
  const double n = double(p.t.size());
  while(!fit.kept.empty()) {
    const std::vector<double> cost = search.removal_costs(fit.kept, fit.spline.control_points);
    std::vector<std::size_t> order(cost.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return cost[a] < cost[b]; });
    bool removed = false;
    for(std::size_t q = 0; q < order.size() && !removed; ++q) {
      const std::ptrdiff_t i = std::ptrdiff_t(order[q]);
      std::vector<std::size_t> kept = fit.kept;
      kept.erase(kept.begin() + i);
      Eigen::MatrixXd X(fit.spline.control_points.rows() - 1, fit.spline.control_points.cols());
      X << fit.spline.control_points.topRows(i + 1), fit.spline.control_points.bottomRows(X.rows() - i - 1);
      for(int pass = 0; pass < 4; ++pass)
        if(!search.sweep(kept, X, i - reach, i + reach)) break;
      // Knots outside [i - reach, i + reach) stayed: the change lies within these nodes.
      const double u0 = search.node(kept, i - reach - 3), u1 = search.node(kept, i + reach + 2);
      const auto before = search.errors_between(fit.kept, fit.spline.control_points, u0, u1);
      const auto after = search.errors_between(kept, X, u0, u1);
      const double squared = fit.squared_error - before.first + after.first;
      const bool promising = goal.max_error  ? after.second <= *goal.max_error
                             : goal.rms_error ? squared <= *goal.rms_error * *goal.rms_error * n
                                              : squared + goal.lambda * double(kept.size()) < fit.objective;
      if(!promising) continue;
      Spline_fit trial = relocated(p, search, finish(p, kept, goal.lambda, Sample_errors::summary_only), goal.lambda);
      if(goal.is_bound() ? goal.met(trial) : trial.objective < fit.objective) {
        fit = std::move(trial);
        removed = true;
      }
    }
    if(!removed) break;
  }
  return fit;
}

} // namespace internal
} // namespace Spline_approximation
} // namespace CGAL
