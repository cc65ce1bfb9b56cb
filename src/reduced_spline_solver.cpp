// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/Reduced_spline_solver.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <cmath>
#include <map>

namespace CGAL {
namespace Tangent_vector_fields {

namespace {
int harmonic_count(const Eigenfield_basis& basis, int d)
{
  int h = 0;
  for(int k = 0; k < d; ++k) h += basis.type(k) == Eigenfield_type::harmonic;
  return h;
}
int checked_size(const Eigenfield_basis& basis, int d)
{
  if(d < 0 || d > basis.size())
    throw Invalid_input("basis size " + std::to_string(d) + " out of range [0, " + std::to_string(basis.size()) + "]");
  return d == 0 ? basis.size() : d;
}
} // namespace

Reduced_spline_solver::Reduced_spline_solver(std::shared_ptr<const Eigenfield_basis> basis, int basis_size,
                                             const Spline_options& options)
  : Spline_solver(std::shared_ptr<const Operator_matrices>(basis, &basis->operators()),
                  harmonic_count(*basis, checked_size(*basis, basis_size)), options),
    basis_(std::move(basis)), d_(checked_size(*basis_, basis_size))
{
  const Operator_matrices& ops = basis_->operators();
  G_rows_ = ops.G();
  // (J G*)(2f, e) = -G*(2f+1, e), (J G*)(2f+1, e) = G*(2f, e): J applied to the rows.
  Eigen::SparseMatrix<double> J = ops.J();
  JG_star_rows_ = J * ops.G_star_interior();
  exact_position_.assign(basis_->number_of_exact(), -1);
  coexact_position_.assign(basis_->number_of_coexact(), -1);
  exact_scale_ = Eigen::VectorXd::Zero(basis_->number_of_exact());
  coexact_scale_ = Eigen::VectorXd::Zero(basis_->number_of_coexact());
  for(int k = 0; k < d_; ++k)
  {
    const int i = basis_->index_in_type(k);
    switch(basis_->type(k))
    {
    case Eigenfield_type::harmonic: harmonic_positions_.push_back(k); break;
    case Eigenfield_type::exact:
      exact_position_[i] = k;
      exact_scale_[i] = 1 / std::sqrt(basis_->exact_eigenvalues()[i]);
      break;
    case Eigenfield_type::coexact:
      coexact_position_[i] = k;
      coexact_scale_[i] = 1 / std::sqrt(basis_->coexact_eigenvalues()[i]);
      break;
    }
  }
  update_energy();
}

void Reduced_spline_solver::update_energy()
{
  energy_.resize(d_);
  inverse_energy_.resize(d_);
  for(int k = 0; k < d_; ++k)
  {
    const double lambda = basis_->eigenvalue(k);
    energy_[k] = basis_->type(k) == Eigenfield_type::harmonic ? 0 : lambda * lambda + omega_ * lambda;
    inverse_energy_[k] = energy_[k] > 0 ? 1 / energy_[k] : 0;
  }
}

Eigen::VectorXd Reduced_spline_solver::basis_row(const Constraint_row& row) const
{
  // r U = (G^T r)^T Phi Lambda^-1/2 (exact), ((J G*)^T r)^T Psi Mu^-1/2 (coexact), r U_h (harmonic).
  std::map<int, double> vertices, edges;
  for(const auto& e : row.entries)
  {
    for(Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(G_rows_, e.first); it; ++it)
      vertices[static_cast<int>(it.col())] += e.second * it.value();
    for(Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(JG_star_rows_, e.first); it; ++it)
      edges[static_cast<int>(it.col())] += e.second * it.value();
  }
  Eigen::VectorXd exact = Eigen::VectorXd::Zero(basis_->number_of_exact());
  for(const auto& v : vertices) exact += v.second * basis_->exact_eigenfunctions().row(v.first).transpose();
  Eigen::VectorXd coexact = Eigen::VectorXd::Zero(basis_->number_of_coexact());
  for(const auto& e : edges) coexact += e.second * basis_->coexact_eigenfunctions().row(e.first).transpose();
  Eigen::VectorXd result = Eigen::VectorXd::Zero(d_);
  for(int i = 0; i < exact.size(); ++i)
    if(exact_position_[i] >= 0) result[exact_position_[i]] = exact[i] * exact_scale_[i];
  for(int i = 0; i < coexact.size(); ++i)
    if(coexact_position_[i] >= 0) result[coexact_position_[i]] = coexact[i] * coexact_scale_[i];
  for(std::size_t j = 0; j < harmonic_positions_.size(); ++j)
  {
    const int k = harmonic_positions_[j];
    const int column = basis_->index_in_type(k);
    double s = 0;
    for(const auto& e : row.entries) s += e.second * basis_->harmonic_fields()(e.first, column);
    result[k] = s;
  }
  return result;
}

void Reduced_spline_solver::pull_back(std::vector<Row>& rows) const
{
  for(Row& row : rows)
  {
    row.representation = basis_row(row.row);
    row.y = row.representation.cwiseProduct(inverse_energy_);
    row.harmonic.resize(harmonic_positions_.size());
    for(std::size_t j = 0; j < harmonic_positions_.size(); ++j) row.harmonic[j] = row.representation[harmonic_positions_[j]];
  }
}

double Reduced_spline_solver::apply(const Row& row, const Eigen::VectorXd& y) const
{
  return row.representation.dot(y);
}

double Reduced_spline_solver::energy(const Eigen::VectorXd& a) const
{
  return a.cwiseProduct(a).dot(energy_);
}

void Reduced_spline_solver::add_harmonic(const Eigen::VectorXd& z, Eigen::VectorXd& a) const
{
  for(std::size_t j = 0; j < harmonic_positions_.size(); ++j) a[harmonic_positions_[j]] += z[j];
}

Eigen::VectorXd Reduced_spline_solver::field() const
{
  return basis_->field(coefficients());
}

std::string Reduced_spline_solver::dependency_hint() const
{
  const int free = d_ - static_cast<int>(harmonic_positions_.size());
  if(number_of_rows() + 1 > free)
    return "a basis of " + std::to_string(d_) + " fields (" + std::to_string(free) +
           " with energy) cannot meet more independent constraint rows than that: use a larger basis";
  return "if the constraints are distinct, a larger basis may tell them apart";
}

} // namespace Tangent_vector_fields
} // namespace CGAL
