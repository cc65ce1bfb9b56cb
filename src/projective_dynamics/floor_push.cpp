// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Projective_dynamics/internal/floor_push.h>

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <utility>

namespace CGAL {
namespace Projective_dynamics {
namespace internal {

namespace {

typedef Eigen::SparseMatrix<double, Eigen::RowMajor> Sparse;

// A vertex's row of U on the local columns.
struct Local_row
{
  std::vector<std::pair<int, double>> entries;
  double dot(const Eigen::VectorXd& y) const
  {
    double s = 0;
    for(const auto& e : entries) s += e.second * y[e.first];
    return s;
  }
  void add_outer(Eigen::MatrixXd& H, double weight) const
  {
    for(const auto& a : entries)
      for(const auto& b : entries) H(a.first, b.first) += weight * a.second * b.second;
  }
  void add_to(Eigen::VectorXd& r, double weight) const
  {
    for(const auto& e : entries) r[e.first] += weight * e.second;
  }
};

} // namespace

Eigen::VectorXd smallest_floor_push(const Sparse& U, const Eigen::MatrixXd& Mr_inverse, const std::vector<int>& rows,
                                    const Eigen::VectorXd& need, const std::vector<int>& held, double tolerance,
                                    Floor_push_report* report)
{
  const int k = int(U.cols());
  // The columns the rows touch, numbered locally.
  std::vector<int> local(std::size_t(k), -1), columns;
  auto local_row = [&](int v) {
    Local_row row;
    for(Sparse::InnerIterator it(U, v); it; ++it)
    {
      if(it.value() == 0) continue;
      int& c = local[std::size_t(it.col())];
      if(c < 0) c = int(columns.size()), columns.push_back(int(it.col()));
      row.entries.emplace_back(c, it.value());
    }
    return row;
  };
  std::vector<Local_row> A, E;
  for(int v : rows) A.push_back(local_row(v));
  for(int v : held) E.push_back(local_row(v));
  const int m = int(columns.size());
  Floor_push_report r;
  r.columns = m, r.constraints = int(rows.size());
  if(m == 0)
  {
    if(report) *report = r;
    return Eigen::VectorXd::Zero(k);
  }

  // P = Minv(C, C)^-1: the metric of delta_C once the other columns take their cheapest values.
  Eigen::MatrixXd B(m, m);
  for(int a = 0; a < m; ++a)
    for(int b = 0; b < m; ++b) B(a, b) = Mr_inverse(columns[std::size_t(a)], columns[std::size_t(b)]);
  const Eigen::MatrixXd P = B.llt().solve(Eigen::MatrixXd::Identity(m, m));

  // The penalty: a thousand times the typical diagonal of P over the typical squared row, so the
  // Newton matrix stays well conditioned (a relative 1e-3 per augmented-Lagrangian update is
  // left of a multiplier's error; the factorization is reused while the active set repeats).
  double row_norms = 0;
  for(const Local_row& row : A)
    for(const auto& e : row.entries) row_norms += e.second * e.second;
  for(const Local_row& row : E)
    for(const auto& e : row.entries) row_norms += e.second * e.second;
  row_norms /= double(std::max<std::size_t>(1, A.size() + E.size()));
  const double rho = 1e3 * P.diagonal().mean() / std::max(row_norms, 1e-300);

  Eigen::VectorXd y = Eigen::VectorXd::Zero(m), lambda = Eigen::VectorXd::Zero(Eigen::Index(A.size())),
                  mu = Eigen::VectorXd::Zero(Eigen::Index(E.size()));
  std::vector<char> factored_active, active(A.size());
  Eigen::LLT<Eigen::MatrixXd> newton;
  auto find_active = [&] {
    for(std::size_t i = 0; i < A.size(); ++i) active[i] = need[Eigen::Index(i)] - A[i].dot(y) + lambda[Eigen::Index(i)] / rho > 0;
  };
  auto largest_violation = [&] {
    double worst = 0;
    for(std::size_t i = 0; i < A.size(); ++i) worst = std::max(worst, need[Eigen::Index(i)] - A[i].dot(y));
    for(const Local_row& row : E) worst = std::max(worst, std::abs(row.dot(y)));
    return worst;
  };
  // The augmented Lagrangian phi(y) (up to a constant) and its gradient.
  auto phi = [&](const Eigen::VectorXd& v) {
    double value = 0.5 * v.dot(P * v);
    for(std::size_t i = 0; i < A.size(); ++i)
    {
      const double g = need[Eigen::Index(i)] - A[i].dot(v) + lambda[Eigen::Index(i)] / rho;
      if(g > 0) value += 0.5 * rho * g * g;
    }
    for(std::size_t j = 0; j < E.size(); ++j)
    {
      const double e = E[j].dot(v) + mu[Eigen::Index(j)] / rho;
      value += 0.5 * rho * e * e;
    }
    return value;
  };
  auto gradient = [&](const Eigen::VectorXd& v) {
    Eigen::VectorXd g = P * v;
    for(std::size_t i = 0; i < A.size(); ++i)
    {
      const double gi = need[Eigen::Index(i)] - A[i].dot(v) + lambda[Eigen::Index(i)] / rho;
      if(gi > 0) A[i].add_to(g, -rho * gi);
    }
    for(std::size_t j = 0; j < E.size(); ++j) E[j].add_to(g, rho * (E[j].dot(v) + mu[Eigen::Index(j)] / rho));
    return g;
  };
  // Outer: multiplier updates.  Inner: semismooth Newton on phi, a convex piecewise quadratic,
  // with a backtracking line search (without it the active set can cycle); a full step that
  // keeps its active set lands on phi's exact minimiser.
  for(int outer = 0; outer < 200; ++outer)
  {
    for(int inner = 0; inner < 50; ++inner)
    {
      find_active();
      if(active != factored_active)
      {
        Eigen::MatrixXd H = P;
        for(std::size_t i = 0; i < A.size(); ++i)
          if(active[i]) A[i].add_outer(H, rho);
        for(const Local_row& row : E) row.add_outer(H, rho);
        newton.compute(H);
        factored_active = active;
        ++r.factorizations;
      }
      Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m);
      for(std::size_t i = 0; i < A.size(); ++i)
        if(active[i]) A[i].add_to(rhs, rho * need[Eigen::Index(i)] + lambda[Eigen::Index(i)]);
      for(std::size_t j = 0; j < E.size(); ++j) E[j].add_to(rhs, -mu[Eigen::Index(j)]);
      const Eigen::VectorXd step = newton.solve(rhs) - y;
      const double value = phi(y), slope = gradient(y).dot(step);
      double t = 1;
      while(t > 1e-10 && phi(y + t * step) > value + 1e-4 * t * slope) t *= 0.5;
      y += t * step;
      find_active();
      if(t == 1 && active == factored_active) break;
    }
    for(std::size_t i = 0; i < A.size(); ++i)
      lambda[Eigen::Index(i)] = std::max(0.0, lambda[Eigen::Index(i)] + rho * (need[Eigen::Index(i)] - A[i].dot(y)));
    for(std::size_t j = 0; j < E.size(); ++j) mu[Eigen::Index(j)] += rho * E[j].dot(y);
    r.largest_violation = largest_violation();
    r.updates = outer + 1;
    if(r.largest_violation <= tolerance) break;
  }
  Eigen::VectorXd delta = Eigen::VectorXd::Zero(k);
  const Eigen::VectorXd z = P * y;
  for(int a = 0; a < m; ++a) delta += Mr_inverse.col(columns[std::size_t(a)]) * z[a];
  if(report) *report = r;
  return delta;
}

} // namespace internal
} // namespace Projective_dynamics
} // namespace CGAL
