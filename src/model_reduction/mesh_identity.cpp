// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Model_reduction/internal/mesh_identity.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <utility>

namespace CGAL {
namespace Model_reduction {
namespace internal {

namespace {

// A reproducible stream of weights in [0.5, 1.5) (a linear congruential generator).
struct Weights
{
  std::uint64_t state = 0x243f6a8885a308d3ull;
  double next()
  {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return 0.5 + double(state >> 11) / double(1ull << 53);
  }
};

} // namespace

std::uint64_t connectivity_fingerprint(std::int64_t number_of_vertices, std::int64_t number_of_edges,
                                       const std::vector<std::array<int, 3>>& faces,
                                       const std::vector<std::array<int, 3>>& face_edges)
{
  Hasher h;
  h.add(number_of_vertices);
  h.add(number_of_edges);
  h.add(std::int64_t(faces.size()));
  for(std::size_t f = 0; f < faces.size(); ++f)
  {
    const std::array<int, 3>& c = faces[f];
    const int first = int(std::min_element(c.begin(), c.end()) - c.begin());
    for(int k = 0; k < 3; ++k) h.add(c[(first + k) % 3]);
    if(!face_edges.empty())
      for(int k = 0; k < 3; ++k) h.add(face_edges[f][(first + k) % 3]);
  }
  return h.h;
}

std::array<double, 5> geometry_signature(double total_area, const std::vector<double>& edge_lengths)
{
  std::array<double, 5> s{};
  s[0] = total_area;
  Weights w;
  for(double l : edge_lengths)
    for(int k = 1; k < 5; ++k) s[k] += w.next() * l;
  return s;
}

Mesh_identity triangle_mesh_identity(const Eigen::VectorXd& x, const std::vector<std::array<int, 3>>& triangles)
{
  const std::int64_t n = x.size() / 3;
  auto point = [&](int v) -> Eigen::Vector3d {
    return (v >= 0 && v < n) ? Eigen::Vector3d(x.segment<3>(3 * Eigen::Index(v))) : Eigen::Vector3d::Zero();
  };
  std::vector<std::pair<int, int>> edges;
  edges.reserve(3 * triangles.size());
  double area = 0;
  for(const auto& t : triangles)
  {
    for(int k = 0; k < 3; ++k) edges.emplace_back(std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3]));
    area += 0.5 * (point(t[1]) - point(t[0])).cross(point(t[2]) - point(t[0])).norm();
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::vector<double> lengths;
  lengths.reserve(edges.size());
  for(const auto& e : edges) lengths.push_back((point(e.first) - point(e.second)).norm());
  Mesh_identity id;
  id.connectivity = connectivity_fingerprint(n, std::int64_t(edges.size()), triangles);
  id.geometry = geometry_signature(area, lengths);
  return id;
}

std::array<double, 4> position_signature(const Eigen::VectorXd& x)
{
  std::array<double, 4> s{};
  Weights w;
  for(Eigen::Index i = 0; i < x.size(); ++i)
  {
    s[std::size_t(i % 3)] += w.next() * x[i];
    s[3] += std::abs(x[i]);
  }
  return s;
}

} // namespace internal
} // namespace Model_reduction
} // namespace CGAL
