// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/Reduced_spline_solver.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Tangent_vector_fields {

namespace {
int harmonic_count(const Eigenfield_basis& basis, int d)
{
  int h = 0;
  for(int k = 0; k < d; ++k) h += basis.type(k) == Eigenfield_type::harmonic;
  return h;
}
} // namespace

Reduced_spline_solver::Reduced_spline_solver(std::shared_ptr<const Eigenfield_basis> basis, int basis_size,
                                             const Spline_options& options)
  : Spline_solver(std::shared_ptr<const Operator_matrices>(basis, &basis->operators()),
                  harmonic_count(*basis, internal::checked_basis_size(*basis, basis_size)), options),
    basis_(std::move(basis)), d_(internal::checked_basis_size(*basis_, basis_size)), rows_in_basis_(*basis_, d_)
{
  update_energy();
}

void Reduced_spline_solver::update_energy()
{
  energy_.resize(d_);
  inverse_energy_.resize(d_);
  for(int k = 0; k < d_; ++k)
  {
    // In the length unit (see Spline_solver.h): eigenvalues times u^2.
    const double lambda = basis_->eigenvalue(k) * length_unit_ * length_unit_;
    energy_[k] = basis_->type(k) == Eigenfield_type::harmonic ? 0 : lambda * lambda + omega_ * lambda;
    inverse_energy_[k] = energy_[k] > 0 ? 1 / energy_[k] : 0;
  }
}

double Reduced_spline_solver::lowest_missing_energy() const
{
  // Missing: the basis' own elements from d on (sorted), and what it never computed.
  const Basis_report& report = basis_->report();
  double lambda = std::min(report.exact_complete_below, report.coexact_complete_below);
  if(d_ < basis_->size()) lambda = std::min(lambda, basis_->eigenvalue(d_));
  if(lambda == std::numeric_limits<double>::infinity()) return lambda;
  lambda *= length_unit_ * length_unit_; // as update_energy
  return lambda * lambda + omega_ * lambda;
}

Eigen::VectorXd Reduced_spline_solver::field_masses() const
{
  // MX / u^2, in which the rows' representation (u times the basis) is orthonormal.
  return operators().field_masses() / (length_unit_ * length_unit_);
}

void Reduced_spline_solver::pull_back(std::vector<Row>& rows) const
{
  for(Row& row : rows)
  {
    // The row on the basis orthonormal for MX / u^2: u times the given basis.
    row.representation = basis_row(row.row) * length_unit_;
    row.y = row.representation.cwiseProduct(inverse_energy_);
    const std::vector<int>& harmonic = rows_in_basis_.harmonic_positions();
    row.harmonic.resize(harmonic.size());
    for(std::size_t j = 0; j < harmonic.size(); ++j) row.harmonic[j] = row.representation[harmonic[j]];
  }
}

double Reduced_spline_solver::apply(const Row& row, const Eigen::VectorXd& y) const
{
  return row.representation.dot(y);
}

double Reduced_spline_solver::energy(const Eigen::VectorXd& a) const
{
  double harmonic = 0;
  for(int k : rows_in_basis_.harmonic_positions()) harmonic += a[k] * a[k];
  return a.cwiseProduct(a).dot(energy_) + harmonic_penalty_ * harmonic;
}

void Reduced_spline_solver::add_harmonic(const Eigen::VectorXd& z, Eigen::VectorXd& a) const
{
  const std::vector<int>& harmonic = rows_in_basis_.harmonic_positions();
  for(std::size_t j = 0; j < harmonic.size(); ++j) a[harmonic[j]] += z[j];
}

Eigen::VectorXd Reduced_spline_solver::field() const
{
  return basis_->field(coefficients());
}

Eigen::MatrixXd Reduced_spline_solver::fields_of(const Eigen::MatrixXd& a) const
{
  Compressed_fields c;
  c.coefficients = a * length_unit_; // as coefficients() does
  return basis_->decompress(c);
}

std::string Reduced_spline_solver::dependency_hint() const
{
  const int free = d_ - static_cast<int>(rows_in_basis_.harmonic_positions().size());
  if(number_of_rows() + 1 > free)
    return "a basis of " + std::to_string(d_) + " fields (" + std::to_string(free) +
           " with energy) cannot meet more independent constraint rows than that: use a larger basis";
  return "if the constraints are distinct, a larger basis may tell them apart";
}

} // namespace Tangent_vector_fields
} // namespace CGAL
