// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// B-spline basis functions, the banded design and jump matrices, and curve evaluation.

#include <CGAL/Spline_approximation/B_spline.h>
#include <CGAL/Spline_approximation/internal/spline_numerics.h>

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace Spline_approximation {
namespace internal {
namespace {

// The k-th derivative of N_{i,k}, constant on each span l = i .. i+k: c[l - i].  Differentiating
// k times by N'_{l,p} = p (N_{l,p-1} / (U_{l+p} - U_l) - N_{l+1,p-1} / (U_{l+p+1} - U_{l+1})).
void kth_derivative_on_spans(const Eigen::VectorXd& U, int k, Eigen::Index i, double* c)
{
  for(int q = 0; q <= k; ++q) c[q] = q == 0 ? 1.0 : 0.0;
  for(int p = k; p >= 1; --p) {
    double next[5] = {0, 0, 0, 0, 0};
    for(int q = 0; q <= k - p; ++q) {
      const Eigen::Index l = i + q;
      const double a = U[l + p] - U[l], b = U[l + p + 1] - U[l + 1];
      if(a > 0) next[q] += c[q] * p / a;
      if(b > 0) next[q + 1] -= c[q] * p / b;
    }
    for(int q = 0; q <= k; ++q) c[q] = next[q];
  }
}

} // namespace

// Column by column with the row's entries in registers: Eigen's row expressions on a
// column-major matrix of 2 or 3 columns cost more than the arithmetic (these two products are
// most of a least-squares fit on a million samples).
Eigen::MatrixXd Band_rows::times(const Eigen::MatrixXd& X) const
{
  Eigen::MatrixXd out(rows(), X.cols());
  const Eigen::Index w = values.cols();
  for(Eigen::Index c = 0; c < X.cols(); ++c) {
    const double* x = X.col(c).data();
    double* o = out.col(c).data();
    for(Eigen::Index r = 0; r < rows(); ++r) {
      double sum = 0;
      if(wrap > 0) for(Eigen::Index q = 0; q < w; ++q) sum += values(r, q) * x[column(r, q)];
      else for(Eigen::Index q = 0; q < w; ++q) sum += values(r, q) * x[first[r] + q];
      o[r] = sum;
    }
  }
  return out;
}

void Band_rows::add_transpose_times(const Eigen::MatrixXd& Y, double w, Eigen::MatrixXd& out) const
{
  const Eigen::Index width = values.cols();
  for(Eigen::Index c = 0; c < Y.cols(); ++c) {
    const double* y = Y.col(c).data();
    double* o = out.col(c).data();
    for(Eigen::Index r = 0; r < rows(); ++r) {
      const double wy = w * y[r];
      if(wrap > 0) for(Eigen::Index q = 0; q < width; ++q) o[column(r, q)] += values(r, q) * wy;
      else for(Eigen::Index q = 0; q < width; ++q) o[first[r] + q] += values(r, q) * wy;
    }
  }
}

Eigen::VectorXd clamped_knots(const Eigen::VectorXd& interior, int degree)
{
  Eigen::VectorXd U(interior.size() + 2 * (degree + 1));
  U.head(degree + 1).setZero();
  U.segment(degree + 1, interior.size()) = interior;
  U.tail(degree + 1).setOnes();
  return U;
}

Basis make_basis(const Eigen::VectorXd& knots, int degree, bool closed)
{
  Basis b;
  b.degree = degree;
  b.closed = closed;
  b.knots = knots.size();
  if(!closed) {
    b.U = clamped_knots(knots, degree);
    b.controls = b.U.size() - degree - 1;
    return b;
  }
  const Eigen::VectorXd u = knots.size() > 0 ? knots : Eigen::VectorXd::Zero(1);
  const Eigen::Index m = u.size();
  // U[i] = u[(i - k - 1) mod m] + floor((i - k - 1) / m), so that U[k + 1] = u[0]: every t in
  // [0, 1) has its span between U[k] (u[m-1] - 1 < 0) and U[m + k + 1] (u[0] + 1 > t), and
  // the k + 1 basis functions there, with their knots, inside the vector.
  b.U.resize(m + 2 * degree + 2);
  for(Eigen::Index i = 0; i < b.U.size(); ++i) {
    const Eigen::Index shifted = i - degree - 1;
    const Eigen::Index period = shifted >= 0 ? shifted / m : -((-shifted + m - 1) / m);
    b.U[i] = u[shifted - period * m] + double(period);
  }
  b.controls = m;
  return b;
}

Band_rows design_rows(const Basis& b, const Eigen::VectorXd& t)
{
  const int k = b.degree;
  Band_rows A;
  A.wrap = b.closed ? b.controls : 0;
  A.first.resize(t.size());
  A.values.resize(t.size(), k + 1);
  double N[4];
  Basis_at basis(b);
  for(Eigen::Index j = 0; j < t.size(); ++j) {
    A.first[j] = int(basis(t[j], N));
    for(int q = 0; q <= k; ++q) A.values(j, q) = N[q];
  }
  return A;
}

Band_rows jump_rows(const Basis& b)
{
  const int k = b.degree;
  const Eigen::Index m = b.knots;
  Band_rows J;
  J.wrap = b.closed ? b.controls : 0;
  J.first.resize(m);
  J.values.resize(m, k + 2);
  double c[5];
  for(Eigen::Index r = 0; r < m; ++r) {
    const Eigen::Index s = k + 1 + r; // U[s] is the r-th knot, interior or on the circle
    J.first[r] = int(s - k - 1);
    for(Eigen::Index i = s - k - 1; i <= s; ++i) {
      kth_derivative_on_spans(b.U, k, i, c);
      const double right = (s - i >= 0 && s - i <= k) ? c[s - i] : 0.0;
      const double left = (s - 1 - i >= 0 && s - 1 - i <= k) ? c[s - 1 - i] : 0.0;
      J.values(r, i - (s - k - 1)) = right - left;
    }
    // The norm of the row as it acts on the control points: with fewer than k + 2 wrapped
    // control points, entries landing in one column add first.
    double norm = J.values.row(r).norm();
    if(J.wrap > 0 && J.wrap < k + 2) {
      Eigen::VectorXd acting = Eigen::VectorXd::Zero(J.wrap);
      for(Eigen::Index q = 0; q < k + 2; ++q) acting[J.column(r, q)] += J.values(r, q);
      // A row that cancels out (one knot on the circle: only constants) stays zero, not roundoff scaled up.
      norm = acting.norm() > 1e-12 * norm ? acting.norm() : 0.0;
      if(norm == 0) J.values.row(r).setZero();
    }
    if(norm > 0) J.values.row(r) /= norm;
  }
  return J;
}

} // namespace internal

Eigen::RowVectorXd B_spline::operator()(double t) const
{
  Eigen::VectorXd one(1);
  one[0] = t;
  return evaluate(one).row(0);
}

Eigen::MatrixXd B_spline::evaluate(const Eigen::VectorXd& t) const
{
  if(closed) { // knots on the circle; t wraps with period 1
    const Eigen::VectorXd c = t.array() - t.array().floor();
    return internal::design_rows(internal::make_basis(knots, degree, true), c.cwiseMin(std::nextafter(1.0, 0.0)))
        .times(control_points);
  }
  const Eigen::VectorXd c = t.cwiseMax(knots[0]).cwiseMin(knots[knots.size() - 1]);
  internal::Basis b;
  b.U = knots;
  b.degree = degree;
  b.controls = control_points.rows();
  return internal::design_rows(b, c).times(control_points);
}

} // namespace Spline_approximation
} // namespace CGAL
