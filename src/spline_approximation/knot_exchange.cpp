// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Remove two knots, add one (degree 1, open or closed): the move that takes the knot relocation
// past the last vertex or two where no single removal holds.
//
// Greedy removal with relocation stopped one or two vertices over the optimum on small counts
// (bench table 8: one over an optimum of 15 vertices, 6.7 %; two over 22, 9.1 %): every single
// removal left the error over the bound even after the knots slid.  Two things were missing.  The
// optimum's knots may lie a candidate or two off the fit's over several knots in a row, and a
// sweep moves one knot at a time: where a chain of knots has to move together, each knot
// alone, its neighbours held, only loses.  And the knot to give up may be far from the place
// that needs one more.
//
// Hence the move: two neighbouring knots are removed and one knot is added, either between
// their outer neighbours (the pair replaced by one knot at the best candidate there) or in
// the span elsewhere where an added knot lowers the squared error most (every span scanned
// beforehand).  Around both places the knots then slide, one at a time (the sweep) and in
// runs of two to four shifted together, with the vertices beyond held: a local model that is
// itself a polyline on the new knots, its error exact where it changed.  The moves are tried
// in the order of their cost on a model with only the new knot placed; one whose local model
// meets the goal is refitted globally and kept if the refit meets the goal, as a removal is.

#include "degree_one_search.h"

#include <numeric>

namespace CGAL {
namespace Spline_approximation {
namespace internal {
namespace {

// Open curves: marks for the start and end vertices where a range of the curve is given by the
// candidates of the knots at its ends.
constexpr Index start_mark = std::numeric_limits<Index>::min() / 4;
constexpr Index end_mark = std::numeric_limits<Index>::max() / 4;

class Exchange_search
{
public:
  explicit Exchange_search(const Degree_one_search& s) : s_(s), m_(s.number_of_candidates()), closed_(s.closed()) {}

  // The least squared error over the spans from vertex f0 - 1 to vertex f1 + 1 (those that
  // exist), vertices f0..f1 free and f0 - 1, f1 + 1 held at their rows of X: a tridiagonal
  // system, the same for every coordinate.  A closed curve needs f1 - f0 + 3 <= K (distinct
  // vertices).  The minimiser's rows (vertex v in row v - f0) go to `solution` if given.
  // +infinity where a free vertex has no samples or the system is singular.
  double chain_minimum(const Knots& vk, const Eigen::MatrixXd& X, Index f0, Index f1, Eigen::MatrixXd* solution) const
  {
    const Index K = Index(vk.size());
    if(!closed_) f0 = std::max<Index>(f0, -1), f1 = std::min<Index>(f1, K);
    const Index F = f1 - f0 + 1;
    if(F < 1) return std::numeric_limits<double>::infinity();
    const Eigen::Index D = X.cols();
    const std::size_t size = std::size_t(F);
    std::vector<double> d(size, 0.0), e(size, 0.0), pivot(size, 0.0), l(size, 0.0);
    Eigen::MatrixXd g = Eigen::MatrixXd::Zero(F, D);
    double c = 0;
    for(Index v = f0 - 1; v <= f1; ++v) { // the span from vertex v to v + 1
      if(!s_.has_vertex(vk, v) || !s_.has_vertex(vk, v + 1)) continue;
      const Span_quadratic q = s_.span_between(vk, v);
      const Index a = v - f0, b = a + 1; // free indices, or held where outside [0, F)
      c += q.E;
      const bool a_free = a >= 0, b_free = b < F;
      const Eigen::RowVectorXd xa = X.row(s_.row(vk, v)), xb = X.row(s_.row(vk, v + 1));
      if(a_free) {
        d[std::size_t(a)] += q.ss;
        g.row(a) += q.us;
      } else {
        c += -2 * xa.dot(q.us) + q.ss * xa.squaredNorm();
      }
      if(b_free) {
        d[std::size_t(b)] += q.ee;
        g.row(b) += q.ue;
      } else {
        c += -2 * xb.dot(q.ue) + q.ee * xb.squaredNorm();
      }
      if(a_free && b_free) e[std::size_t(a)] += q.se; // coupling of free a and a + 1
      else if(a_free) g.row(a) -= q.se * xb;
      else if(b_free) g.row(b) -= q.se * xa;
      else c += 2 * q.se * xa.dot(xb);
    }
    // L D L^T of the tridiagonal matrix, forward substitution alongside: the minimum of
    // c - 2 x.g + x^T H x is c - g^T H^-1 g = c - sum |y_k|^2 / D_k.
    const double largest = *std::max_element(d.begin(), d.end());
    double reduction = 0;
    for(Index k = 0; k < F; ++k) {
      const std::size_t u = std::size_t(k);
      if(!(d[u] > 0)) return std::numeric_limits<double>::infinity();
      if(k > 0) {
        l[u] = e[u - 1] / pivot[u - 1];
        g.row(k) -= l[u] * g.row(k - 1);
      }
      pivot[u] = d[u] - (k > 0 ? l[u] * e[u - 1] : 0.0);
      if(!(pivot[u] > 1e-14 * largest)) return std::numeric_limits<double>::infinity();
      reduction += g.row(k).squaredNorm() / pivot[u];
    }
    if(solution) {
      solution->resize(F, D);
      for(Index k = F - 1; k >= 0; --k) {
        solution->row(k) = g.row(k) / pivot[std::size_t(k)];
        if(k + 1 < F) solution->row(k) -= l[std::size_t(k + 1)] * solution->row(k + 1);
      }
    }
    return c - reduction;
  }

  // The vertices first - 1 .. last re-optimised together, the next ones out held (on a closed
  // curve at most K - 2 of them, so that the held two are distinct).
  void refit_vertices(const Knots& vk, Eigen::MatrixXd& X, Index first, Index last) const
  {
    const Index K = Index(vk.size());
    Index f0 = first - 1, f1 = last;
    if(closed_) f1 = std::min(f1, f0 + K - 3);
    else f0 = std::max<Index>(f0, -1), f1 = std::min(f1, K);
    Eigen::MatrixXd solution;
    if(!std::isfinite(chain_minimum(vk, X, f0, f1, &solution))) return;
    for(Index v = f0; v <= f1; ++v) X.row(s_.row(vk, v)) = solution.row(v - f0);
  }

  // Runs of two to four neighbouring knots among first..last - 1 shifted together, with the
  // run's vertices and the one on each side re-optimised (the next held).  Steps from a quarter
  // of the smallest gap around the run, halved down to a 32nd of it (one candidate on a coarse
  // grid; finer steps on dense candidates changed no vertex count in bench tables 2 and 8 and
  // cost a third of the move's time at 100,000 samples); a shift is kept where it lowers the
  // squared error beyond rounding.  Returns whether a run moved.
  bool shift_runs(Knots& vk, Eigen::MatrixXd& X, Index first, Index last) const
  {
    const Index K = Index(vk.size());
    if(!closed_) first = std::max<Index>(first, 0), last = std::min(last, K);
    bool moved = false;
    Eigen::MatrixXd solution, best_solution;
    for(Index L = 2; L <= 4; ++L) {
      if(closed_ ? L + 4 > K : L > K) break; // a closed run needs distinct held vertices
      for(Index a = first; a + L <= last; ++a) {
        const Index b = a + L; // the run: knots a .. b - 1
        const Index lo = !closed_ && a == 0 ? -1 : s_.knot_candidate(vk, a - 1);
        const Index hi = !closed_ && b == K ? m_ : s_.knot_candidate(vk, b);
        Index smallest = hi - s_.knot_candidate(vk, b - 1);
        for(Index v = a; v < b; ++v) smallest = std::min(smallest, s_.knot_candidate(vk, v) - (v == a ? lo : s_.knot_candidate(vk, v - 1)));
        double here = chain_minimum(vk, X, a - 1, b, nullptr);
        const double tol = s_.tie(s_.samples_between(vk, a - 2, b + 1)); // the chain's spans
        const Index finest = std::max<Index>(1, smallest / 32);
        for(Index step = std::max<Index>(1, smallest / 4); step >= finest;) {
          double best = here;
          Index best_shift = 0;
          for(Index shift : {-step, step}) { // a tie goes to the shift down
            if(s_.knot_candidate(vk, a) + shift <= lo || s_.knot_candidate(vk, b - 1) + shift >= hi) continue;
            shift_run(vk, a, b, shift);
            const double e = chain_minimum(vk, X, a - 1, b, &solution);
            shift_run(vk, a, b, -shift);
            if(e < best - tol) {
              best = e;
              best_shift = shift;
              best_solution = solution;
            }
          }
          // Only for a gain beyond a tie, as in the sweep.
          if(best_shift != 0 && std::isfinite(best) && !(best >= here - tol)) {
            shift_run(vk, a, b, best_shift);
            for(Index v = a - 1; v <= b; ++v) X.row(s_.row(vk, v)) = best_solution.row(v - (a - 1));
            here = best;
            moved = true;
            continue; // the same step again
          }
          step /= 2;
        }
      }
    }
    return moved;
  }

  // The knots first..last - 1 slid until they settle (at most four rounds of sweeps and run
  // shifts), then the vertices around them re-optimised together.
  void descend(Knots& vk, Eigen::MatrixXd& X, Index first, Index last) const
  {
    refit_vertices(vk, X, first, last);
    for(int round = 0; round < 4; ++round) {
      for(int pass = 0; pass < 4; ++pass)
        if(!s_.sweep(vk, X, first, last)) break;
      if(!shift_runs(vk, X, first, last)) break;
    }
    refit_vertices(vk, X, first, last);
  }

  // The polyline on the knots `vk` whose knot i keeps the vertex of old knot from[i], or takes
  // its place on the old polyline where from[i] < 0 (a new knot); open: the ends kept.
  Eigen::MatrixXd rebuilt(const Knots& old_vk, const Eigen::MatrixXd& old_X, const Knots& vk,
                          const std::vector<Index>& from) const
  {
    const Index K = Index(vk.size()), old_K = Index(old_vk.size());
    Eigen::MatrixXd X(old_X.rows() + (K - old_K), old_X.cols());
    if(!closed_) {
      X.row(s_.row(vk, -1)) = old_X.row(s_.row(old_vk, -1));
      X.row(s_.row(vk, K)) = old_X.row(s_.row(old_vk, old_K));
    }
    for(Index i = 0; i < K; ++i) {
      if(from[std::size_t(i)] >= 0) {
        X.row(s_.row(vk, i)) = old_X.row(s_.row(old_vk, from[std::size_t(i)]));
        continue;
      }
      const double u = s_.candidate(vk[std::size_t(i)]);
      Index v = -1; // the old span holding u: from vertex v to v + 1
      if(closed_) {
        while(s_.node(old_vk, v) > u) --v;
        while(s_.node(old_vk, v + 1) <= u) ++v;
      } else {
        while(v + 1 < old_K && s_.node(old_vk, v + 1) <= u) ++v;
      }
      const double a = s_.node(old_vk, v), b = s_.node(old_vk, v + 1), f = (u - a) / (b - a);
      X.row(s_.row(vk, i)) = (1 - f) * old_X.row(s_.row(old_vk, v)) + f * old_X.row(s_.row(old_vk, v + 1));
    }
    return X;
  }

  // Vertex v of vk at the knot of candidate C (unwrapped), or an end mark (open).
  Index vertex_of(const Knots& vk, Index C) const
  {
    const Index K = Index(vk.size());
    if(!closed_) {
      if(C == start_mark) return -1;
      if(C == end_mark) return K;
      return Index(std::lower_bound(vk.begin(), vk.end(), C) - vk.begin());
    }
    const Index period = floor_div(C - vk[0], m_);
    return Index(std::lower_bound(vk.begin(), vk.end(), C - period * m_) - vk.begin()) + period * K;
  }
  // The mark of vertex v: its knot's candidate, or an end mark (open).
  Index mark_of(const Knots& vk, Index v) const
  {
    if(!closed_ && v < 0) return start_mark;
    if(!closed_ && v >= Index(vk.size())) return end_mark;
    return s_.knot_candidate(vk, v);
  }

  // Squared and largest error of (vk, X) between the vertices marked A and B (A < B), or over
  // the whole curve where `whole`.
  std::pair<double, double> errors(const Knots& vk, const Eigen::MatrixXd& X, Index A, Index B, bool whole) const
  {
    if(whole) return s_.errors_between(vk, X, closed_ ? 0 : -1, Index(vk.size()));
    return s_.errors_between(vk, X, vertex_of(vk, A), vertex_of(vk, B));
  }

  Index period() const { return m_; }

private:
  void shift_run(Knots& vk, Index a, Index b, Index shift) const
  {
    const Index K = Index(vk.size());
    for(Index v = a; v < b; ++v) vk[std::size_t(closed_ ? v - floor_div(v, K) * K : v)] += shift;
  }

  const Degree_one_search& s_;
  Index m_;
  bool closed_;
};

// A closed curve's knots turned so that knot i comes first (one period added to those before
// it), the vertices' rows with them: every window then starts at index 0.
void turn(Knots& vk, Eigen::MatrixXd& X, Index i, Index m)
{
  const Index K = Index(vk.size());
  Knots turned(vk.size());
  for(Index q = 0; q < K; ++q) turned[std::size_t(q)] = vk[std::size_t((q + i) % K)] + (q + i >= K ? m : 0);
  Eigen::MatrixXd rows(X.rows(), X.cols());
  for(Eigen::Index r = 0; r < X.rows(); ++r) rows.row(r) = X.row((r + Eigen::Index(i)) % X.rows());
  vk = std::move(turned);
  X = std::move(rows);
}

// The best knot added in each span of (vk, X) (from vertex v to v + 1; open v = -1 .. K - 1,
// closed 0 .. K - 1), its vertex and its span's ends re-optimised, the next vertices held.
struct Insertion
{
  double gain = -std::numeric_limits<double>::infinity(); // squared error removed
  Index added = 0;                                         // its candidate
  Index samples = 0;                                       // those of the spans the gain covers
};

std::vector<Insertion> insertions(const Degree_one_search& search, const Exchange_search& x, const Knots& vk,
                                  const Eigen::MatrixXd& X)
{
  const Index K = Index(vk.size()), first_span = search.closed() ? 0 : -1;
  std::vector<Insertion> best(std::size_t(K - first_span));
  for(Index v = first_span; v < K; ++v) {
    const Index lo = x.mark_of(vk, v) == start_mark ? -1 : search.knot_candidate(vk, v);
    const Index hi = x.mark_of(vk, v + 1) == end_mark ? x.period() : search.knot_candidate(vk, v + 1);
    if(hi - lo < 2) continue; // no candidate inside
    const Index q = v + 1;    // the new knot's index, first placed halfway, then swept
    Knots with = vk;
    with.insert(with.begin() + q, (lo + hi) / 2);
    std::vector<Index> from(std::size_t(K + 1));
    for(Index k = 0; k <= K; ++k) from[std::size_t(k)] = k < q ? k : k == q ? -1 : k - 1;
    Eigen::MatrixXd X_with = x.rebuilt(vk, X, with, from);
    search.sweep(with, X_with, q, q + 1);
    const double after = x.chain_minimum(with, X_with, q - 1, q + 1, nullptr);
    best[std::size_t(v - first_span)] = {x.chain_minimum(vk, X, v, v + 1, nullptr) - after,
                                         search.knot_candidate(with, q), search.samples_between(vk, v - 1, v + 2)};
  }
  return best;
}

// A move as tried: knots i and i + 1 removed, a knot added at candidate `added` (unwrapped as
// the knots turned to start at knot i on a closed curve).
struct Exchange
{
  Index i, added;
  double estimate; // the squared error added, on a model with only the new knot placed
  Index samples;   // those of the spans the estimate covers (for its tie tolerance)
};

// Every neighbouring pair with both places for its new knot, cheapest first.
std::vector<Exchange> exchanges(const Degree_one_search& search, const Exchange_search& x, const Knots& vk0,
                                const Eigen::MatrixXd& X0)
{
  const bool closed = search.closed();
  const Index K = Index(vk0.size()), m = x.period(), first_span = closed ? 0 : -1;
  const std::vector<Insertion> elsewhere = insertions(search, x, vk0, X0);
  std::vector<Exchange> moves;
  for(Index i = 0; i < (closed ? K : K - 1); ++i) {
    Knots vk = vk0;
    Eigen::MatrixXd X = X0;
    if(closed) turn(vk, X, i, m);
    const Index at = closed ? 0 : i; // the pair is knots at and at + 1 of vk
    const double before = x.chain_minimum(vk, X, at - 1, at + 2, nullptr);
    const Index pair_samples = search.samples_between(vk, at - 2, at + 3);
    Knots without;
    std::vector<Index> from;
    for(Index k = 0; k < K; ++k)
      if(k != at && k != at + 1) without.push_back(vk[std::size_t(k)]), from.push_back(k);
    const Eigen::MatrixXd X_without = x.rebuilt(vk, X, without, from);
    // Between the outer neighbours (knots at - 1 and at of `without`): the new knot swept to
    // its best candidate there.
    const Index lo = x.mark_of(without, at - 1) == start_mark ? -1 : search.knot_candidate(without, at - 1);
    const Index hi = x.mark_of(without, at) == end_mark ? m : search.knot_candidate(without, at);
    if(hi - lo >= 2) {
      Knots with = without;
      with.insert(with.begin() + at, (lo + hi) / 2);
      std::vector<Index> from_with(std::size_t(K - 1));
      for(Index k = 0; k < K - 1; ++k) from_with[std::size_t(k)] = k < at ? k : k == at ? -1 : k - 1;
      Eigen::MatrixXd X_with = x.rebuilt(without, X_without, with, from_with);
      search.sweep(with, X_with, at, at + 1);
      const double e = x.chain_minimum(with, X_with, at - 1, at + 1, nullptr) - before;
      if(std::isfinite(e)) moves.push_back({i, search.knot_candidate(with, at), e, pair_samples});
    }
    // Elsewhere: in the span away from the pair's three where an added knot gains most.
    const double removed = x.chain_minimum(without, X_without, at - 1, at, nullptr) - before;
    Exchange far{i, 0, std::numeric_limits<double>::infinity(), 0};
    for(Index v = first_span; v < K; ++v) {
      const Index turned_v = closed ? v - i - floor_div(v - i, K) * K : v; // the span in vk
      if((turned_v >= at - 1 && turned_v <= at + 1) || (closed && turned_v == K - 1)) continue;
      const Insertion& e = elsewhere[std::size_t(v - first_span)];
      // The candidate as vk counts them: knots before knot i are a period on once turned.  A
      // tie goes to the first span.
      const Index samples = pair_samples + e.samples;
      if(removed - e.gain < far.estimate - search.tie(std::max(samples, far.samples)))
        far = {i, closed && v < i ? e.added + m : e.added, removed - e.gain, samples};
    }
    if(std::isfinite(far.estimate)) moves.push_back(far);
  }
  // Cheapest first; tied estimates (a symmetric curve's, up to rounding) in the order built,
  // by pair and then place: an order of indices, the same for a moved copy.
  std::vector<double> estimate, tie;
  for(const Exchange& move : moves) estimate.push_back(move.estimate), tie.push_back(search.tie(move.samples));
  std::vector<Exchange> ordered;
  for(std::size_t q : order_with_ties(estimate, tie)) ordered.push_back(moves[q]);
  return ordered;
}

} // namespace

bool remove_two_add_one(const Problem& p, const Goal& goal, const Degree_one_search& search, Spline_fit& fit)
{
  const bool closed = p.closed;
  const Index K = Index(fit.kept.size());
  if(K < 2 || (closed && std::size_t(K - 1) < fewest_closed_knots)) return false;
  const Exchange_search x(search);
  const Index m = x.period(), K1 = K - 1;
  constexpr Index reach = 6; // the knots that slide on either side of a change, as for a removal
  const Knots vk0 = search.unwrapped(fit.kept);
  const Eigen::MatrixXd& X0 = fit.spline.control_points;
  const double n = double(p.t.size());
  for(const Exchange& move : exchanges(search, x, vk0, X0)) {
    Knots old_vk = vk0;
    Eigen::MatrixXd old_X = X0;
    if(closed) turn(old_vk, old_X, move.i, m);
    const Index at = closed ? 0 : move.i;
    Knots vk;
    std::vector<Index> from;
    for(Index k = 0; k < K; ++k)
      if(k != at && k != at + 1) vk.push_back(old_vk[std::size_t(k)]), from.push_back(k);
    const auto place = std::lower_bound(vk.begin(), vk.end(), move.added);
    if(place != vk.end() && *place == move.added) continue;
    from.insert(from.begin() + (place - vk.begin()), -1);
    vk.insert(place, move.added);
    Eigen::MatrixXd X = x.rebuilt(old_vk, old_X, vk, from);
    // The pair's outer neighbours and the new knot in vk (open: -1 and K - 1 for the ends).
    const Index left = x.vertex_of(vk, x.mark_of(old_vk, at - 1));
    const Index right = x.vertex_of(vk, x.mark_of(old_vk, at + 2));
    const Index added = x.vertex_of(vk, move.added);
    Index first[2] = {left + 1 - reach, added - reach}, last[2] = {right + reach, added + 1 + reach};
    // The two places' errors lie between the knots first - 3 and last + 2 (knots outside
    // [first, last) stay, and the vertices from first - 2 out); where those share a span (on a
    // closed curve also a period apart), the places are one.
    int places = 2;
    for(Index shift : {Index(0), -K1, K1}) {
      if(places == 1 || (shift != 0 && !closed)) continue;
      if(first[1] + shift < last[0] + 5 && first[0] < last[1] + shift + 5) {
        first[0] = std::min(first[0], first[1] + shift);
        last[0] = std::max(last[0], last[1] + shift);
        places = 1;
      }
    }
    const bool whole = closed && (places == 1 ? last[0] - first[0] + 5 >= K1
                                              : last[0] - first[0] + last[1] - first[1] + 10 >= K1);
    if(whole) places = 1, first[0] = 0, last[0] = K1;
    for(int s = 0; s < places; ++s) x.descend(vk, X, first[s], last[s]);
    // The model's squared error, exact: the fit's outside the places, the model's in them.
    double squared = fit.squared_error, largest = 0;
    for(int s = 0; s < places; ++s) {
      const Index A = x.mark_of(vk, first[s] - 3), B = x.mark_of(vk, last[s] + 2);
      const auto after = x.errors(vk, X, A, B, whole), before = x.errors(old_vk, old_X, A, B, whole);
      squared += after.first - before.first;
      largest = std::max(largest, after.second);
    }
    if(!model_may_meet(goal, largest, [&] { return squared; }, n, double(K1), fit.objective)) continue;
    std::vector<std::size_t> kept;
    search.wrap(vk, kept, X);
    // As for a removal: the refit first (a max bound may fail where the model met it), then
    // two rounds of relocation, kept if the goal still holds.
    auto holds = [&](const Spline_fit& f) { return keeps_goal(goal, f, fit); };
    Spline_fit trial = finish(p, kept, goal.lambda, Sample_errors::summary_only);
    if(!holds(trial)) continue;
    Spline_fit moved = relocated(p, search, trial, goal.lambda, 2);
    fit = holds(moved) ? std::move(moved) : std::move(trial);
    return true;
  }
  return false;
}

} // namespace internal
} // namespace Spline_approximation
} // namespace CGAL
