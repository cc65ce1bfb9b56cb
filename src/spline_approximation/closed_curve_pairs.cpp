// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The closed-curve dynamic programming's lists of quadratics in two vertices (see
// exact_optimum_closed.cpp) and their dominance test.  Two paths to a node compare as functions
// of (x0, x); "p below q everywhere" keeps lists long (x0 adds dimensions in which p must stay
// below), but only where q is within the bound can its path matter, and there p usually is
// below: that is the test.

#include "closed_curve_dp.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Spline_approximation {
namespace internal {
namespace closed_dp {
namespace {

constexpr double minus_infinity = -std::numeric_limits<double>::infinity();

// p(X) for a record p at X = (x0, x) (D each).
double value_at(const double* p, const double* X, std::size_t D)
{
  const double* b = p + 5;
  double v = p[3];
  for(std::size_t d = 0; d < D; ++d) {
    const double x0 = X[d], x = X[D + d];
    v += p[0] * x0 * x0 + 2 * p[1] * x0 * x + p[2] * x * x + b[d] * x0 + b[D + d] * x;
  }
  return v;
}

// Which vertices a record does not depend on (exactly zero coefficients): 1 x0, 2 x, 3 both.
int free_vertices(const double* p, std::size_t D)
{
  const double* b = p + 5;
  return (p[1] == 0 && p[0] == 0 && all_zero(b, D) ? 1 : 0) | (p[1] == 0 && p[2] == 0 && all_zero(b + D, D) ? 2 : 0);
}

// Is p <= q wherever q <= T?  Cheap refutations first: p above q at q's minimiser, or where the
// line from p's minimiser through q's leaves {q <= T}.  Then weak duality (the S-lemma): for
// mu >= 0, g(mu) = min over X of (1 + mu) q - p - mu T is at most min (q - p) over {q <= T}, so
// any mu with g(mu) >= 0 proves it.  g is concave with slope q(X_mu) - T at its minimiser X_mu:
// a bisection on the slope's sign, stopped by g >= 0 (yes) or by the tangents at the brackets,
// which bound g from above, falling below 0 (no).  Undecided: no (the lists only grow).
// `units` counts the work.
bool below_where_within(const double* p, const double* q, double T, std::size_t D, std::size_t& units)
{
  ++units;
  const double q_least = q[4];
  if(q_least > T) return true; // nowhere within T
  if(const int q_free = free_vertices(q, D)) {
    // {q <= T} is unbounded along the vertex q ignores: p must ignore it too (a convex function
    // of it is unbounded above), and the test is on the other vertex alone.
    const int p_free = free_vertices(p, D);
    if((p_free & q_free) != q_free) return false;
    if(q_free == 3) return p[3] <= q[3];
    const int on = q_free == 2 ? 0 : 1; // the vertex both depend on: x0 or x
    return vertex_below_where_within(p[on == 0 ? 0 : 2], p + 5 + on * D, p[3], q[on == 0 ? 0 : 2], q + 5 + on * D, q[3], T,
                                     D);
  }
  const bool bounded = q_least > minus_infinity;
  if(bounded) {
    const double* X = q + 5 + 2 * D;
    const double pX = value_at(p, X, D);
    if(pX > q_least) return false;
    if(p[4] > minus_infinity) {
      const double* Y = p + 5 + 2 * D;
      const double* pb = p + 5;
      double vqv = 0, vpv = 0, slope = 0; // along v = X - Y: q's and p's curvature, p's slope at X
      for(std::size_t d = 0; d < D; ++d) {
        const double v0 = X[d] - Y[d], v1 = X[D + d] - Y[D + d];
        vqv += q[0] * v0 * v0 + 2 * q[1] * v0 * v1 + q[2] * v1 * v1;
        vpv += p[0] * v0 * v0 + 2 * p[1] * v0 * v1 + p[2] * v1 * v1;
        slope += (2 * (p[0] * X[d] + p[1] * X[D + d]) + pb[d]) * v0 + (2 * (p[1] * X[d] + p[2] * X[D + d]) + pb[D + d]) * v1;
      }
      if(vqv > 0) {
        const double tau = std::sqrt((T - q_least) / vqv); // q = T there
        if(pX + tau * slope + tau * tau * vpv > T) return false;
      }
    }
  }
  const double *pb = p + 5, *qb = q + 5;
  // g(mu) and its slope; -infinity where (1 + mu) Mq - Mp is not well-conditioned positive definite.
  auto g = [&](double mu, double& slope) {
    ++units;
    const double s = 1 + mu;
    const double h00 = s * q[0] - p[0], h01 = s * q[1] - p[1], h11 = s * q[2] - p[2];
    const double det = h00 * h11 - h01 * h01;
    if(!(h00 > 0 && h11 > 0 && det > 1e-9 * h00 * h11)) return minus_infinity;
    double half_lx = 0, qX = 0;
    for(std::size_t d = 0; d < D; ++d) { // the minimiser solves 2 H X = -l, coordinate by coordinate
      const double l0 = s * qb[d] - pb[d], l1 = s * qb[D + d] - pb[D + d];
      const double x0 = -(h11 * l0 - h01 * l1) / (2 * det), x1 = -(h00 * l1 - h01 * l0) / (2 * det);
      half_lx += 0.5 * (l0 * x0 + l1 * x1);
      qX += q[0] * x0 * x0 + 2 * q[1] * x0 * x1 + q[2] * x1 * x1 + qb[d] * x0 + qb[D + d] * x1;
    }
    slope = qX + q[3] - T;
    return s * q[3] - p[3] - mu * T + half_lx;
  };
  double slope = 0;
  const double at_zero = g(0, slope);
  if(at_zero >= 0) return true; // below everywhere
  if(!bounded) return false;    // {q <= T} unbounded, or q ill-conditioned: that test only
  if(at_zero > minus_infinity && slope <= 0) return false; // g's maximum is at 0
  // The least mu with (1 + mu) Mq - Mp positive definite: the larger root s of det(s Mq - Mp).
  const double A = q[0] * q[2] - q[1] * q[1], B = q[0] * p[2] + q[2] * p[0] - 2 * q[1] * p[1],
               C = p[0] * p[2] - p[1] * p[1];
  double lo = std::max(0.0, (B + std::sqrt(std::max(0.0, B * B - 4 * A * C))) / (2 * A) - 1);
  // Brackets: g rising at lo (or undefined there), falling at hi.
  double hi = std::max(1.0, 2 * lo), g_hi = 0, s_hi = 0;
  for(int grow = 0;; ++grow) {
    g_hi = g(hi, s_hi);
    if(g_hi >= 0) return true;
    if(g_hi > minus_infinity && s_hi < 0) break;
    if(grow == 60) return false;
    lo = hi, hi *= 2;
  }
  double g_lo = minus_infinity, s_lo = 0;
  for(int step = 0; step < 40; ++step) {
    if(g_lo > minus_infinity) {
      const double cross = (g_hi - g_lo + s_lo * lo - s_hi * hi) / (s_lo - s_hi);
      if(g_lo + s_lo * (cross - lo) < 0) return false;
    }
    const double mu = 0.5 * (lo + hi);
    double s_mu = 0;
    const double g_mu = g(mu, s_mu);
    if(g_mu >= 0) return true;
    if(g_mu == minus_infinity || s_mu > 0) lo = mu, g_lo = g_mu, s_lo = s_mu;
    else hi = mu, g_hi = g_mu, s_hi = s_mu;
  }
  return false;
}

} // namespace

void Pair_record::make(double a00, double a01, double a11, const double* b, double c, std::size_t D, double* out)
{
  out[0] = a00, out[1] = a01, out[2] = a11, out[3] = c;
  out[4] = pair_minimum(a00, a01, a11, b, b + D, c, D);
  std::copy_n(b, 2 * D, out + 5);
  double* X = out + 5 + 2 * D;
  std::fill_n(X, 2 * D, 0.0);
  if(!(out[4] > minus_infinity)) return;
  const int free = free_vertices(out, D);
  const double det = a00 * a11 - a01 * a01;
  for(std::size_t d = 0; d < D; ++d) { // 2 M X = -b, coordinate by coordinate; a free vertex at 0
    if(free == 0) {
      X[d] = -(a11 * b[d] - a01 * b[D + d]) / (2 * det);
      X[D + d] = -(a00 * b[D + d] - a01 * b[d]) / (2 * det);
    } else if(free == 2 && a00 > 0) {
      X[d] = -b[d] / (2 * a00);
    } else if(free == 1 && a11 > 0) {
      X[D + d] = -b[D + d] / (2 * a11);
    }
  }
}

void add_pair(const Circle& circle, Pair_quadratics& Q, const double* record, double limit, int node, int index)
{
  if(record[4] > limit) return;
  const std::size_t D = std::size_t(circle.D), stride = Pair_record::size(D);
  std::size_t units = 0;
  for(std::size_t r = 0; r < Q.size(); ++r)
    if(below_where_within(Q.record(r, D), record, limit, D, units)) {
      circle.count_work(units);
      return;
    }
  std::size_t w = 0;
  for(std::size_t r = 0; r < Q.size(); ++r) {
    if(below_where_within(record, Q.record(r, D), limit, D, units)) continue;
    std::copy_n(&Q.records[r * stride], stride, &Q.records[w * stride]);
    Q.from_node[w] = Q.from_node[r];
    Q.from_index[w] = Q.from_index[r];
    ++w;
  }
  Q.records.resize(w * stride);
  Q.from_node.resize(w);
  Q.from_index.resize(w);
  Q.records.insert(Q.records.end(), record, record + stride);
  Q.from_node.push_back(node);
  Q.from_index.push_back(index);
  circle.count_work(units);
}

} // namespace closed_dp
} // namespace internal
} // namespace Spline_approximation
} // namespace CGAL
