// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Vibration_modes/Mode_problem.h>
#include <CGAL/Vibration_modes/errors.h>

#include "connected_components.h"

#include <Eigen/Dense>

#include <cmath>
#include <numeric>
#include <string>

namespace CGAL {
namespace Vibration_modes {

void Mode_problem::check() const
{
  const Eigen::Index n = H.rows();
  if(H.cols() != n || n == 0) throw Invalid_input("mode problem: H must be square and non-empty");
  if(mass.size() != n)
    throw Invalid_input("mode problem: " + std::to_string(mass.size()) + " masses for " + std::to_string(n) +
                        " unknowns");
  if(group_size < 1 || n % group_size != 0)
    throw Invalid_input("mode problem: group size " + std::to_string(group_size) + " does not divide " +
                        std::to_string(n) + " unknowns");
  for(Eigen::Index i = 0; i < n; ++i)
  {
    if(!(mass[i] > 0) || !std::isfinite(mass[i]))
      throw Invalid_input("mode problem: the mass of unknown " + std::to_string(i) + " is " +
                          std::to_string(mass[i]) + ", not finite and positive");
    if(mass[i] != mass[i - i % group_size])
      throw Invalid_input("mode problem: unknown " + std::to_string(i) + " has a mass other than its group's");
  }
  if(kernel.cols() > 0 && kernel.rows() != n)
    throw Invalid_input("mode problem: the kernel has " + std::to_string(kernel.rows()) + " rows for " +
                        std::to_string(n) + " unknowns");
  for(int k = 0; k < H.outerSize(); ++k)
    for(Eigen::SparseMatrix<double>::InnerIterator it(H, k); it; ++it)
      if(!std::isfinite(it.value())) throw Invalid_input("mode problem: H has a non-finite entry");
  if(!free_unknowns.empty() && Eigen::Index(free_unknowns.size()) != n)
    throw Invalid_input("mode problem: the free unknowns do not match H");
}

Eigen::MatrixXd Mode_problem::expand(const Eigen::MatrixXd& free_vectors) const
{
  if(free_unknowns.empty()) return free_vectors;
  Eigen::MatrixXd full = Eigen::MatrixXd::Zero(full_size, free_vectors.cols());
  for(std::size_t i = 0; i < free_unknowns.size(); ++i) full.row(free_unknowns[i]) = free_vectors.row(Eigen::Index(i));
  return full;
}

namespace internal {

std::vector<int> connected_components(Eigen::Index n,
                                      const std::vector<Discrete_shells::Shell_energy::Triangle>& triangles, int& count)
{
  std::vector<int> parent(std::size_t(n), -1);
  auto find = [&](int v) {
    while(parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for(const auto& t : triangles)
    for(int v : t)
      if(parent[v] < 0) parent[v] = v;
  for(const auto& t : triangles)
  {
    const int a = find(t[0]);
    for(int i = 1; i < 3; ++i)
    {
      const int b = find(t[i]);
      if(a != b) parent[b] = a;
    }
  }
  std::vector<int> label(std::size_t(n), -1), id(std::size_t(n), -1);
  count = 0;
  for(int v = 0; v < n; ++v)
    if(parent[v] >= 0)
    {
      const int r = find(v);
      if(id[r] < 0) id[r] = count++;
      label[v] = id[r];
    }
  return label;
}

} // namespace internal

Eigen::MatrixXd rigid_motions(const Eigen::VectorXd& x, const std::vector<Discrete_shells::Shell_energy::Triangle>& triangles,
                              const std::vector<int>& pinned)
{
  const Eigen::Index n = x.size() / 3;
  int count = 0;
  const std::vector<int> label = internal::connected_components(n, triangles, count);
  std::vector<std::vector<int>> members(count), pins(count);
  for(int v = 0; v < n; ++v)
    if(label[v] >= 0) members[label[v]].push_back(v);
  for(int p : pinned)
    if(p >= 0 && p < n && label[p] >= 0) pins[label[p]].push_back(p);

  std::vector<Eigen::VectorXd> columns;
  for(int c = 0; c < count; ++c)
  {
    // Coordinates about the centroid in units of the component's size, so that the six
    // motions are equally scaled and the pins' rank test below is scale-free.
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for(int v : members[c]) centre += x.segment<3>(3 * v);
    centre /= double(members[c].size());
    double size = 0;
    for(int v : members[c]) size = std::max(size, (x.segment<3>(3 * v) - centre).norm());
    auto local = [&](int v) -> Eigen::Vector3d { return (x.segment<3>(3 * v) - centre) / size; };
    // The motion with coefficients (t, omega) at v: t + omega x p = [I, -[p]x] (t, omega).
    auto motion = [&](int v) {
      const Eigen::Vector3d p = local(v);
      Eigen::Matrix<double, 3, 6> G;
      G << Eigen::Matrix3d::Identity(), Eigen::Matrix3d::Zero();
      G.block<3, 3>(0, 3) << 0, p.z(), -p.y(), -p.z(), 0, p.x(), p.y(), -p.x(), 0;
      return G;
    };
    // Coefficients of the motions that vanish at the pins: the null space of their rows.
    Eigen::MatrixXd coefficients = Eigen::MatrixXd::Identity(6, 6);
    if(!pins[c].empty())
    {
      Eigen::MatrixXd G(3 * pins[c].size(), 6);
      for(std::size_t i = 0; i < pins[c].size(); ++i) G.block<3, 6>(3 * Eigen::Index(i), 0) = motion(pins[c][i]);
      Eigen::JacobiSVD<Eigen::MatrixXd> svd(G, Eigen::ComputeFullV);
      // Singular values are O(1) in these units; collinear pins leave one at rounding level.
      const Eigen::VectorXd s = svd.singularValues();
      int rank = 0;
      for(int i = 0; i < s.size(); ++i) rank += s[i] > 1e-9 * s[0];
      coefficients = svd.matrixV().rightCols(6 - rank);
    }
    for(int j = 0; j < coefficients.cols(); ++j)
    {
      Eigen::VectorXd column = Eigen::VectorXd::Zero(x.size());
      for(int v : members[c]) column.segment<3>(3 * v) = motion(v) * coefficients.col(j);
      columns.push_back(column);
    }
  }
  Eigen::MatrixXd K(x.size(), Eigen::Index(columns.size()));
  for(std::size_t j = 0; j < columns.size(); ++j) K.col(Eigen::Index(j)) = columns[j];
  return K;
}

Mode_problem shell_mode_problem(const Discrete_shells::Shell_energy& energy, const std::vector<int>& pinned)
{
  const Eigen::Index n = energy.number_of_vertices();
  std::vector<char> is_free(std::size_t(n), 0);
  for(const auto& t : energy.triangles())
    for(int v : t) is_free[v] = 1;
  for(int p : pinned)
  {
    if(p < 0 || p >= n)
      throw Invalid_input("pinned vertex " + std::to_string(p) + " is outside the mesh (" + std::to_string(n) +
                          " vertices)");
    is_free[p] = 0;
  }
  Mode_problem problem;
  problem.group_size = 3;
  problem.full_size = 3 * n;
  std::vector<Eigen::Index> index(std::size_t(3 * n), -1);
  for(Eigen::Index v = 0; v < n; ++v)
    if(is_free[v])
      for(int c = 0; c < 3; ++c)
      {
        index[3 * v + c] = Eigen::Index(problem.free_unknowns.size());
        problem.free_unknowns.push_back(3 * v + c);
      }
  if(problem.free_unknowns.empty()) throw Invalid_input("every vertex of the shell is pinned: nothing can move");

  const Eigen::SparseMatrix<double> H = energy.rest_hessian();
  const Eigen::VectorXd mass = energy.lumped_mass();
  const Eigen::Index m = Eigen::Index(problem.free_unknowns.size());
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(std::size_t(H.nonZeros()));
  for(int k = 0; k < H.outerSize(); ++k)
    for(Eigen::SparseMatrix<double>::InnerIterator it(H, k); it; ++it)
      if(index[it.row()] >= 0 && index[it.col()] >= 0) entries.emplace_back(index[it.row()], index[it.col()], it.value());
  problem.H.resize(m, m);
  problem.H.setFromTriplets(entries.begin(), entries.end());
  problem.mass.resize(m);
  const Eigen::MatrixXd K = rigid_motions(energy.rest_positions(), energy.triangles(), pinned);
  problem.kernel.resize(m, K.cols());
  for(Eigen::Index i = 0; i < m; ++i)
  {
    problem.mass[i] = mass[problem.free_unknowns[i]];
    problem.kernel.row(i) = K.row(problem.free_unknowns[i]);
  }
  return problem;
}

} // namespace Vibration_modes
} // namespace CGAL
