// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_REDUCED_SPLINE_SOLVER_H
#define CGAL_TANGENT_VECTOR_FIELDS_REDUCED_SPLINE_SOLVER_H

/// \file Reduced_spline_solver.h
/// Tangent vector field splines in the span of a spectral basis (SPEC 7): the
/// real-time solver of the thesis.

#include <CGAL/Tangent_vector_fields/Eigenfield_basis.h>
#include <CGAL/Tangent_vector_fields/Spline_solver.h>
#include <CGAL/Tangent_vector_fields/internal/Basis_rows.h>

#include <memory>

namespace CGAL {
namespace Tangent_vector_fields {

/// \brief Splines `x = U a` over the first `d` elements of an `Eigenfield_basis`.
///
/// In the basis the energy is diagonal, `D = Lambda^2 + omega Lambda`, so a row's
/// pull-back is `D^-1 (C~_i U)^T` (harmonic entries 0) and `K = C D^-1 C^T` costs
/// `O(rows d)` per new row.  A value edit costs two `nc x nc` triangular solves and
/// one `d x nc` product; adding a constraint `O(nc d + nc^2)`.  The full field is
/// reconstructed only when asked for (`field`).
class Reduced_spline_solver : public Spline_solver
{
public:
  /// `basis_size`: how many elements of the basis to use (0: all).
  /// \throws Invalid_input if `basis_size` exceeds the basis.
  Reduced_spline_solver(std::shared_ptr<const Eigenfield_basis> basis, int basis_size = 0,
                        const Spline_options& options = Spline_options());

  int basis_size() const { return d_; }
  const Eigenfield_basis& basis() const { return *basis_; }
  /// Coefficients `a` of the spline in the basis (`basis_size()`).
  Eigen::VectorXd coefficients() const { return solution() * length_unit_; }
  Eigen::VectorXd field() const override;

  /// The row `C~_i U` of a constraint row in this basis.
  Eigen::VectorXd basis_row(const Constraint_row& row) const { return rows_in_basis_(row); }

protected:
  void pull_back(std::vector<Row>& rows) const override;
  double apply(const Row& row, const Eigen::VectorXd& y) const override;
  Eigen::MatrixXd fields_of(const Eigen::MatrixXd& solutions) const override;
  double energy(const Eigen::VectorXd& a) const override;
  void add_harmonic(const Eigen::VectorXd& z, Eigen::VectorXd& a) const override;
  int space_dimension() const override { return d_; }
  std::string dependency_hint() const override;
  void energy_changed() override { update_energy(); }
  double lowest_missing_energy() const override;
  Eigen::VectorXd field_masses() const override;

private:
  void update_energy();

  std::shared_ptr<const Eigenfield_basis> basis_;
  int d_;
  internal::Basis_rows rows_in_basis_;
  Eigen::VectorXd inverse_energy_; // 1/D_k, 0 on harmonic elements
  Eigen::VectorXd energy_;         // D_k
};

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
