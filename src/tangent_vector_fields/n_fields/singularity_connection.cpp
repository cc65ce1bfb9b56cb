// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/internal/singularity_connection.h>
#include <CGAL/Model_reduction/Sparse_spd_solver.h>
#include <CGAL/Tangent_vector_fields/internal/n_field_geometry.h>

#include <cmath>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {
namespace internal {

Eigen::VectorXd singularity_connection(const N_field_operators& ops)
{
  const Intrinsic_mesh& mesh = ops.mesh();
  const int nv = mesh.number_of_vertices();
  const Eigen::VectorXd& K = ops.vertex_curvatures();
  const Eigen::VectorXd& area = ops.operators().vertex_masses();
  const Eigen::VectorXd& w = ops.edge_weights();

  const std::vector<char>& boundary = ops.boundary_vertices();
  std::vector<char> prescribed(nv, 0);

  // Target holonomy: 2 pi k / n at prescribed vertices; elsewhere the angle defect plus, on a
  // closed component, an equal share per unit area of what the prescribed ones gave up.
  const Mesh_topology& topology = mesh.topology();
  const int components = topology.number_of_components();
  Eigen::VectorXd b = Eigen::VectorXd::Zero(nv);
  std::vector<double> given_up(components, 0.), free_area(components, 0.);
  for(const auto& [v, k] : ops.options().singularities)
  {
    prescribed[v] = 1;
    b[v] = 2 * M_PI * k / ops.n() - K[v];
    given_up[mesh.vertex_component(v)] -= b[v];
  }
  for(int v = 0; v < nv; ++v)
    if(!mesh.is_isolated_vertex(v) && !prescribed[v] && !boundary[v]) free_area[mesh.vertex_component(v)] += area[v];
  for(int v = 0; v < nv; ++v)
  {
    if(mesh.is_isolated_vertex(v) || prescribed[v] || boundary[v]) continue;
    const int c = mesh.vertex_component(v);
    if(topology.components[c].is_closed() && free_area[c] > 0) b[v] = given_up[c] * area[v] / free_area[c];
  }

  // Unknowns: interior vertices (the boundary holds u = 0), one per closed component held at
  // 0 as well (its equation follows from the others: b sums to 0 there).
  std::vector<int> unknown(nv, -1);
  std::vector<char> held(components, 0);
  int count = 0;
  for(int v = 0; v < nv; ++v)
  {
    if(mesh.is_isolated_vertex(v) || boundary[v]) continue;
    const int c = mesh.vertex_component(v);
    if(topology.components[c].is_closed() && !held[c])
    {
      held[c] = 1;
      continue;
    }
    unknown[v] = count++;
  }
  Eigen::VectorXd delta = Eigen::VectorXd::Zero(mesh.number_of_interior_edges());
  if(count == 0) return delta;
  // Smallest sum_e w_e delta_e^2 with the prescribed curl: delta_e = (u_a - u_b) / w_e and
  // the graph Laplacian with weights 1 / w_e gives u.
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd rhs(count);
  for(int v = 0; v < nv; ++v)
    if(unknown[v] >= 0) rhs[unknown[v]] = b[v];
  for(int i = 0; i < mesh.number_of_interior_edges(); ++i)
  {
    const auto& ab = mesh.edge_vertices(mesh.interior_edges()[i]);
    const double c = 1 / w[i];
    for(int s = 0; s < 2; ++s)
    {
      const int p = unknown[ab[s]], q = unknown[ab[1 - s]];
      if(p < 0) continue;
      entries.emplace_back(p, p, c);
      if(q >= 0) entries.emplace_back(p, q, -c);
    }
  }
  Eigen::SparseMatrix<double> L(count, count);
  L.setFromTriplets(entries.begin(), entries.end());
  Model_reduction::Sparse_spd_solver solver;
  solver.factor(L, "the vertex Laplacian of the singularities' connection");
  const Eigen::VectorXd x = solver.solve(rhs);
  auto u = [&](int v) { return unknown[v] >= 0 ? x[unknown[v]] : 0.; };
  for(int i = 0; i < mesh.number_of_interior_edges(); ++i)
  {
    const int e = mesh.interior_edges()[i];
    const int f = mesh.edge_faces(e)[0];
    int a = mesh.edge_vertices(e)[0], bv = mesh.edge_vertices(e)[1];
    // a: the edge's start in the counter-clockwise order of its first face.
    if((local_corner(mesh, f, a) + 1) % 3 != local_corner(mesh, f, bv)) std::swap(a, bv);
    delta[i] = (u(a) - u(bv)) / w[i];
  }
  return delta;
}

} // namespace internal
} // namespace Tangent_vector_fields
} // namespace CGAL
