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

// The span s (k <= s < number of control points) with U[s] <= t < U[s+1]; the last span for t at the end.
Eigen::Index find_span(const Eigen::VectorXd& U, int k, double t)
{
  const Eigen::Index n_ctrl = U.size() - k - 1;
  if(t >= U[n_ctrl]) return n_ctrl - 1;
  if(t <= U[k]) return k;
  const double* it = std::upper_bound(U.data() + k, U.data() + n_ctrl + 1, t);
  return Eigen::Index(it - U.data()) - 1;
}

// The k + 1 basis functions N_{s-k..s} nonzero on span s, at t (Cox-de Boor, triangular scheme).
void basis_functions(const Eigen::VectorXd& U, int k, Eigen::Index s, double t, double* N)
{
  double left[4], right[4];
  N[0] = 1.0;
  for(int j = 1; j <= k; ++j) {
    left[j] = t - U[s + 1 - j];
    right[j] = U[s + j] - t;
    double saved = 0.0;
    for(int r = 0; r < j; ++r) {
      const double tmp = N[r] / (right[r + 1] + left[j - r]);
      N[r] = saved + right[r + 1] * tmp;
      saved = left[j - r] * tmp;
    }
    N[j] = saved;
  }
}

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

Eigen::MatrixXd Band_rows::times(const Eigen::MatrixXd& X) const
{
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(rows(), X.cols());
  for(Eigen::Index r = 0; r < rows(); ++r)
    for(Eigen::Index q = 0; q < values.cols(); ++q) out.row(r) += values(r, q) * X.row(first[r] + q);
  return out;
}

void Band_rows::add_transpose_times(const Eigen::MatrixXd& Y, double w, Eigen::MatrixXd& out) const
{
  for(Eigen::Index r = 0; r < rows(); ++r)
    for(Eigen::Index q = 0; q < values.cols(); ++q) out.row(first[r] + q) += (w * values(r, q)) * Y.row(r);
}

Eigen::VectorXd clamped_knots(const Eigen::VectorXd& interior, int degree)
{
  Eigen::VectorXd U(interior.size() + 2 * (degree + 1));
  U.head(degree + 1).setZero();
  U.segment(degree + 1, interior.size()) = interior;
  U.tail(degree + 1).setOnes();
  return U;
}

Band_rows design_rows(const Eigen::VectorXd& U, int k, const Eigen::VectorXd& t)
{
  Band_rows A;
  A.first.resize(t.size());
  A.values.resize(t.size(), k + 1);
  double N[4];
  for(Eigen::Index j = 0; j < t.size(); ++j) {
    const Eigen::Index s = find_span(U, k, t[j]);
    basis_functions(U, k, s, t[j], N);
    A.first[j] = int(s - k);
    for(int q = 0; q <= k; ++q) A.values(j, q) = N[q];
  }
  return A;
}

Band_rows jump_rows(const Eigen::VectorXd& U, int k)
{
  const Eigen::Index n_ctrl = U.size() - k - 1, m = n_ctrl - k - 1;
  Band_rows J;
  J.first.resize(m);
  J.values.resize(m, k + 2);
  double c[5];
  for(Eigen::Index r = 0; r < m; ++r) {
    const Eigen::Index s = k + 1 + r; // U[s] is the r-th interior knot
    J.first[r] = int(s - k - 1);
    for(Eigen::Index i = s - k - 1; i <= s; ++i) {
      kth_derivative_on_spans(U, k, i, c);
      const double right = (s - i >= 0 && s - i <= k) ? c[s - i] : 0.0;
      const double left = (s - 1 - i >= 0 && s - 1 - i <= k) ? c[s - 1 - i] : 0.0;
      J.values(r, i - (s - k - 1)) = right - left;
    }
    const double norm = J.values.row(r).norm();
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
  const Eigen::VectorXd c = t.cwiseMax(knots[0]).cwiseMin(knots[knots.size() - 1]);
  return internal::design_rows(knots, degree, c).times(control_points);
}

} // namespace Spline_approximation
} // namespace CGAL
