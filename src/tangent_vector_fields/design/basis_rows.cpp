// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/internal/Basis_rows.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <cmath>
#include <map>

namespace CGAL {
namespace Tangent_vector_fields {
namespace internal {

int checked_basis_size(const Eigenfield_basis& basis, int d)
{
  if(d < 0 || d > basis.size())
    throw Invalid_input("basis size " + std::to_string(d) + " out of range [0, " + std::to_string(basis.size()) + "]");
  return d == 0 ? basis.size() : d;
}

Basis_rows::Basis_rows(const Eigenfield_basis& basis, int d) : basis_(basis), d_(d)
{
  const Operator_matrices& ops = basis.operators();
  G_rows_ = ops.G();
  const Eigen::SparseMatrix<double> JG = ops.J() * ops.G_star_interior();
  JG_star_rows_ = JG;
  exact_position_.assign(basis.number_of_exact(), -1);
  coexact_position_.assign(basis.number_of_coexact(), -1);
  exact_scale_ = Eigen::VectorXd::Zero(basis.number_of_exact());
  coexact_scale_ = Eigen::VectorXd::Zero(basis.number_of_coexact());
  for(int k = 0; k < d_; ++k)
  {
    const int i = basis.index_in_type(k);
    switch(basis.type(k))
    {
    case Eigenfield_type::harmonic: harmonic_positions_.push_back(k); break;
    case Eigenfield_type::exact:
      exact_position_[i] = k;
      exact_scale_[i] = 1 / std::sqrt(basis.exact_eigenvalues()[i]);
      break;
    case Eigenfield_type::coexact:
      coexact_position_[i] = k;
      coexact_scale_[i] = 1 / std::sqrt(basis.coexact_eigenvalues()[i]);
      break;
    }
  }
}

Eigen::VectorXd Basis_rows::operator()(const Constraint_row& row) const
{
  std::map<int, double> vertices, edges;
  for(const auto& e : row.entries)
  {
    for(Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(G_rows_, e.first); it; ++it)
      vertices[static_cast<int>(it.col())] += e.second * it.value();
    for(Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(JG_star_rows_, e.first); it; ++it)
      edges[static_cast<int>(it.col())] += e.second * it.value();
  }
  Eigen::VectorXd exact = Eigen::VectorXd::Zero(basis_.number_of_exact());
  for(const auto& v : vertices) basis_.exact_eigenfunctions().add_row(v.first, v.second, exact);
  Eigen::VectorXd coexact = Eigen::VectorXd::Zero(basis_.number_of_coexact());
  for(const auto& e : edges) basis_.coexact_eigenfunctions().add_row(e.first, e.second, coexact);
  Eigen::VectorXd result = Eigen::VectorXd::Zero(d_);
  for(int i = 0; i < exact.size(); ++i)
    if(exact_position_[i] >= 0) result[exact_position_[i]] = exact[i] * exact_scale_[i];
  for(int i = 0; i < coexact.size(); ++i)
    if(coexact_position_[i] >= 0) result[coexact_position_[i]] = coexact[i] * coexact_scale_[i];
  for(int k : harmonic_positions_)
  {
    const int column = basis_.index_in_type(k);
    double s = 0;
    for(const auto& e : row.entries) s += e.second * basis_.harmonic_fields()(e.first, column);
    result[k] = s;
  }
  return result;
}

} // namespace internal
} // namespace Tangent_vector_fields
} // namespace CGAL
