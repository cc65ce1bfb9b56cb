// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The pieces of the closed-curve dynamic programming (exact_optimum_closed.cpp): samples and
// candidates around the circle, segment sums, the arc that must hold a knot and the lower bounds
// on a path's completion (closed_curve_bounds.cpp), and the lists of quadratics in two vertices
// with their dominance test (closed_curve_pairs.cpp).

#ifndef CGAL_SPLINE_APPROXIMATION_CLOSED_CURVE_DP_H
#define CGAL_SPLINE_APPROXIMATION_CLOSED_CURVE_DP_H

#include <CGAL/Spline_approximation/internal/spline_numerics.h>

#include "periodic_index.h"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Spline_approximation {
namespace internal {
namespace closed_dp {

// Indices "unwrapped" around the circle (periodic_index.h): candidate u is candidate u mod m one
// period (1) on per m, sample r likewise per n.
using internal::Index;
using internal::floor_div;

// Sums over a segment's samples as its far end moves away from its start vertex (to later
// candidates, or to earlier ones for a backward segment): d a sample's distance in t from the
// start, e from the end.  Every sum the segment's quadratic needs is a sum of nonnegative terms
// (sum of e^2 is not count L^2 - 2 L sum d + sum d^2, which cancels when the samples crowd the
// end, and the elimination divides by it), and the line's error comes from centred sums.
struct Segment_sums
{
  Index start, end, next; // the candidates at its ends; the next sample to add
  bool forward;
  double count = 0, d1 = 0, d2 = 0, e1 = 0, e2 = 0, de = 0, pp = 0;
  std::vector<double> p, dp, ep;         // sums of p, d p, e p
  double mean_d = 0, m2_d = 0, m2_p = 0; // centred (Welford): for the line's error
  std::vector<double> mean_p, cross;
  Segment_sums(std::size_t D, Index start, Index next, bool forward)
    : start(start), end(start), next(next), forward(forward), p(D), dp(D), ep(D), mean_p(D), cross(D)
  {}
  void add(double d, double e, const double* x) // x: the sample's D coordinates
  {
    count += 1; d1 += d; d2 += d * d; e1 += e; e2 += e * e; de += d * e;
    const double delta_d = d - mean_d;
    mean_d += delta_d / count;
    m2_d += delta_d * (d - mean_d);
    for(std::size_t k = 0; k < p.size(); ++k) {
      pp += x[k] * x[k];
      p[k] += x[k], dp[k] += d * x[k], ep[k] += e * x[k];
      const double delta_p = x[k] - mean_p[k];
      mean_p[k] += delta_p / count;
      m2_p += delta_p * (x[k] - mean_p[k]);
      cross[k] += delta_d * (x[k] - mean_p[k]);
    }
  }
  void move_end(double delta) // every e grows by delta
  {
    e2 += delta * (2 * e1 + count * delta);
    de += delta * d1;
    for(std::size_t k = 0; k < p.size(); ++k) ep[k] += delta * p[k];
    e1 += count * delta;
  }
  // The least squared error of an affine function of t on these samples: a lower bound for any
  // segment spanning them (0 where the line is not well determined).
  double line_error() const
  {
    if(!(count >= 2 && m2_d > 1e-12 * d2)) return 0;
    double c2 = 0;
    for(double c : cross) c2 += c * c;
    return std::max(0.0, m2_p - c2 / m2_d);
  }
};

// A segment's squared error in its start and end vertices xs, xe over length L (with f = d / L):
// al |xs|^2 + 2 be xs.xe + ga |xe|^2 - 2 xs.u - 2 xe.v + q, from sums of (1 - f)^2, f (1 - f),
// f^2, (1 - f) p, f p, |p|^2.
struct Segment
{
  double al = 0, be = 0, ga = 0, q = 0;
  std::vector<double> u, v;
  void set(const Segment_sums& m, double L) // in place: no allocation per segment once sized
  {
    al = m.e2 / (L * L), be = m.de / (L * L), ga = m.d2 / (L * L), q = m.pp;
    u.resize(m.ep.size());
    v.resize(m.dp.size());
    for(std::size_t k = 0; k < u.size(); ++k) u[k] = m.ep[k] / L, v[k] = m.dp[k] / L;
  }
};

// The samples (centred on their mean: the values are differences of sums of |p|^2, whose
// roundoff an offset from the origin would inflate) and candidates around the circle, and the
// work done on them: past a limit the problem is refused rather than run for minutes.
class Circle
{
public:
  Circle(const Problem& p, std::size_t work_limit);
  Index n, m;
  Eigen::Index D;
  double centred_squared_norm() const { return X_.squaredNorm(); }
  // The first sample at or after candidate u.
  Index first_sample(Index u) const
  {
    const Index period = floor_div(u, m);
    return period * n + first_[std::size_t(u - period * m)];
  }
  // Candidate `to` minus candidate `from`, in t.
  double gap(Index from, Index to) const;
  // Sums over the samples from candidate `start` on (forward) or before it.
  Segment_sums sums_from(Index start, bool forward) const;
  // Moves the end of `sums` to candidate `end` (further from its start), adding the samples passed.
  void reach(Segment_sums& sums, Index end) const;
  // Dominance tests and the like, a few nanoseconds each.
  void count_work(std::size_t units) const;

private:
  const Eigen::MatrixXd X_; // the centred samples, one per column (contiguous coordinates)
  const Eigen::VectorXd& t_;
  const Eigen::VectorXd& c_;
  std::vector<Index> first_; // per candidate in [0, m), its first sample
  std::size_t work_limit_;
  mutable std::size_t work_ = 0, sample_visits_ = 0;
};

// The shortest arc [s, s + w) of candidates in which every closed polyline of two knots or more
// within `bound` has a knot, as {s, w}; {0, m} (every candidate) where none is shorter.
std::pair<Index, Index> knot_arc(const Circle& circle, double bound);

inline bool all_zero(const double* b, std::size_t D)
{
  for(std::size_t d = 0; d < D; ++d)
    if(b[d] != 0) return false;
  return true;
}

// The minimum of a |x|^2 + b.x + c (-infinity if unbounded).
inline double vertex_minimum(double a, const double* b, double c, std::size_t D)
{
  double b2 = 0;
  for(std::size_t d = 0; d < D; ++d) b2 += b[d] * b[d];
  if(a > 0) return c - b2 / (4 * a);
  return b2 == 0 ? c : -std::numeric_limits<double>::infinity();
}

// Is a |x|^2 + pb.x + pc <= qa |x|^2 + qb.x + qc wherever the latter is at most T?  On that
// ball (centre z, radius R) the difference is da |y|^2 + e.y + d(z) in y = x - z, least at
// |y| = min(R, |e| / (2 da)) along -e (at R if da <= 0).
inline bool vertex_below_where_within(double pa, const double* pb, double pc, double qa, const double* qb, double qc,
                                      double T, std::size_t D)
{
  if(!(qa > 0)) { // q constant (else unbounded below, which no path's value is): so must p be
    if(!all_zero(qb, D)) return false;
    return qc > T || (pa == 0 && all_zero(pb, D) && pc <= qc);
  }
  const double q_least = vertex_minimum(qa, qb, qc, D), R2 = (T - q_least) / qa;
  if(!(R2 >= 0)) return true; // nowhere within T
  const double da = qa - pa;
  double z2 = 0, pz = 0, e2 = 0;
  for(std::size_t d = 0; d < D; ++d) {
    const double z = -qb[d] / (2 * qa), e = 2 * da * z + (qb[d] - pb[d]);
    z2 += z * z, pz += pb[d] * z, e2 += e * e;
  }
  const double at_centre = q_least - (pa * z2 + pz + pc), e = std::sqrt(e2), R = std::sqrt(R2);
  const double rho = da > 0 ? std::min(R, e / (2 * da)) : R;
  return da * rho * rho - e * rho + at_centre >= 0;
}

// The minimum of a00 |x0|^2 + 2 a01 x0.x + a11 |x|^2 + b0.x0 + b1.x + c, or -infinity where
// it is not determined well enough to prune by (a condition number below 1e6 keeps its roundoff
// under the pruning slack).  A vertex no sample weighs on has exactly zero coefficients: it
// drops out (every-sample candidates give such paths: a segment holding only the sample at its
// start does not weigh on its end).
inline double pair_minimum(double a00, double a01, double a11, const double* b0, const double* b1, double c,
                           std::size_t D)
{
  if(a01 == 0 && a11 == 0 && all_zero(b1, D)) return vertex_minimum(a00, b0, c, D);
  if(a01 == 0 && a00 == 0 && all_zero(b0, D)) return vertex_minimum(a11, b1, c, D);
  const double det = a00 * a11 - a01 * a01;
  if(!(a00 > 0 && a11 > 0 && det > 1e-6 * a00 * a11)) return -std::numeric_limits<double>::infinity();
  double s00 = 0, s01 = 0, s11 = 0;
  for(std::size_t d = 0; d < D; ++d) s00 += b0[d] * b0[d], s01 += b0[d] * b1[d], s11 += b1[d] * b1[d];
  return c - (a11 * s00 - 2 * a01 * s01 + a00 * s11) / (4 * det);
}

// Quadratics in two vertices, the first vertex x0 and the current one x:
// a00 |x0|^2 + 2 a01 x0.x + a11 |x|^2 + b0.x0 + b1.x + c, each stored as a record with its
// minimum and minimiser (every dominance test reads them), with the path it came from.
struct Pair_record
{
  // Record layout: a00, a01, a11, c, the minimum (-infinity where it is not determined well
  // enough to prune by), then b0, b1 (D each), then the minimiser's x0 and x (D each).
  static std::size_t size(std::size_t D) { return 5 + 4 * D; }
  // Fills `out` (size(D) values) from the coefficients.
  static void make(double a00, double a01, double a11, const double* b, double c, std::size_t D, double* out);
};
struct Pair_quadratics
{
  std::vector<double> records;
  std::vector<int> from_node, from_index;
  std::size_t size() const { return from_node.size(); }
  const double* record(std::size_t k, std::size_t D) const { return &records[k * Pair_record::size(D)]; }
};
// Adds the path `record` unless it is worth more than `limit` everywhere or another lies below it
// wherever it is within `limit` (the only place a path through it can matter, any completion
// costing at least what `limit` leaves), and drops the old ones it lies below likewise.
void add_pair(const Circle& circle, Pair_quadratics& Q, const double* record, double limit, int node, int index);

// Quadratics a |x|^2 + b.x + c in one vertex.
struct Vertex_quadratics
{
  std::vector<double> a, c, b; // b: D per quadratic
  std::size_t size() const { return a.size(); }
};

// Lower bounds on what follows node u (j0 < u <= last) on a closed polyline whose first knot is
// j0 and whose other knots are at most `last`: its restriction to the samples from candidate u to
// `end` (j0 one period on) is an open polyline there with free end vertices, so the least cost of
// such a polyline (squared error, plus `knot_cost` per knot strictly inside) bounds it from
// below.  An open DP run backwards from `end` gives them all; with `layers` > 0, per number
// r < layers of knots inside (at(u, r): at most r of them).  +infinity where no path from j0
// through u can be within `bound`.
class Completion_bounds
{
public:
  Completion_bounds(const Circle& circle, Index j0, Index last, Index end, double knot_cost, std::size_t layers,
                    double bound);
  double at(Index u, std::size_t r) const { return least_[layered_ ? r : 0][std::size_t(u - j0_)]; }
  // Whether the path `record` at node u, completed with at most r knots, costs more than `bound`
  // for every (x0, x): the completions as functions of x, not only their least values.
  bool exceeds(Index u, std::size_t r, const double* record, double bound) const;

private:
  const Circle& circle_;
  Index j0_;
  bool layered_;
  std::size_t D_;
  std::vector<std::vector<double>> least_;            // [layer][u - j0]
  std::vector<std::vector<Vertex_quadratics>> lists_; // [layer][u - j0], the end's at 0
};

} // namespace closed_dp
} // namespace internal
} // namespace Spline_approximation
} // namespace CGAL

#endif
