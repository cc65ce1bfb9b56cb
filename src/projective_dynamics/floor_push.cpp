// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Projective_dynamics/internal/floor_push.h>

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace CGAL {
namespace Projective_dynamics {
namespace internal {

namespace {

typedef Eigen::SparseMatrix<double, Eigen::RowMajor> Sparse;

// Vertices' rows of U on the problem's columns (numbered locally), stored one after another:
// the Newton steps pass over thousands of them many times per push (the armadillo at rest on
// the floor: ~2,800 rows, ~22 steps), and rows in separate vectors cost a cache miss each.
struct Local_rows
{
  std::vector<int> start{0}, column;
  std::vector<double> value;
  std::size_t size() const { return start.size() - 1; }
  double dot(std::size_t i, const Eigen::VectorXd& y) const
  {
    double s = 0;
    for(int p = start[i]; p < start[i + 1]; ++p) s += value[std::size_t(p)] * y[column[std::size_t(p)]];
    return s;
  }
  void add_outer(std::size_t i, Eigen::MatrixXd& H, double weight) const
  {
    for(int p = start[i]; p < start[i + 1]; ++p)
      for(int q = start[i]; q < start[i + 1]; ++q)
        H(column[std::size_t(p)], column[std::size_t(q)]) += weight * value[std::size_t(p)] * value[std::size_t(q)];
  }
  void add_to(std::size_t i, Eigen::VectorXd& r, double weight) const
  {
    for(int p = start[i]; p < start[i + 1]; ++p) r[column[std::size_t(p)]] += weight * value[std::size_t(p)];
  }
  // Appends the row of U of vertex v on the columns numbered by `local` (-1: not a column of the
  // problem); a column met first is numbered next when `grow`.
  void add_row_of(const Eigen::SparseMatrix<double, Eigen::RowMajor>& U, int v, std::vector<int>& local,
                  std::vector<int>& columns, bool grow)
  {
    for(Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(U, v); it; ++it)
    {
      if(it.value() == 0) continue;
      int& c = local[std::size_t(it.col())];
      if(c < 0 && grow) c = int(columns.size()), columns.push_back(int(it.col()));
      if(c >= 0) column.push_back(c), value.push_back(it.value());
    }
    start.push_back(int(column.size()));
  }
};

// The multiplier loop of both pushes: minimises y^T P y subject to A_i y >= need_i and E_j y = 0.
Eigen::VectorXd solve_push(const Eigen::MatrixXd& P, const Local_rows& A, const Local_rows& E,
                           const Eigen::VectorXd& need, double tolerance, Floor_push_report& r, Eigen::VectorXd* multipliers)
{
  const int m = int(P.rows());
  // The penalty: a thousand times the typical diagonal of P over the typical squared row, so the
  // Newton matrix stays well conditioned (a relative 1e-3 per augmented-Lagrangian update is
  // left of a multiplier's error; the factorization is reused while the active set repeats).
  double row_norms = 0;
  for(double a : A.value) row_norms += a * a;
  for(double e : E.value) row_norms += e * e;
  row_norms /= double(std::max<std::size_t>(1, A.size() + E.size()));
  const double first_rho = 1e3 * P.diagonal().mean() / std::max(row_norms, 1e-300);
  double rho = first_rho;

  Eigen::VectorXd y = Eigen::VectorXd::Zero(m), lambda = Eigen::VectorXd::Zero(Eigen::Index(A.size())),
                  mu = Eigen::VectorXd::Zero(Eigen::Index(E.size()));
  if(multipliers && multipliers->size() == lambda.size()) lambda = multipliers->cwiseMax(0.0);
  std::vector<char> factored_active, active(A.size());
  int updates_since_factoring = 0;
  Eigen::LLT<Eigen::MatrixXd> newton;
  // A y, kept up to date along the steps (the rows are passed once per Newton step).
  Eigen::VectorXd Ay = Eigen::VectorXd::Zero(Eigen::Index(A.size()));
  auto find_active = [&] {
    for(std::size_t i = 0; i < A.size(); ++i) active[i] = need[Eigen::Index(i)] - Ay[Eigen::Index(i)] + lambda[Eigen::Index(i)] / rho > 0;
  };
  auto largest_violation = [&] {
    double worst = 0;
    for(std::size_t i = 0; i < A.size(); ++i) worst = std::max(worst, need[Eigen::Index(i)] - Ay[Eigen::Index(i)]);
    for(std::size_t j = 0; j < E.size(); ++j) worst = std::max(worst, std::abs(E.dot(j, y)));
    return worst;
  };
  // Outer: multiplier updates.  Inner: semismooth Newton on the augmented Lagrangian phi, a
  // convex piecewise quadratic, with a backtracking line search (without it the active set can
  // cycle); a full step that keeps its active set lands on phi's exact minimiser.
  const std::size_t c = A.size(), h = E.size();
  Eigen::VectorXd ay(c), ad(c), ey(h), ed(h);
  double best_violation = std::numeric_limits<double>::infinity(), previous_violation = best_violation;
  int stalled = 0;
  for(int outer = 0; outer < 200; ++outer)
  {
    for(int inner = 0; inner < 50; ++inner)
    {
      find_active();
      if(active != factored_active)
      {
        // A few rows in or out: rank-one updates of the factor (O(m^2) each, against O(m^3) for
        // a new factorization); many, a downdate that loses definiteness, or a new penalty:
        // factor anew.
        std::vector<std::size_t> changed;
        if(factored_active.size() == c)
          for(std::size_t i = 0; i < c && changed.size() * 8 <= std::size_t(m); ++i)
            if(active[i] != factored_active[i]) changed.push_back(i);
        // (at most m / 2 updates between factorizations: rounding accumulates in the factor)
        bool updated = factored_active.size() == c && changed.size() * 8 <= std::size_t(m) &&
                       2 * (updates_since_factoring + int(changed.size())) <= m;
        if(updated)
        {
          Eigen::VectorXd v(m);
          for(std::size_t i : changed)
          {
            v.setZero();
            A.add_to(i, v, std::sqrt(rho));
            newton.rankUpdate(v, active[i] ? 1.0 : -1.0);
            if(newton.info() != Eigen::Success)
            {
              updated = false;
              break;
            }
          }
          updates_since_factoring += int(changed.size());
        }
        if(!updated)
        {
          Eigen::MatrixXd H = P;
          for(std::size_t i = 0; i < c; ++i)
            if(active[i]) A.add_outer(i, H, rho);
          for(std::size_t j = 0; j < E.size(); ++j) E.add_outer(j, H, rho);
          newton.compute(H);
          ++r.factorizations;
          updates_since_factoring = 0;
        }
        factored_active = active;
      }
      Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m);
      for(std::size_t i = 0; i < c; ++i)
        if(active[i]) A.add_to(i, rhs, rho * need[Eigen::Index(i)] + lambda[Eigen::Index(i)]);
      for(std::size_t j = 0; j < h; ++j) E.add_to(j, rhs, -mu[Eigen::Index(j)]);
      const Eigen::VectorXd d = newton.solve(rhs) - y;
      // phi along y + t d, from the products at y and along d (each trial costs the rows only).
      const Eigen::VectorXd Py = P * y, Pd = P * d;
      for(std::size_t i = 0; i < c; ++i)
        ay[Eigen::Index(i)] = need[Eigen::Index(i)] - Ay[Eigen::Index(i)] + lambda[Eigen::Index(i)] / rho, ad[Eigen::Index(i)] = A.dot(i, d);
      for(std::size_t j = 0; j < h; ++j) ey[Eigen::Index(j)] = E.dot(j, y) + mu[Eigen::Index(j)] / rho, ed[Eigen::Index(j)] = E.dot(j, d);
      // Only rows positive somewhere on [0, 1] enter phi there (g is linear in t).
      std::vector<Eigen::Index> touching;
      for(std::size_t i = 0; i < c; ++i)
        if(ay[Eigen::Index(i)] > 0 || ay[Eigen::Index(i)] - ad[Eigen::Index(i)] > 0) touching.push_back(Eigen::Index(i));
      const double dPy = d.dot(Py), dPd = d.dot(Pd);
      auto phi = [&](double t) {
        double value = t * dPy + 0.5 * t * t * dPd;
        for(Eigen::Index i : touching)
        {
          const double g = ay[i] - t * ad[i];
          if(g > 0) value += 0.5 * rho * g * g;
        }
        for(std::size_t j = 0; j < h; ++j)
        {
          const double e = ey[Eigen::Index(j)] + t * ed[Eigen::Index(j)];
          value += 0.5 * rho * e * e;
        }
        return value;
      };
      double slope = d.dot(Py);
      for(std::size_t i = 0; i < c; ++i)
        if(ay[Eigen::Index(i)] > 0) slope -= rho * ay[Eigen::Index(i)] * ad[Eigen::Index(i)];
      for(std::size_t j = 0; j < h; ++j) slope += rho * ey[Eigen::Index(j)] * ed[Eigen::Index(j)];
      const double value = phi(0);
      double t = 1;
      while(t > 1e-10 && phi(t) > value + 1e-4 * t * slope) t *= 0.5;
      y += t * d;
      Ay += t * ad;
      find_active();
      if(t == 1 && active == factored_active) break;
    }
    for(std::size_t i = 0; i < c; ++i)
      lambda[Eigen::Index(i)] = std::max(0.0, lambda[Eigen::Index(i)] + rho * (need[Eigen::Index(i)] - Ay[Eigen::Index(i)]));
    for(std::size_t j = 0; j < h; ++j) mu[Eigen::Index(j)] += rho * E.dot(j, y);
    r.largest_violation = largest_violation();
    r.updates = outer + 1;
    if(r.largest_violation <= tolerance) break;
    // Slow progress (multipliers of nearly dependent contacts) calls for a stiffer penalty, up
    // to 1e6 times the first; once it is there, rounding sets a floor under the violation (the
    // Newton matrix's condition number times the unit round-off): stop once ten updates in a
    // row did not halve the best violation.
    if(r.largest_violation > 0.25 * previous_violation && rho < 1e6 * first_rho)
      rho *= 10, factored_active.clear();
    previous_violation = r.largest_violation;
    if(r.largest_violation < 0.5 * best_violation) best_violation = r.largest_violation, stalled = 0;
    else if(++stalled == 10) break;
  }
  if(multipliers) *multipliers = lambda;
  return y;
}

} // namespace

Eigen::VectorXd smallest_floor_push(const Sparse& U, const Eigen::MatrixXd& Mr_inverse, const std::vector<int>& rows,
                                    const Eigen::VectorXd& need, const std::vector<int>& held, double tolerance,
                                    Floor_push_report* report, Eigen::VectorXd* multipliers)
{
  const int k = int(U.cols());
  // The columns the rows touch, numbered locally.
  std::vector<int> local(std::size_t(k), -1), columns;
  Local_rows A, E;
  for(int v : rows) A.add_row_of(U, v, local, columns, true);
  for(int v : held) E.add_row_of(U, v, local, columns, true);
  const int m = int(columns.size());
  Floor_push_report r;
  r.columns = m, r.constraints = int(rows.size());
  Eigen::VectorXd delta = Eigen::VectorXd::Zero(k);
  if(m > 0)
  {
    // P = Minv(C, C)^-1: the metric of delta_C once the other columns take their cheapest values.
    const Eigen::MatrixXd B = Mr_inverse(columns, columns);
    const Eigen::MatrixXd P = B.llt().solve(Eigen::MatrixXd::Identity(m, m));
    const Eigen::VectorXd z = P * solve_push(P, A, E, need, tolerance, r, multipliers);
    for(int a = 0; a < m; ++a) delta += Mr_inverse.col(columns[std::size_t(a)]) * z[a];
  }
  if(report) *report = r;
  return delta;
}

Push_subspace push_subspace(const Sparse& U, const Eigen::MatrixXd& Mr, const std::vector<int>& push_columns)
{
  Push_subspace p;
  p.columns = push_columns;
  std::vector<int> local(std::size_t(U.cols()), -1);
  for(std::size_t a = 0; a < push_columns.size(); ++a) local[std::size_t(push_columns[a])] = int(a);
  std::vector<Eigen::Triplet<double>> entries;
  for(Eigen::Index v = 0; v < U.rows(); ++v)
    for(Sparse::InnerIterator it(U, v); it; ++it)
      if(local[std::size_t(it.col())] >= 0) entries.emplace_back(int(v), local[std::size_t(it.col())], it.value());
  p.U.resize(U.rows(), Eigen::Index(push_columns.size()));
  p.U.setFromTriplets(entries.begin(), entries.end());
  const Eigen::MatrixXd M = Mr(push_columns, push_columns);
  p.Mr_inverse = M.llt().solve(Eigen::MatrixXd::Identity(M.rows(), M.cols()));
  return p;
}

Eigen::VectorXd smallest_floor_push_in(const Sparse& U, const Eigen::MatrixXd& Mr, const std::vector<int>& push_columns,
                                       const std::vector<int>& rows, const Eigen::VectorXd& need, const std::vector<int>& held,
                                       double tolerance, Floor_push_report* report, Eigen::VectorXd* multipliers)
{
  const Push_subspace p = push_subspace(U, Mr, push_columns);
  const Eigen::VectorXd pushed = smallest_floor_push(p.U, p.Mr_inverse, rows, need, held, tolerance, report, multipliers);
  Eigen::VectorXd delta = Eigen::VectorXd::Zero(U.cols());
  for(std::size_t a = 0; a < push_columns.size(); ++a) delta[push_columns[a]] = pushed[Eigen::Index(a)];
  return delta;
}

} // namespace internal
} // namespace Projective_dynamics
} // namespace CGAL
