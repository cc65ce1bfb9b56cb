// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Vibration_modes/Mode_problem.h>
#include <CGAL/Vibration_modes/errors.h>

#include "connected_components.h"

#include <Eigen/Geometry>

#include <string>

namespace CGAL {
namespace Vibration_modes {

Mode_problem laplacian_mode_problem(const Eigen::VectorXd& x,
                                    const std::vector<Discrete_shells::Shell_energy::Triangle>& triangles,
                                    const std::vector<int>& pinned)
{
  // The shell's checks of the triangles (indices, finite coordinates, zero areas) and its
  // lumped mass: the same mass as the shell's, one entry per vertex.
  const Discrete_shells::Shell_energy area_only(x, triangles, {0, 1, 0});
  const Eigen::VectorXd shell_mass = area_only.lumped_mass();
  const Eigen::Index n = x.size() / 3;
  int components = 0;
  const std::vector<int> component = internal::connected_components(n, triangles, components);
  std::vector<char> has_pin(std::size_t(components), 0);
  std::vector<Eigen::Index> index(std::size_t(n), -1);
  for(int p : pinned)
  {
    if(p < 0 || p >= n)
      throw Invalid_input("pinned vertex " + std::to_string(p) + " is outside the mesh (" + std::to_string(n) +
                          " vertices)");
    if(component[p] >= 0) has_pin[component[p]] = 1;
    index[p] = -2;
  }
  Mode_problem problem;
  problem.group_size = 1;
  problem.full_size = n;
  for(Eigen::Index v = 0; v < n; ++v)
    if(component[v] >= 0 && index[v] == -1)
    {
      index[v] = Eigen::Index(problem.free_unknowns.size());
      problem.free_unknowns.push_back(v);
    }
  const Eigen::Index m = Eigen::Index(problem.free_unknowns.size());
  if(m == 0) throw Invalid_input("every vertex is pinned: nothing can move");

  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(12 * triangles.size());
  for(const auto& t : triangles)
    for(int i = 0; i < 3; ++i)
    {
      const int a = t[i], b = t[(i + 1) % 3], c = t[(i + 2) % 3];
      const Eigen::Vector3d ca = x.segment<3>(3 * a) - x.segment<3>(3 * c), cb = x.segment<3>(3 * b) - x.segment<3>(3 * c);
      const double half_cot = 0.5 * ca.dot(cb) / ca.cross(cb).norm(); // angle at c, facing edge ab
      const Eigen::Index ia = index[a], ib = index[b];
      if(ia >= 0) entries.emplace_back(ia, ia, half_cot);
      if(ib >= 0) entries.emplace_back(ib, ib, half_cot);
      if(ia >= 0 && ib >= 0)
      {
        entries.emplace_back(ia, ib, -half_cot);
        entries.emplace_back(ib, ia, -half_cot);
      }
    }
  problem.H.resize(m, m);
  problem.H.setFromTriplets(entries.begin(), entries.end());
  problem.mass.resize(m);
  for(Eigen::Index i = 0; i < m; ++i) problem.mass[i] = shell_mass[3 * problem.free_unknowns[i]];
  // The constants of each component without pins.
  std::vector<Eigen::Index> column(std::size_t(components), -1);
  Eigen::Index kernel_columns = 0;
  for(int c = 0; c < components; ++c)
    if(!has_pin[c]) column[c] = kernel_columns++;
  problem.kernel = Eigen::MatrixXd::Zero(m, kernel_columns);
  for(Eigen::Index i = 0; i < m; ++i)
  {
    const int c = component[problem.free_unknowns[i]];
    if(column[c] >= 0) problem.kernel(i, column[c]) = 1;
  }
  return problem;
}

} // namespace Vibration_modes
} // namespace CGAL
