// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Vibration_modes/mode_segmentation.h>

#include <cmath>
#include <numeric>
#include <string>

namespace CGAL {
namespace Vibration_modes {

Mode_segmentation segment_by_modes(const Eigen::MatrixXd& modes, int g,
                                   const std::vector<Discrete_shells::Shell_energy::Triangle>& triangles,
                                   double threshold)
{
  if(modes.cols() == 0) throw Invalid_input("mode segmentation: no modes");
  if(g < 1 || modes.rows() % g != 0)
    throw Invalid_input("mode segmentation: " + std::to_string(modes.rows()) + " rows are not " + std::to_string(g) +
                        " per vertex");
  if(!modes.allFinite()) throw Invalid_input("mode segmentation: the modes have a non-finite entry (NaN or infinity)");
  if(!(threshold >= 0 && threshold < 1))
    throw Invalid_input("mode segmentation: the threshold must be in [0, 1) (got " + std::to_string(threshold) + ")");
  const Eigen::Index n = modes.rows() / g;
  for(std::size_t t = 0; t < triangles.size(); ++t)
    for(int v : triangles[t])
      if(v < 0 || v >= n)
        throw Invalid_input("mode segmentation: triangle " + std::to_string(t) + " has vertex " + std::to_string(v) +
                            ", but the modes have " + std::to_string(n) + " vertices");
  // |u_i(v)| per vertex and mode, and each mode's peak.
  Eigen::MatrixXd length(n, modes.cols());
  for(Eigen::Index v = 0; v < n; ++v) length.row(v) = modes.middleRows(g * v, g).colwise().norm();
  const Eigen::RowVectorXd peak = length.colwise().maxCoeff();
  std::vector<int> mode(std::size_t(n), -1);
  for(Eigen::Index v = 0; v < n; ++v)
  {
    Eigen::Index best;
    const double value = length.row(v).maxCoeff(&best);
    if(value > 0 && value >= threshold * peak[best]) mode[std::size_t(v)] = int(best);
  }
  // Connected regions of equal mode: union-find over the triangles' edges.
  std::vector<int> parent(static_cast<std::size_t>(n));
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int v) {
    while(parent[std::size_t(v)] != v) v = parent[std::size_t(v)] = parent[std::size_t(parent[std::size_t(v)])];
    return v;
  };
  for(const auto& t : triangles)
    for(int i = 0; i < 3; ++i)
    {
      const int a = t[i], b = t[(i + 1) % 3];
      if(mode[std::size_t(a)] >= 0 && mode[std::size_t(a)] == mode[std::size_t(b)]) parent[std::size_t(find(a))] = find(b);
    }
  Mode_segmentation s;
  s.region.assign(std::size_t(n), -1);
  std::vector<int> id(std::size_t(n), -1);
  for(Eigen::Index v = 0; v < n; ++v)
    if(mode[std::size_t(v)] >= 0)
    {
      const int r = find(int(v));
      if(id[std::size_t(r)] < 0)
      {
        id[std::size_t(r)] = s.number_of_regions();
        s.region_mode.push_back(mode[std::size_t(v)]);
        s.region_size.push_back(0);
      }
      s.region[std::size_t(v)] = id[std::size_t(r)];
      ++s.region_size[std::size_t(id[std::size_t(r)])];
    }
  return s;
}

} // namespace Vibration_modes
} // namespace CGAL
