// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The exact optimum, where it is computable.
//
// Degree 1, dynamic programming over ordered subsets of the candidates.  The least-squares
// polyline is not separable per segment (neighbouring segments share a vertex), so the value
// at node i is a function of the vertex x_i there: V_i(x) = the least squared error over the
// samples before node i of a polyline ending at x, a minimum of isotropic quadratics
// a |x|^2 + b.x + c (one per surviving path).  A step from node j to node i adds the segment's
// squared error, a quadratic in (x_j, x_i), and minimises x_j out in closed form.  A quadratic
// that lies above another everywhere is dropped (exact pairwise test), which keeps the lists
// short on curve data.  Penalty mode charges lambda per interior node; bound mode (RMS) runs
// the same recursion layered by the number of knots and stops at the first count that meets it.
// Closed curves: exact_optimum_closed.cpp.
//
// Brute force: every subset of up to max_brute_force_candidates candidates, each fitted.

#include <CGAL/Spline_approximation/internal/spline_numerics.h>

#include <algorithm>
#include <bitset>
#include <limits>
#include <string>

namespace CGAL {
namespace Spline_approximation {
namespace internal {
namespace {

// Quadratics a |x|^2 + b.x + c, each with where it came from (node, index in that node's list).
struct Quadratics
{
  std::vector<double> a, c, b; // b: D per quadratic
  std::vector<int> from_node, from_index;
  std::size_t size() const { return a.size(); }
};

class Degree_one_dp
{
public:
  Degree_one_dp(const Problem& p) : p_(p), P_(*p.samples), D_(P_.cols()), m_(p.candidates.size())
  {
    node_t_.resize(m_ + 2);
    node_t_[0] = 0;
    node_t_.segment(1, m_) = p.candidates;
    node_t_[m_ + 1] = 1;
    first_.resize(m_ + 2);
    for(Eigen::Index i = 0; i <= m_ + 1; ++i) // first sample at or after the node
      first_[i] = Eigen::Index(std::lower_bound(p.t.data(), p.t.data() + p.t.size(), node_t_[i]) - p.t.data());
    first_[m_ + 1] = p.t.size(); // the last segment includes t = 1
  }

  // Pushes node j's list Q to the nodes i_first <= i < i_end (list dst(i), cost(i) added), the
  // segment sums growing with i: one pass over the samples after node j, about c_j (accurate).
  template <class Cost, class Dst>
  void push(const Quadratics& Q, Eigen::Index j, Eigen::Index i_first, Eigen::Index i_end, Cost cost, Dst dst) const
  {
    if(Q.size() == 0) return;
    const double cj = node_t_[j];
    double S0 = 0, T1 = 0, T2 = 0, q = 0;
    Eigen::RowVectorXd Pp = Eigen::RowVectorXd::Zero(D_), Pt = Eigen::RowVectorXd::Zero(D_);
    Eigen::Index r = first_[j];
    for(Eigen::Index i = j + 1; i < i_end; ++i) {
      for(; r < first_[i]; ++r) {
        const double d = p_.t[r] - cj;
        S0 += 1; T1 += d; T2 += d * d; q += P_.row(r).squaredNorm();
        Pp += P_.row(r); Pt += d * P_.row(r);
      }
      if(i < i_first) continue;
      const double L = node_t_[i] - cj;
      // The segment's squared error: al |x_j|^2 + 2 be x_j.x_i + ga |x_i|^2 - 2 x_j.u - 2 x_i.v + q.
      const double ga = T2 / (L * L), be = T1 / L - ga, al = S0 - 2 * T1 / L + ga;
      const Eigen::RowVectorXd u = Pp - Pt / L, v = Pt / L;
      for(std::size_t k = 0; k < Q.size(); ++k) {
        Eigen::Map<const Eigen::RowVectorXd> b(&Q.b[k * std::size_t(D_)], D_);
        const double A = Q.a[k] + al, C = Q.c[k] + q;
        const Eigen::RowVectorXd B = b - 2 * u;
        double na = ga, nc = C;
        Eigen::RowVectorXd nb = -2 * v;
        if(A > 0) { // minimise over x_j: x_j = -(2 be x + B) / (2 A)
          na -= be * be / A;
          nb -= (be / A) * B;
          nc -= B.squaredNorm() / (4 * A);
          // A vertex that the samples leave free (one sample in the segment and x_j free
          // before it, or none) has weight exactly 0 and no linear term; computed, both cancel
          // to roundoff, and a later minimum over x_i would divide the one by the other
          // (paths far below their true error).  A weight below 1e-10 of the segment's own is
          // that roundoff: the vertex is free.
          if(na <= 1e-10 * ga) {
            na = 0;
            nb.setZero();
          }
        }
        add(dst(i), na, nb, nc + cost(i), int(j), int(k));
      }
    }
  }

  static double minimum(const Quadratics& Q, std::size_t r, Eigen::Index D)
  {
    Eigen::Map<const Eigen::RowVectorXd> b(&Q.b[r * std::size_t(D)], D);
    return Q.a[r] > 0 ? Q.c[r] - b.squaredNorm() / (4 * Q.a[r]) : Q.c[r];
  }

  Eigen::Index m() const { return m_; }
  Eigen::Index dim() const { return D_; }

private:
public:
  // Paths whose squared error (and knot cost) so far already exceed `bound` cannot win: the
  // rest only adds.  The bound is a known solution's objective, or the bound mode's budget.
  double bound = std::numeric_limits<double>::infinity();
  // Beyond this many pairwise tests (a few seconds) the problem is declared not computable:
  // the pairwise test makes a list's cost quadratic in its length, and on smooth data with
  // many candidates the lists grow long.
  mutable std::size_t work = 0;
  std::size_t work_limit = std::size_t(1) << 30;

private:

  void add(Quadratics& Q, double a, const Eigen::RowVectorXd& b, double c, int node, int index) const
  {
    if((a > 0 ? c - b.squaredNorm() / (4 * a) : c) > bound) return;
    // Drop the new one if an old one lies below it everywhere, and the old ones it lies below.
    auto below = [&](double a1, const double* b1, double c1, double a2, const double* b2, double c2) {
      const double da = a2 - a1, dc = c2 - c1; // is q1 <= q2 everywhere?
      double db2 = 0;
      for(Eigen::Index d = 0; d < D_; ++d) db2 += (b2[d] - b1[d]) * (b2[d] - b1[d]);
      if(da > 0) return dc - db2 / (4 * da) >= 0;
      return da == 0 && db2 == 0 && dc >= 0;
    };
    for(std::size_t r = 0; r < Q.size(); ++r)
      if(below(Q.a[r], &Q.b[r * std::size_t(D_)], Q.c[r], a, b.data(), c)) return;
    std::size_t w = 0;
    for(std::size_t r = 0; r < Q.size(); ++r) {
      if(below(a, b.data(), c, Q.a[r], &Q.b[r * std::size_t(D_)], Q.c[r])) continue;
      Q.a[w] = Q.a[r]; Q.c[w] = Q.c[r]; Q.from_node[w] = Q.from_node[r]; Q.from_index[w] = Q.from_index[r];
      for(Eigen::Index d = 0; d < D_; ++d) Q.b[w * std::size_t(D_) + std::size_t(d)] = Q.b[r * std::size_t(D_) + std::size_t(d)];
      ++w;
    }
    Q.a.resize(w); Q.c.resize(w); Q.from_node.resize(w); Q.from_index.resize(w); Q.b.resize(w * std::size_t(D_));
    Q.a.push_back(a); Q.c.push_back(c); Q.from_node.push_back(node); Q.from_index.push_back(index);
    Q.b.insert(Q.b.end(), b.data(), b.data() + D_);
    work += Q.size();
    if(work > work_limit)
      throw Invalid_input("spline fit: the dynamic programming optimum is not computable here (more than " +
                          std::to_string(work_limit) + " path comparisons); use fewer candidate knots");
  }

  const Problem& p_;
  const Eigen::MatrixXd& P_;
  Eigen::Index D_, m_;
  Eigen::VectorXd node_t_;
  Eigen::VectorXi first_;
};

Quadratics start(Eigen::Index D)
{
  Quadratics Q;
  Q.a = {0}; Q.c = {0}; Q.from_node = {-1}; Q.from_index = {-1};
  Q.b.assign(std::size_t(D), 0.0);
  return Q;
}

} // namespace

Spline_fit dynamic_programming(const Problem& p, const Goal& goal)
{
  if(p.closed) return closed_dynamic_programming(p, goal);
  Degree_one_dp dp(p);
  const Eigen::Index m = dp.m(), D = dp.dim();
  // Slack on the pruning bounds, so that roundoff never prunes the optimum itself: the values
  // are differences of sums of |p|^2, so their roundoff is relative to that sum.
  const double slack = 1e-9 * p.samples->squaredNorm();
  const double budget = double(p.t.size()) * (goal.rms_error ? *goal.rms_error * *goal.rms_error : 0.0);
  if(!goal.is_bound()) dp.bound = greedy_removal(p, goal).objective + slack;
  else dp.bound = budget + slack;
  const std::size_t nodes = std::size_t(m + 2);
  std::vector<std::size_t> kept;
  if(!goal.is_bound()) {
    std::vector<Quadratics> V(nodes);
    V[0] = start(D);
    for(Eigen::Index j = 0; j <= m; ++j) // V[j] is final once every earlier node has pushed
      dp.push(V[std::size_t(j)], j, j + 1, m + 2, [&](Eigen::Index i) { return i <= m ? goal.lambda : 0.0; },
              [&](Eigen::Index i) -> Quadratics& { return V[std::size_t(i)]; });
    const Quadratics& end = V[nodes - 1];
    if(end.size() == 0) throw Numerical_failure("spline fit: the dynamic programming lost every path (roundoff)");
    std::size_t best = 0;
    for(std::size_t r = 1; r < end.size(); ++r)
      if(Degree_one_dp::minimum(end, r, D) < Degree_one_dp::minimum(end, best, D)) best = r;
    for(int node = end.from_node[best], index = end.from_index[best]; node > 0;) {
      kept.push_back(std::size_t(node - 1));
      const Quadratics& Q = V[std::size_t(node)];
      node = Q.from_node[std::size_t(index)];
      index = Q.from_index[std::size_t(index)];
    }
  } else {
    // Layer K: paths with K interior knots.  The end is reached from layer K without a new knot.
    std::vector<std::vector<Quadratics>> layers(1, std::vector<Quadratics>(nodes));
    layers[0][0] = start(D);
    for(std::size_t K = 0;; ++K) {
      if(K > 0) {
        layers.emplace_back(nodes);
        for(Eigen::Index j = 0; j < m; ++j)
          dp.push(layers[K - 1][std::size_t(j)], j, j + 1, m + 1, [](Eigen::Index) { return 0.0; },
                  [&](Eigen::Index i) -> Quadratics& { return layers[K][std::size_t(i)]; });
      }
      bool alive = false;
      for(const Quadratics& Q : layers[K]) alive = alive || Q.size() > 0;
      if(!alive) { // every path over the budget: the bound cannot be met, answer with every knot
        for(Eigen::Index i = m; i >= 1; --i) kept.push_back(std::size_t(i - 1));
        break;
      }
      Quadratics end;
      for(Eigen::Index j = 0; j <= m; ++j) // to the end node only
        dp.push(layers[K][std::size_t(j)], j, m + 1, m + 2, [](Eigen::Index) { return 0.0; },
                [&](Eigen::Index) -> Quadratics& { return end; });
      std::size_t best = 0;
      for(std::size_t r = 1; r < end.size(); ++r)
        if(Degree_one_dp::minimum(end, r, D) < Degree_one_dp::minimum(end, best, D)) best = r;
      // Within the budget up to roundoff: the refit of those knots decides (its errors are the
      // ones reported); all knots is the last resort.
      if(end.size() > 0 && (Degree_one_dp::minimum(end, best, D) <= budget + slack || K == std::size_t(m))) {
        std::vector<std::size_t> path;
        int node = end.from_node[best], index = end.from_index[best];
        for(std::size_t L = K; node > 0; --L) {
          path.push_back(std::size_t(node - 1));
          const Quadratics& Q = layers[L][std::size_t(node)];
          node = Q.from_node[std::size_t(index)];
          index = Q.from_index[std::size_t(index)];
        }
        std::reverse(path.begin(), path.end());
        Spline_fit fit = finish(p, path, goal.lambda);
        if(goal.met(fit) || K == std::size_t(m)) return fit;
      }
    }
  }
  std::reverse(kept.begin(), kept.end());
  return finish(p, kept, goal.lambda);
}

Spline_fit brute_force(const Problem& p, const Goal& goal)
{
  const std::size_t m = std::size_t(p.candidates.size());
  // Bound mode: by increasing knot count, stopping after the first count that meets the bound.
  std::vector<std::vector<unsigned>> by_count(m + 1);
  for(unsigned mask = 0; mask < (1u << m); ++mask) by_count[std::bitset<32>(mask).count()].push_back(mask);
  Spline_fit best;
  bool have = false;
  for(std::size_t count = 0; count <= m; ++count) {
    for(unsigned mask : by_count[count]) {
      std::vector<std::size_t> kept;
      for(std::size_t i = 0; i < m; ++i) if(mask & (1u << i)) kept.push_back(i);
      Spline_fit fit = finish(p, kept, goal.lambda);
      if(!have || better(fit, best, goal)) { best = std::move(fit); have = true; }
    }
    if(goal.is_bound() && goal.met(best)) break;
  }
  return best;
}

} // namespace internal
} // namespace Spline_approximation
} // namespace CGAL
