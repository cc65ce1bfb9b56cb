// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The degree-1 local search's model (knot_relocation.cpp, knot_exchange.cpp): a polyline's
// knots as unwrapped candidate indices, the squared error of a few spans as a quadratic in their
// vertices from the spans' moments, and a knot's sweep to its best candidate between its
// neighbours.
//
// A sweep takes the moments of the left span (about its left end) as the trial knot moves
// right, those of the right span (about its right end) as the window's minus what moved, from
// sums over blocks of samples (sample_moments.h): moments about a span's own end, without the
// cancellation of prefix sums over the whole curve at a million samples.

#ifndef CGAL_SPLINE_APPROXIMATION_DEGREE_ONE_SEARCH_H
#define CGAL_SPLINE_APPROXIMATION_DEGREE_ONE_SEARCH_H

#include <CGAL/Spline_approximation/internal/spline_numerics.h>

#include "periodic_index.h"
#include "sample_moments.h"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Spline_approximation {
namespace internal {

// A span's squared error as a quadratic in its end vertices xs (start) and xe (end):
// E - 2 xs.us - 2 xe.ue + ss |xs|^2 + 2 se xs.xe + ee |xe|^2.
struct Span_quadratic
{
  double E = 0, ss = 0, se = 0, ee = 0;
  Eigen::RowVectorXd us, ue;
};

// From moments about the span's start (about_start) or end; h is the span's length.  With
// f = d / h the weight of the far vertex: sum (1-f)^2, sum f (1-f), sum f^2.
inline void set_span_quadratic(Span_quadratic& q, const Moments& m, double h, bool about_start)
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

inline Span_quadratic span_quadratic(const Moments& m, double h, bool about_start)
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

// Knots as unwrapped candidate indices ("virtual"): increasing; on a closed curve they may leave
// [0, m) by a period (index C stands for candidate C mod m, one period, m, further on), so a
// knot can slide across the seam.  Samples alike: index J is sample J mod n, one period on.
typedef std::vector<Index> Knots; // periodic_index.h

class Degree_one_search
{
public:
  Degree_one_search(const Problem& p)
    : p_(p), P_(*p.samples), D_(P_.cols()), n_(p.t.size()), m_(p.candidates.size()), closed_(p.closed),
      blocks_(p.t, P_), tie_unit_(squared_error_tie * squared_spread(P_))
  {}

  // Squared errors over `samples` samples closer than this are a tie (spline_numerics.h): the
  // choice among them goes by index, so that a moved or scaled copy chooses alike.
  double tie(Index samples) const { return tie_unit_ * double(std::max<Index>(samples, 1)); }
  // The samples of the spans from vertex v0 to vertex v1 (those that exist).
  Index samples_between(const Knots& vk, Index v0, Index v1) const
  {
    if(!closed_) v0 = std::max<Index>(v0, -1), v1 = std::min<Index>(v1, Index(vk.size()));
    return first_at(node(vk, v1)) - first_at(node(vk, v0));
  }

  Knots unwrapped(const std::vector<std::size_t>& kept) const { return Knots(kept.begin(), kept.end()); }
  // Back to increasing indices in [0, m), the vertices' rows turned with them.
  void wrap(const Knots& vk, std::vector<std::size_t>& kept, Eigen::MatrixXd& X) const
  {
    kept.resize(vk.size());
    for(std::size_t i = 0; i < vk.size(); ++i) kept[i] = std::size_t(vk[i] - floor_div(vk[i], m_) * m_);
    if(!closed_) return;
    const std::size_t first = std::size_t(std::min_element(kept.begin(), kept.end()) - kept.begin());
    std::rotate(kept.begin(), kept.begin() + std::ptrdiff_t(first), kept.end());
    // The vertex of knot i is row i + 1 (mod K): rows turn by the same amount.
    Eigen::MatrixXd turned(X.rows(), X.cols());
    for(Eigen::Index r = 0; r < X.rows(); ++r) turned.row(r) = X.row((r + Eigen::Index(first)) % X.rows());
    X = std::move(turned);
  }

  // Sample J's parameter and coordinates (the divisions only for J off the first period).
  double t(Index J) const
  {
    return J >= 0 && J < n_ ? p_.t[Eigen::Index(J)] : p_.t[Eigen::Index(J - floor_div(J, n_) * n_)] + double(floor_div(J, n_));
  }
  const double* sample(Index J) const
  {
    return &P_(Eigen::Index(J >= 0 && J < n_ ? J : J - floor_div(J, n_) * n_), 0);
  }
  double candidate(Index C) const
  {
    return p_.candidates[Eigen::Index(C - floor_div(C, m_) * m_)] + double(floor_div(C, m_));
  }
  // First sample at or after parameter u (open: the last span includes t = 1).
  Index first_at(double u) const
  {
    if(!closed_ && u >= 1) return n_;
    const double period = std::floor(u);
    const double f = u - period;
    return Index(period) * n_ + Index(std::lower_bound(p_.t.data(), p_.t.data() + n_, f) - p_.t.data());
  }
  // The parameter of vertex v (v = i: knot i; open: v = -1 the start, v = K the end).
  double node(const Knots& vk, Index v) const
  {
    if(!closed_ && v < 0) return 0.0;
    if(!closed_ && v >= Index(vk.size())) return 1.0;
    return candidate(knot_candidate(vk, v));
  }
  // The row of vertex v in the control points (the vertex of knot i is row i + 1, mod K closed).
  Eigen::Index row(const Knots& vk, Index v) const
  {
    const Index K = Index(vk.size());
    return Eigen::Index(closed_ ? (v + 1 - floor_div(v + 1, K) * K) : v + 1);
  }
  bool has_vertex(const Knots& vk, Index v) const { return closed_ || (v >= -1 && v <= Index(vk.size())); }

  // Adds sign times the moments of the samples [J0, J1) about e (d = t - e about a start,
  // e - t about an end) to m, period by period.
  void add_moments(Moments& m, Index J0, Index J1, double e, bool about_start, double sign = 1) const
  {
    while(J0 < J1) {
      const Index period = floor_div(J0, n_), j0 = J0 - period * n_, j1 = std::min(n_, J1 - period * n_);
      blocks_.add(m, Eigen::Index(j0), Eigen::Index(j1), double(period), e, about_start, sign);
      J0 = period * n_ + j1;
    }
  }
  Moments moments(Index J0, Index J1, double e, bool about_start) const
  {
    Moments m(D_);
    add_moments(m, J0, J1, e, about_start);
    return m;
  }
  Span_quadratic span_between(const Knots& vk, Index v) const // the span from vertex v to v + 1
  {
    const double a = node(vk, v), b = node(vk, v + 1);
    return span_quadratic(moments(first_at(a), first_at(b), a, true), b - a, true);
  }

  // The window of knot i: vertices A (held, if any), a, u, b (free), B (held, if any); its
  // outer spans [A, a) and [b, B) filled, the two spans at the knot ([a, u), [u, b), from
  // `inner` on) left for the caller.
  Window outer_spans(const Knots& vk, const Eigen::MatrixXd& X, Index i) const
  {
    Window w;
    if(has_vertex(vk, i - 2)) {
      w.spans.push_back(span_between(vk, i - 2));
      w.free_at.push_back(-1);
      w.held.push_back(X.row(row(vk, i - 2)));
    }
    for(int f = 0; f < 3; ++f) {
      w.free_at.push_back(f);
      w.held.push_back(X.row(row(vk, i - 1 + f)));
    }
    if(has_vertex(vk, i + 2)) {
      w.spans.push_back(span_between(vk, i + 1));
      w.free_at.push_back(-1);
      w.held.push_back(X.row(row(vk, i + 2)));
    }
    w.inner = has_vertex(vk, i - 2) ? 1 : 0;
    w.spans.insert(w.spans.begin() + std::ptrdiff_t(w.inner), 2, Span_quadratic());
    return w;
  }

  // One sweep over the knots first..last - 1: each moved to its best candidate between its
  // neighbours, with its own vertex and its neighbours' re-optimised and the next ones out held.
  // Returns whether a knot moved.
  bool sweep(Knots& vk, Eigen::MatrixXd& X, Index first, Index last) const
  {
    bool moved = false;
    const Index K = Index(vk.size());
    if(!closed_) first = std::max<Index>(first, 0), last = std::min(last, K);
    Eigen::MatrixXd solution, best_solution;
    for(Index v = first; v < last; ++v) {
      const Index k = closed_ ? v - floor_div(v, K) * K : v; // the knot's entry in vk
      const double a = node(vk, v - 1), b = node(vk, v + 1);
      const Index ja = first_at(a), jb = first_at(b);
      Window w = outer_spans(vk, X, v);
      const std::size_t s2 = w.inner;
      const Moments whole = moments(ja, jb, b, false);
      const Index current = knot_candidate(vk, v);
      const Index c_first = !closed_ && v == 0 ? 0 : knot_candidate(vk, v - 1) + 1;
      const Index c_end = !closed_ && v + 1 == K ? m_ : knot_candidate(vk, v + 1);
      double best = std::numeric_limits<double>::infinity(), here = best;
      Index best_c = current;
      // A candidate wins only by more than a tie: among tied ones the first tried, an order
      // fixed by the candidates' indices (the current one's included, it is tried in turn).
      const double tol = tie(samples_between(vk, v - 2, v + 2));
      // Evaluates the candidates lo, lo + stride, ... below hi, and the current one, from the
      // moments `from` (the samples before `from.j` moved left: valid for candidates from
      // `from.c` on).  Keeps, for the next level, the moments at the evaluated place before the best.
      struct Place
      {
        Index c, j;
        Moments left, right;
      };
      Place start{c_first, ja, Moments(D_), whole}, before_best = start;
      auto scan = [&](Index lo, Index hi, Index stride, const Place& from) {
        Place at = from, previous = from;
        for(Index c = lo; c < hi;) {
          const double u = candidate(c);
          const Index moved_to = std::max(at.j, std::min(jb, first_at(u)));
          add_moments(at.left, at.j, moved_to, a, true);
          add_moments(at.right, at.j, moved_to, b, false, -1);
          at.j = moved_to;
          at.c = c;
          set_span_quadratic(w.spans[s2], at.left, u - a, true);
          set_span_quadratic(w.spans[s2 + 1], at.right, b - u, false);
          const double e = w.minimum(&solution);
          if(c == current) here = e;
          if(e < best - tol) {
            best = e;
            best_c = c;
            best_solution = solution;
            before_best = previous;
          }
          previous = at;
          const Index next = c + stride;
          c = (c < current && current < next) ? current : next;
        }
      };
      // Coarse to fine: at most `per_level` trials per level, each level around the best so far.
      // 32 kept every vertex count of bench tables 2, 7 and 8 that 64 gave, at 0.85x the time;
      // 16 lost a vertex at a million samples.
      constexpr Index per_level = 32;
      Index lo = c_first, hi = c_end;
      for(Place from = start;;) {
        const Index stride = std::max<Index>(1, (hi - lo + per_level - 1) / per_level);
        scan(lo, hi, stride, from);
        if(stride == 1) break;
        lo = std::max(c_first, best_c - stride + 1);
        hi = std::min(c_end, best_c + stride);
        from = before_best;
        lo = std::max(lo, from.c); // its moments hold for candidates from its own on
      }
      // Move only for a gain beyond a tie (the window's sums carry relative error ~1e-13, of
      // the samples' spread on centred data, not of the window's own error).
      if(best_c != current && std::isfinite(best) && !(best >= here - tol)) {
        vk[std::size_t(k)] += best_c - current;
        for(Eigen::Index f = 0; f < 3; ++f) X.row(row(vk, v - 1 + f)) = best_solution.row(f);
        moved = true;
      }
    }
    return moved;
  }

  // The squared error added by removing each knot, its two neighbours' vertices re-optimised
  // and the next ones out held (the same local model as the sweep).
  std::vector<double> removal_costs(const Knots& vk, const Eigen::MatrixXd& X) const
  {
    std::vector<double> cost(vk.size());
    for(Index i = 0; i < Index(vk.size()); ++i) {
      const double a = node(vk, i - 1), b = node(vk, i + 1);
      Window w = outer_spans(vk, X, i);
      const std::size_t s2 = w.inner;
      w.spans[s2] = span_between(vk, i - 1);
      w.spans[s2 + 1] = span_between(vk, i);
      const double with = w.minimum(nullptr);
      // Without the knot: one span from a to b, the knot's vertex gone from the chain.
      w.spans.erase(w.spans.begin() + std::ptrdiff_t(s2) + 1);
      w.spans[s2] = span_quadratic(moments(first_at(a), first_at(b), a, true), b - a, true);
      const std::size_t v = s2 + 1; // the knot's vertex in the chain
      w.free_at.erase(w.free_at.begin() + std::ptrdiff_t(v));
      w.held.erase(w.held.begin() + std::ptrdiff_t(v));
      w.free_at[v] = 1;
      cost[std::size_t(i)] = w.minimum(nullptr) - with;
    }
    return cost;
  }

  // The squared error and max error of the polyline (vk, X) over the spans from vertex v0 to
  // vertex v1 (at most one period).
  std::pair<double, double> errors_between(const Knots& vk, const Eigen::MatrixXd& X, Index v0, Index v1) const
  {
    double total = 0, largest = 0;
    if(!closed_) v0 = std::max<Index>(v0, -1), v1 = std::min<Index>(v1, Index(vk.size()));
    for(Index v = v0; v < v1; ++v) {
      const double a = node(vk, v), b = node(vk, v + 1);
      const auto xa = X.row(row(vk, v)), xb = X.row(row(vk, v + 1));
      for(Index J = first_at(a), end = first_at(b); J < end; ++J) {
        const double s = (t(J) - a) / (b - a);
        double e = 0;
        for(Eigen::Index k = 0; k < D_; ++k) {
          const double r = sample(J)[k * P_.rows()] - (1 - s) * xa[k] - s * xb[k];
          e += r * r;
        }
        total += e;
        largest = std::max(largest, e);
      }
    }
    return {total, std::sqrt(largest)};
  }

  // The unwrapped candidate of knot v (closed: any v, a period of candidates per K knots).
  Index knot_candidate(const Knots& vk, Index v) const
  {
    const Index K = Index(vk.size());
    return closed_ ? vk[std::size_t(v - floor_div(v, K) * K)] + floor_div(v, K) * m_ : vk[std::size_t(v)];
  }
  Index number_of_candidates() const { return m_; }
  bool closed() const { return closed_; }

private:

  const Problem& p_;
  const Eigen::MatrixXd& P_;
  Eigen::Index D_;
  Index n_, m_;
  bool closed_;
  Block_moments blocks_;
  double tie_unit_;
};

// Sweeps and refits until the squared error falls by less than 1e-3 relative or after `rounds`
// sweeps; the fit returned is a least-squares fit on its knots (knot_relocation.cpp).
Spline_fit relocated(const Problem& p, const Degree_one_search& search, Spline_fit fit, double lambda, int rounds = 8);

// Two knots within a short window removed and one added where the squared error falls most, the
// knots around both places slid (knot_exchange.cpp): true, with `fit` replaced by the new fit
// (one knot fewer), where the goal allows it.
bool remove_two_add_one(const Problem& p, const Goal& goal, const Degree_one_search& search, Spline_fit& fit);

// A closed curve's window of a knot needs five distinct vertices.
constexpr std::size_t fewest_closed_knots = 5;

// Whether a move's local model may meet the goal with K knots over n samples (a refit
// decides): by its largest error for a max bound, else by its squared error (a callable,
// computed only then).  Shared by removals (knot_relocation.cpp) and exchanges
// (knot_exchange.cpp).
template <class Squared>
bool model_may_meet(const Goal& goal, double largest, const Squared& squared, double n, double K, double objective)
{
  if(goal.max_error) return largest <= *goal.max_error;
  if(goal.rms_error) return squared() <= *goal.rms_error * *goal.rms_error * n;
  return squared() + goal.lambda * K < objective;
}

// Whether a refit keeps the goal: a bound met, or (penalty) a lower objective than the fit's.
inline bool keeps_goal(const Goal& goal, const Spline_fit& refit, const Spline_fit& fit)
{
  return goal.is_bound() ? goal.met(refit) : refit.objective < fit.objective;
}

} // namespace internal
} // namespace Spline_approximation
} // namespace CGAL

#endif // CGAL_SPLINE_APPROXIMATION_DEGREE_ONE_SEARCH_H
