// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/internal/scalar_eigenproblem.h>
#include <CGAL/Tangent_vector_fields/errors.h>
#include <CGAL/Model_reduction/internal/huge_pages.h>

namespace CGAL {
namespace Tangent_vector_fields {
namespace internal {

namespace {

typedef Eigen::SparseMatrix<double> Sparse_matrix;

Scalar_eigenproblem exact_problem(const Operator_matrices& ops, double area)
{
  const Intrinsic_mesh& mesh = ops.mesh();
  Scalar_eigenproblem p;
  p.area = area;
  p.full_size = mesh.number_of_vertices();
  std::vector<int> position(mesh.number_of_vertices(), -1);
  for(int v = 0; v < mesh.number_of_vertices(); ++v)
    if(!mesh.is_isolated_vertex(v))
    {
      position[v] = static_cast<int>(p.unknowns.size());
      p.unknowns.push_back(v);
    }
  const Eigen::Index n = static_cast<Eigen::Index>(p.unknowns.size());
  if(n == mesh.number_of_vertices())
  {
    p.unknowns.clear();
    p.A = ops.W();
    p.d = ops.vertex_masses() / area;
  }
  else
  {
    std::vector<Eigen::Triplet<double>> entries;
    const Sparse_matrix& W = ops.W();
    for(int j = 0; j < W.outerSize(); ++j)
      for(Sparse_matrix::InnerIterator it(W, j); it; ++it)
        if(position[it.row()] >= 0 && position[j] >= 0) entries.emplace_back(position[it.row()], position[j], it.value());
    p.A.resize(n, n);
    p.A.setFromTriplets(entries.begin(), entries.end());
    p.d.resize(n);
    for(Eigen::Index i = 0; i < n; ++i) p.d[i] = ops.vertex_masses()[p.unknowns[i]] / area;
  }
  const int components = mesh.topology().number_of_components();
  p.kernel = Eigen::MatrixXd::Zero(n, components);
  for(Eigen::Index i = 0; i < n; ++i)
    p.kernel(i, mesh.vertex_component(p.unknowns.empty() ? static_cast<int>(i) : p.unknowns[i])) = 1;
  return p;
}

Scalar_eigenproblem coexact_problem(const Operator_matrices& ops, double area)
{
  const Intrinsic_mesh& mesh = ops.mesh();
  Scalar_eigenproblem p;
  p.area = area;
  p.full_size = mesh.number_of_interior_edges();
  p.A = ops.W_star();
  p.d = ops.all_to_interior_edges(ops.edge_masses()) / area;
  const Mesh_topology& topology = mesh.topology();
  std::vector<int> kernel_column(topology.number_of_components(), -1);
  int closed = 0;
  for(int c = 0; c < topology.number_of_components(); ++c)
    if(topology.components[c].is_closed()) kernel_column[c] = closed++;
  p.kernel = Eigen::MatrixXd::Zero(p.full_size, closed);
  for(int i = 0; i < mesh.number_of_interior_edges(); ++i)
  {
    const int column = kernel_column[mesh.edge_component(mesh.interior_edges()[i])];
    if(column >= 0) p.kernel(i, column) = 1;
  }
  return p;
}

} // namespace

namespace {

// Column by column: the basis is large, and rows of a column-major matrix are far apart.
template <class Matrix>
Matrix expand_columns(const Scalar_eigenproblem& p, Matrix X, double factor)
{
  typedef typename Matrix::Scalar Scalar;
  if(p.unknowns.empty())
  {
    // In place, and not `return X *= factor`: that returns a reference, which copies the
    // basis (the bunny's 500 coexact functions, 0.42 GB, held twice at the end of the set-up).
    for(Eigen::Index j = 0; j < X.cols(); ++j) X.col(j) = (X.col(j).template cast<double>() * factor).template cast<Scalar>();
    return X;
  }
  Matrix Y;
  Model_reduction::internal::resize_in_huge_pages(Y, p.full_size, X.cols());
  Y.setZero();
  for(Eigen::Index j = 0; j < X.cols(); ++j)
    for(std::size_t i = 0; i < p.unknowns.size(); ++i)
      Y(p.unknowns[i], j) = static_cast<Scalar>(factor * X(static_cast<Eigen::Index>(i), j));
  return Y;
}

} // namespace

Eigen::MatrixXd Scalar_eigenproblem::expand(Eigen::MatrixXd X, double factor) const
{
  return expand_columns(*this, std::move(X), factor);
}

Eigen::MatrixXf Scalar_eigenproblem::expand(Eigen::MatrixXf X, double factor) const
{
  return expand_columns(*this, std::move(X), factor);
}

Scalar_eigenproblem scalar_eigenproblem(const Operator_matrices& ops, Eigenfield_type type, double area)
{
  switch(type)
  {
  case Eigenfield_type::exact: return exact_problem(ops, area);
  case Eigenfield_type::coexact: return coexact_problem(ops, area);
  case Eigenfield_type::harmonic: break;
  }
  throw Invalid_input("harmonic fields have no scalar eigenproblem (eigenvalue 0: a kernel, not a spectrum)");
}

Model_reduction::Eigensolver_options eigensolver_options(const Basis_options& options)
{
  Model_reduction::Eigensolver_options e;
  e.tolerance = options.tolerance;
  e.block_size = options.block_size;
  e.restart_per_pair = options.restart_per_pair;
  e.threads = options.threads;
  e.seed = options.seed;
  return e;
}

} // namespace internal
} // namespace Tangent_vector_fields
} // namespace CGAL
