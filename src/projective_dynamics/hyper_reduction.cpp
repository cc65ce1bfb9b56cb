// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// The hyper-reduction's precomputation (SPEC 12): per group the projection subspace, one sampled
// element at each farthest-point vertex, the fit and F; then the used vertices.

#include <CGAL/Projective_dynamics/Projection_subspace.h>
#include <CGAL/Projective_dynamics/errors.h>
#include <CGAL/Projective_dynamics/internal/projection_subspace_factors.h>

#include "element_graph.h"
#include "hyper_reduction.h"

#include <algorithm>
#include <functional>
#include <string>

namespace CGAL {
namespace Projective_dynamics {
namespace internal {

namespace {
typedef Eigen::SparseMatrix<double, Eigen::RowMajor> Sparse;
}

Hyper_sampling sample_and_fit(const Elastic_model& model, const Reduction_options& r, const Sparse& U, const Sparse& Ut,
                              const std::vector<std::vector<int>>& members, std::vector<Reduced_group>& groups,
                              const std::function<void(const char*, double)>& report)
{
  const auto& elements = model.elements();
  const Sparse& S = model.selection_matrix();
  const internal::Element_graph graph = internal::element_graph(model);
  const std::vector<int> spots = internal::farthest_point_samples(graph, std::min(r.sampled_elements, model.number_of_vertices()), nullptr);
  std::vector<std::vector<int>> vertex_elements(static_cast<std::size_t>(model.number_of_vertices()));
  for(int e = 0; e < model.number_of_elements(); ++e)
    for(int v : internal::element_vertices(model, e)) vertex_elements[std::size_t(v)].push_back(e);
  if(report) report("sampled elements", 0);
  for(std::size_t g = 0; g < groups.size(); ++g)
  {
    Reduced_group& G = groups[g];
    const std::vector<int>& mine = members[g];
    if(report && g > 0) report("projection subspaces", double(g) / double(groups.size()));
    if(mine.empty()) continue;
    const int l = r.projection_columns;
    if(int(mine.size()) < l + 20)
      throw Invalid_input("element group " + std::to_string(g) + " has " + std::to_string(mine.size()) +
                          " elements, fewer than l + 20 = " + std::to_string(l + 20) + " (too few to fit l projection columns)");
    // V in factored form: the fit needs its sampled rows, F = U^T S^T D V its product with S.
    const Projection_subspace_factors V =
        projection_subspace_factors(model, int(g), r.constraint_samples, r.constraint_radius_multiplier, l);
    // One element at each farthest-point vertex (the first of this group there not taken yet);
    // if the vertices run out, evenly spaced elements of the rest.
    const int s = std::min(r.sampled_elements, int(mine.size()));
    std::vector<char> taken(elements.size(), 0);
    for(int v : spots)
    {
      if(int(G.sampled.size()) == s) break;
      for(int e : vertex_elements[std::size_t(v)])
        if(elements[std::size_t(e)].group == int(g) && !taken[std::size_t(e)])
        {
          taken[std::size_t(e)] = 1, G.sampled.push_back(e);
          break;
        }
    }
    std::vector<int> rest;
    for(int e : mine)
      if(!taken[std::size_t(e)]) rest.push_back(e);
    const std::size_t need = std::size_t(s) - G.sampled.size();
    for(std::size_t q = 0; q < need; ++q) G.sampled.push_back(rest[q * rest.size() / need]);
    std::sort(G.sampled.begin(), G.sampled.end());

    std::vector<int> local_rows;
    for(int e : G.sampled)
      for(int q = 0; q < elements[std::size_t(e)].rows; ++q) local_rows.push_back(elements[std::size_t(e)].first_row + q - G.first_row);
    G.JV = V.rows_of_V(local_rows);
    G.F = V.projected(S.middleRows(G.first_row, G.rows), Ut);
  }
  Hyper_sampling h = finish_sampling(model, U, groups);
  if(report) report("projection subspaces", 1);
  return h;
}

Hyper_sampling finish_sampling(const Elastic_model& model, const Sparse& U, std::vector<Reduced_group>& groups)
{
  Hyper_sampling h;
  const auto& elements = model.elements();
  const Sparse& S = model.selection_matrix();
  int stacked = 0;
  for(std::size_t g = 0; g < groups.size(); ++g)
  {
    Reduced_group& G = groups[g];
    if(G.sampled.empty()) continue;
    G.first_sampled_row = stacked;
    G.sampled_rows = 0;
    for(int e : G.sampled) G.sampled_rows += elements[std::size_t(e)].rows;
    stacked += G.sampled_rows;
    G.fit.compute(G.JV.transpose() * G.JV);
    if(G.fit.info() != Eigen::Success)
      throw Numerical_failure("the fitting matrix (J V)^T (J V) of group " + std::to_string(g) +
                              " is singular: more sampled elements or fewer projection columns");
    G.first_sampled = int(h.sampled_all.size());
    for(int e : G.sampled) h.sampled_all.push_back(e);
  }
  std::vector<std::vector<int>> element_vertices(elements.size());
  for(int e : h.sampled_all) element_vertices[std::size_t(e)] = internal::element_vertices(model, e);
  // The used vertices and the sampled rows of S on them.
  std::vector<int> index(std::size_t(model.number_of_vertices()), -1);
  for(int e : h.sampled_all)
    for(int v : element_vertices[std::size_t(e)])
      if(index[std::size_t(v)] < 0) index[std::size_t(v)] = 0, h.used.push_back(v);
  std::sort(h.used.begin(), h.used.end());
  for(std::size_t q = 0; q < h.used.size(); ++q) index[std::size_t(h.used[q])] = int(q);
  std::vector<Eigen::Triplet<double>> t;
  int row = 0;
  for(int e : h.sampled_all)
  {
    h.sampled_row.push_back(row);
    const Element& el = elements[std::size_t(e)];
    for(int q = 0; q < el.rows; ++q, ++row)
      for(Sparse::InnerIterator it(S, el.first_row + q); it; ++it) t.emplace_back(row, index[std::size_t(it.col())], it.value());
  }
  h.S_used.resize(row, Eigen::Index(h.used.size()));
  h.S_used.setFromTriplets(t.begin(), t.end());
  t.clear();
  for(std::size_t q = 0; q < h.used.size(); ++q)
    for(Sparse::InnerIterator it(U, h.used[q]); it; ++it) t.emplace_back(int(q), int(it.col()), it.value());
  h.U_used.resize(Eigen::Index(h.used.size()), int(U.cols()));
  h.U_used.setFromTriplets(t.begin(), t.end());
  return h;
}

} // namespace internal
} // namespace Projective_dynamics
} // namespace CGAL
