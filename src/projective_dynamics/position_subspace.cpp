// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Farthest-point samples with Dijkstra distances on the element edge graph, their weights and
// the position subspace U (SPEC 12).

#include <CGAL/Projective_dynamics/Position_subspace.h>
#include <CGAL/Projective_dynamics/errors.h>

#include "element_graph.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <string>
#include <unordered_map>

namespace CGAL {
namespace Projective_dynamics {
namespace internal {

std::vector<int> element_vertices(const Elastic_model& model, int element)
{
  const Element& el = model.elements()[std::size_t(element)];
  const auto& S = model.selection_matrix();
  std::vector<int> v;
  for(int r = el.first_row; r < el.first_row + el.rows; ++r)
    for(Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(S, r); it; ++it) v.push_back(int(it.col()));
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

Element_graph element_graph(const Elastic_model& model)
{
  const int n = model.number_of_vertices();
  bool only_bending = true;
  for(const Element& el : model.elements()) only_bending = only_bending && el.type == Element_type::bending;
  std::vector<std::pair<int, int>> edges;
  for(int e = 0; e < model.number_of_elements(); ++e)
  {
    if(model.elements()[std::size_t(e)].type == Element_type::bending && !only_bending) continue;
    const std::vector<int> v = element_vertices(model, e);
    for(std::size_t a = 0; a < v.size(); ++a)
      for(std::size_t b = a + 1; b < v.size(); ++b) edges.emplace_back(v[a], v[b]), edges.emplace_back(v[b], v[a]);
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  Element_graph g;
  g.offsets.assign(std::size_t(n) + 1, 0);
  for(const auto& e : edges) ++g.offsets[std::size_t(e.first) + 1];
  for(int i = 0; i < n; ++i) g.offsets[std::size_t(i) + 1] += g.offsets[std::size_t(i)];
  const Positions& x = model.rest_positions();
  for(const auto& e : edges)
  {
    g.neighbours.push_back(e.second);
    g.lengths.push_back((x.row(e.first) - x.row(e.second)).norm());
  }
  return g;
}

namespace {
typedef std::pair<double, int> Entry;
typedef std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> Queue;
} // namespace

void relax_from(const Element_graph& g, int source, std::vector<double>& distance)
{
  Queue queue;
  distance[std::size_t(source)] = 0;
  queue.emplace(0.0, source);
  while(!queue.empty())
  {
    const auto [d, v] = queue.top();
    queue.pop();
    if(d > distance[std::size_t(v)]) continue;
    for(int k = g.offsets[std::size_t(v)]; k < g.offsets[std::size_t(v) + 1]; ++k)
    {
      const int u = g.neighbours[std::size_t(k)];
      const double du = d + g.lengths[std::size_t(k)];
      if(du < distance[std::size_t(u)]) distance[std::size_t(u)] = du, queue.emplace(du, u);
    }
  }
}

std::vector<std::pair<int, double>> ball(const Element_graph& g, int source, double radius)
{
  std::unordered_map<int, double> best;
  std::vector<std::pair<int, double>> out;
  Queue queue;
  best[source] = 0;
  queue.emplace(0.0, source);
  while(!queue.empty())
  {
    const auto [d, v] = queue.top();
    queue.pop();
    if(d > best[v]) continue;
    out.emplace_back(v, d);
    best[v] = -1; // settled
    for(int k = g.offsets[std::size_t(v)]; k < g.offsets[std::size_t(v) + 1]; ++k)
    {
      const int u = g.neighbours[std::size_t(k)];
      const double du = d + g.lengths[std::size_t(k)];
      if(!(du < radius)) continue;
      auto it = best.find(u);
      if(it == best.end() || (it->second >= 0 && du < it->second)) best[u] = du, queue.emplace(du, u);
    }
  }
  return out;
}

std::vector<int> farthest_point_samples(const Element_graph& g, int count, std::vector<double>* distances)
{
  const int n = g.size();
  if(count < 1 || count > n)
    throw Invalid_input("the number of samples must be in [1, " + std::to_string(n) + "] (the number of vertices), not " +
                        std::to_string(count));
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> distance(std::size_t(n), inf);
  relax_from(g, 0, distance);
  // The vertex farthest from vertex 0 (the first of largest distance: deterministic).
  auto farthest = [&] { return int(std::max_element(distance.begin(), distance.end()) - distance.begin()); };
  std::vector<int> samples{farthest()};
  std::fill(distance.begin(), distance.end(), inf);
  relax_from(g, samples[0], distance);
  while(int(samples.size()) < count)
  {
    const int next = farthest();
    samples.push_back(next);
    relax_from(g, next, distance);
  }
  if(distances) *distances = std::move(distance);
  return samples;
}

} // namespace internal

std::vector<int> farthest_point_samples(const Elastic_model& model, int count, std::vector<double>* distances)
{
  return internal::farthest_point_samples(internal::element_graph(model), count, distances);
}

namespace {
Eigen::SparseMatrix<double, Eigen::RowMajor> weights_on(const internal::Element_graph& g, const std::vector<int>& samples,
                                                        double radius)
{
  const int n = g.size(), m = int(samples.size());
  std::vector<Eigen::Triplet<double>> t;
  for(int j = 0; j < m; ++j)
    for(const auto& [v, d] : internal::ball(g, samples[std::size_t(j)], radius))
    {
      const double s = radius > 0 ? 1 - d * d / (radius * radius) : 0;
      t.emplace_back(v, j, d == 0 ? 1.0 : s * s);
    }
  Eigen::SparseMatrix<double, Eigen::RowMajor> W(n, m);
  W.setFromTriplets(t.begin(), t.end());
  for(int i = 0; i < n; ++i)
  {
    double sum = 0;
    for(Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(W, i); it; ++it) sum += it.value();
    if(!(sum > 0))
      throw Invalid_input("vertex " + std::to_string(i) + " is reached by no sample within the radius " +
                          std::to_string(radius) +
                          " (its connected component of the element graph has no sample: more components than samples)");
    for(Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(W, i); it; ++it) it.valueRef() /= sum;
  }
  return W;
}
} // namespace

Eigen::SparseMatrix<double, Eigen::RowMajor> sample_weights(const Elastic_model& model, const std::vector<int>& samples,
                                                            double radius)
{
  for(int s : samples)
    if(s < 0 || s >= model.number_of_vertices())
      throw Invalid_input("sample vertex " + std::to_string(s) + " is outside [0, " + std::to_string(model.number_of_vertices()) + ")");
  return weights_on(internal::element_graph(model), samples, radius);
}

Eigen::MatrixXd Position_subspace::rest_coordinates() const
{
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(basis.cols(), 3);
  for(Eigen::Index j = 0; j < Eigen::Index(samples.size()); ++j)
    for(int c = 0; c < 3; ++c) a(4 * j + c, c) = 1;
  return a;
}

Position_subspace make_position_subspace(const Elastic_model& model, int samples, double radius_multiplier)
{
  if(!(radius_multiplier > 1) || !std::isfinite(radius_multiplier))
    throw Invalid_input("the radius multiplier must be finite and above 1 (a vertex at the covering radius needs a positive weight), not " +
                        std::to_string(radius_multiplier));
  const internal::Element_graph g = internal::element_graph(model);
  Position_subspace P;
  std::vector<double> distance;
  P.samples = internal::farthest_point_samples(g, samples, &distance);
  P.covering_radius = *std::max_element(distance.begin(), distance.end());
  if(!std::isfinite(P.covering_radius))
  {
    const int v = int(std::find(distance.begin(), distance.end(), P.covering_radius) - distance.begin());
    throw Invalid_input("vertex " + std::to_string(v) + " is reached by no sample: the element graph has more connected components than the " +
                        std::to_string(samples) + " samples");
  }
  P.radius = radius_multiplier * P.covering_radius;
  const Eigen::SparseMatrix<double, Eigen::RowMajor> W = weights_on(g, P.samples, P.radius);
  const Positions& x = model.rest_positions();
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(std::size_t(W.nonZeros()) * 4);
  for(int i = 0; i < W.rows(); ++i)
    for(Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(W, i); it; ++it)
    {
      const int j = int(it.col());
      const double w = it.value();
      for(int c = 0; c < 3; ++c) t.emplace_back(i, 4 * j + c, w * x(i, c));
      t.emplace_back(i, 4 * j + 3, w);
    }
  P.basis.resize(model.number_of_vertices(), 4 * samples);
  P.basis.setFromTriplets(t.begin(), t.end());
  return P;
}

} // namespace Projective_dynamics
} // namespace CGAL
