// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "working_set.h"

#include <Eigen/QR>

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace Vibration_modes {
namespace internal {

Group_set support_of(const Mode_problem& p, const Eigen::VectorXd& u)
{
  const int g = p.group_size;
  Group_set set(std::size_t(u.size() / g), 0);
  for(std::size_t v = 0; v < set.size(); ++v) set[v] = u.segment(g * Eigen::Index(v), g).squaredNorm() > 0;
  return set;
}

void grow(const Mode_problem& p, Group_set& set, int rings)
{
  const int g = p.group_size;
  for(int ring = 0; ring < rings; ++ring)
  {
    Group_set next = set;
    // H is symmetric: the column of an unknown lists its neighbours.
    for(Eigen::Index col = 0; col < p.H.outerSize(); col += g)
      if(set[std::size_t(col / g)])
        for(Eigen::SparseMatrix<double>::InnerIterator it(p.H, col); it; ++it) next[std::size_t(it.row() / g)] = 1;
    set.swap(next);
  }
}

std::size_t size_of(const Group_set& set) { return std::size_t(std::count(set.begin(), set.end(), 1)); }

Restricted_problem::Restricted_problem(const Mode_problem& p, const Group_set& set)
{
  const int g = p.group_size;
  std::vector<Eigen::Index> local(std::size_t(p.H.rows()), -1);
  for(std::size_t v = 0; v < set.size(); ++v)
    if(set[v])
      for(int k = 0; k < g; ++k)
      {
        local[std::size_t(g * v + k)] = Eigen::Index(unknowns.size());
        unknowns.push_back(Eigen::Index(g * v + k));
      }
  const Eigen::Index n = Eigen::Index(unknowns.size());
  std::vector<Eigen::Triplet<double>> entries;
  for(Eigen::Index j = 0; j < n; ++j)
    for(Eigen::SparseMatrix<double>::InnerIterator it(p.H, unknowns[std::size_t(j)]); it; ++it)
      if(local[std::size_t(it.row())] >= 0) entries.emplace_back(local[std::size_t(it.row())], j, it.value());
  problem.H.resize(n, n);
  problem.H.setFromTriplets(entries.begin(), entries.end());
  problem.mass.resize(n);
  for(Eigen::Index j = 0; j < n; ++j) problem.mass[j] = p.mass[unknowns[std::size_t(j)]];
  problem.kernel.resize(n, 0);
  problem.group_size = g;
  problem.full_size = n;
}

Eigen::MatrixXd Restricted_problem::restrict(const Eigen::MatrixXd& X) const
{
  Eigen::MatrixXd R(Eigen::Index(unknowns.size()), X.cols());
  for(std::size_t j = 0; j < unknowns.size(); ++j) R.row(Eigen::Index(j)) = X.row(unknowns[j]);
  return R;
}

Eigen::VectorXd Restricted_problem::expand(const Eigen::VectorXd& x, Eigen::Index full_rows) const
{
  Eigen::VectorXd full = Eigen::VectorXd::Zero(full_rows);
  for(std::size_t j = 0; j < unknowns.size(); ++j) full[unknowns[j]] = x[Eigen::Index(j)];
  return full;
}

Eigen::MatrixXd m_orthonormal(const Eigen::MatrixXd& X, const Eigen::VectorXd& mass)
{
  Eigen::MatrixXd Q(X.rows(), 0);
  for(Eigen::Index j = 0; j < X.cols(); ++j)
  {
    Eigen::VectorXd v = X.col(j);
    const double before = std::sqrt(v.dot(mass.cwiseProduct(v)));
    for(int pass = 0; pass < 2; ++pass)
      for(Eigen::Index i = 0; i < Q.cols(); ++i) v -= Q.col(i).dot(mass.cwiseProduct(v)) * Q.col(i);
    const double after = std::sqrt(v.dot(mass.cwiseProduct(v)));
    if(!(after > 1e-10 * before)) continue;
    Q.conservativeResize(Eigen::NoChange, Q.cols() + 1);
    Q.col(Q.cols() - 1) = v / after;
  }
  return Q;
}

Eigen::VectorXd first_order_multipliers(const Mode_problem& p, const Eigen::MatrixXd& F, const Eigen::VectorXd& u,
                                        double mu)
{
  const int g = p.group_size;
  const Eigen::VectorXd Hu2 = 2 * (p.H * u);
  std::vector<Eigen::Index> rows;
  for(Eigen::Index v = 0; v < u.size(); v += g)
    if(u.segment(v, g).squaredNorm() > 0)
      for(int k = 0; k < g; ++k) rows.push_back(v + k);
  Eigen::MatrixXd A(Eigen::Index(rows.size()), 1 + F.cols());
  Eigen::VectorXd b(A.rows());
  for(std::size_t r = 0; r < rows.size(); ++r)
  {
    const Eigen::Index j = rows[r], v = j - j % g;
    const double m = p.mass[j], w = 1 / std::sqrt(m);
    A(Eigen::Index(r), 0) = w * 2 * m * u[j];
    A.row(Eigen::Index(r)).tail(F.cols()) = w * m * F.row(j);
    b[Eigen::Index(r)] = w * (Hu2[j] + mu * m * u[j] / u.segment(v, g).norm());
  }
  return A.colPivHouseholderQr().solve(b);
}

std::vector<Eigen::Index> violations_outside(const Mode_problem& p, const Eigen::MatrixXd& F, const Eigen::VectorXd& u,
                                             double mu, const Group_set& set, double slack)
{
  const int g = p.group_size;
  const Eigen::VectorXd Hu2 = 2 * (p.H * u);
  const Eigen::VectorXd Fnu = F * first_order_multipliers(p, F, u, mu).tail(F.cols());
  std::vector<Eigen::Index> violated;
  for(std::size_t v = 0; v < set.size(); ++v)
  {
    if(set[v]) continue;
    const Eigen::Index j = g * Eigen::Index(v);
    const double m = p.mass[j];
    if((Hu2.segment(j, g) - m * Fnu.segment(j, g)).norm() > mu * m * (1 + slack)) violated.push_back(Eigen::Index(v));
  }
  return violated;
}

} // namespace internal
} // namespace Vibration_modes
} // namespace CGAL
