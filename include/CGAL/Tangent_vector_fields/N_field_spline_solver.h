// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_N_FIELD_SPLINE_SOLVER_H
#define CGAL_TANGENT_VECTOR_FIELDS_N_FIELD_SPLINE_SOLVER_H

/// \file N_field_spline_solver.h
/// n-field splines (SPEC 10): minimise `E_m(z) + omega E_D(z)` subject to hard constraints,
/// with `E_m = z^T S_n (MX^-1 S_n)^(m-1) z` (m = 2: the higher-order energy `E_B`, m = 1 with
/// omega = 0: the classical first-order design).  The same range-space core as the vector
/// splines (`Basic_spline_solver`): reduced on an `N_field_basis` (real-time edits) and full
/// resolution (exact).  Parallel fields (the kernel of `S_n`) play the part of harmonic fields:
/// they carry no energy and the constraints alone determine them.

#include <CGAL/Tangent_vector_fields/N_field_basis.h>
#include <CGAL/Tangent_vector_fields/N_field_constraint.h>
#include <CGAL/Tangent_vector_fields/Spline_solver.h>

#include <Eigen/Core>

#include <memory>

namespace CGAL {
namespace Tangent_vector_fields {

/// \brief A soft alignment of an n-field spline to a guide field `g`: the energy gains
/// `s |z - g|^2_MX`, which draws the field toward the guide where the constraints leave it
/// free (e.g. principal curvature directions, see `curvature_direction_field`).
///
/// `s` is given for the mesh scaled to unit area, like the tension: the term is
/// `(weight / area^m) |z - g|^2_MX` for energy order m, so that the result does not depend on
/// the mesh's scale.  The guide's magnitude weights it: where `|g|` is small (umbilic
/// regions of a curvature guide) the term mostly pulls the field's length down.  With a
/// positive weight no field has zero energy: parallel fields lose their special part.
struct N_field_alignment
{
  Eigen::VectorXd guide; ///< power representation (`2nf`, `N_field_operators::from_vectors`); empty: none
  double weight = 0;     ///< `s >= 0`; 0: no alignment

  bool active() const { return weight > 0 && guide.size() > 0; }
};

/// The n-field spline solvers' common part (constraints, edits, small system, report).
typedef Basic_spline_solver<N_field_constraint, N_field_operators> N_field_spline_solver;
extern template class Basic_spline_solver<N_field_constraint, N_field_operators>;

/// \brief n-field splines `z = Phi a` over the first `d` elements of an `N_field_basis`.
///
/// The energy is diagonal, `D_k = lambda_k^m + omega lambda_k`; a value edit costs two
/// small triangular solves and one `d x rows` product, an add `O(rows d + rows^2)`.
class Reduced_n_field_spline_solver : public N_field_spline_solver
{
public:
  /// `basis_size`: elements of the basis used (0: all); even, so that the truncated basis
  /// turns with the field.  `order`: m >= 1.  With an alignment the guide is projected onto
  /// the basis (its part outside the span is lost).
  /// \throws Invalid_input for an odd or too large basis size, m < 1, or an alignment
  ///         with a negative or non-finite weight or a guide of the wrong size or not finite.
  Reduced_n_field_spline_solver(std::shared_ptr<const N_field_basis> basis, int basis_size = 0,
                                const Spline_options& options = Spline_options(), int order = 2,
                                const N_field_alignment& alignment = N_field_alignment());

  int basis_size() const { return d_; }
  int order() const { return order_; }
  const N_field_basis& basis() const { return *basis_; }
  /// Coefficients of the spline in the basis.
  const Eigen::VectorXd& coefficients() const { return solution(); }
  /// The spline, power representation (`2nf`).
  Eigen::VectorXd field() const override;

protected:
  void pull_back(std::vector<Row>& rows) const override;
  double apply(const Row& row, const Eigen::VectorXd& y) const override;
  Eigen::MatrixXd fields_of(const Eigen::MatrixXd& solutions) const override;
  double energy(const Eigen::VectorXd& a) const override;
  void add_harmonic(const Eigen::VectorXd& z, Eigen::VectorXd& a) const override;
  int space_dimension() const override { return d_; }
  std::string dependency_hint() const override;
  void energy_changed() override { update_energy(); }
  std::string kernel_noun() const override { return "parallel-field"; }
  const Eigen::VectorXd& unconstrained_minimiser() const override { return aligned_; }
  double lowest_missing_energy() const override;
  Eigen::VectorXd field_masses() const override { return operators().masses(); }

private:
  void update_energy();

  std::shared_ptr<const N_field_basis> basis_;
  int d_;
  int order_;
  double alignment_weight_ = 0;     // s / area^m, for the mesh as given
  Eigen::VectorXd guide_;           // the guide's coefficients Phi^T MX g
  double guide_norm2_ = 0;          // |g|^2_MX
  Eigen::VectorXd aligned_;         // the minimiser without constraints (empty: none)
  Eigen::VectorXd inverse_energy_; // 1 / D_k, 0 on the kernel
  Eigen::VectorXd energy_;
};

/// \brief n-field splines at full resolution: the exact minimiser, the yardstick of the
/// reduced one.
///
/// A row `r` is pulled back by sparse solves: with `r~ = r - MX K K^T r` (kernel `K` removed),
/// `S_n u = r~`, then `(S_n + omega MX) y = MX u` for m = 2, or `y = u / (1 + omega)` for
/// m = 1; for m >= 3 (omega = 0 only) `S_n` is applied inversely m times.  `S_n` is
/// factored once (CHOLMOD); on a component with parallel fields one face is held at 0,
/// which leaves the solution exact because `r~` is orthogonal to them.  With an alignment
/// `s |z - g|^2_MX` the energy `S_n (MX^-1 S_n)^(m-1) + omega S_n + s MX` is positive definite:
/// it is formed (two-ring stencil for m = 2) and factored once instead.
class Full_n_field_spline_solver : public N_field_spline_solver
{
public:
  /// \throws Invalid_input for m < 1, m >= 3 with omega > 0 and no alignment, or an
  ///         alignment with a negative or non-finite weight or a guide of the wrong size or not finite.
  Full_n_field_spline_solver(std::shared_ptr<const N_field_operators> operators,
                             const Spline_options& options = Spline_options(), int order = 2,
                             const N_field_alignment& alignment = N_field_alignment());
  ~Full_n_field_spline_solver();

  int order() const { return order_; }
  Eigen::VectorXd field() const override { return solution(); }

protected:
  void pull_back(std::vector<Row>& rows) const override;
  double apply(const Row& row, const Eigen::VectorXd& y) const override;
  double energy(const Eigen::VectorXd& z) const override;
  void add_harmonic(const Eigen::VectorXd& z, Eigen::VectorXd& x) const override;
  int space_dimension() const override;
  void energy_changed() override;
  std::string kernel_noun() const override { return "parallel-field"; }
  const Eigen::VectorXd& unconstrained_minimiser() const override { return aligned_; }

private:
  struct Factors;
  int order_;
  N_field_alignment alignment_;
  double alignment_weight_ = 0; // s / area^m, for the mesh as given
  Eigen::VectorXd aligned_;     // the minimiser without constraints (empty: none)
  std::unique_ptr<Factors> factors_;
};

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
