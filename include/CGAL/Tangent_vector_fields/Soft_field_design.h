// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_SOFT_FIELD_DESIGN_H
#define CGAL_TANGENT_VECTOR_FIELDS_SOFT_FIELD_DESIGN_H

/// \file Soft_field_design.h
/// Soft-constrained field design (Fisher et al. 2007, on piecewise-constant fields as
/// the thesis re-implemented it; SPEC 7): minimise
/// `E_D(x) + omega E_B(x) + sum_i w_i (C~_i x - c_i)^2`, reduced and full.

#include <CGAL/Tangent_vector_fields/Eigenfield_basis.h>
#include <CGAL/Tangent_vector_fields/Field_constraint.h>
#include <CGAL/Tangent_vector_fields/Hodge_solver.h>
#include <CGAL/Tangent_vector_fields/internal/Hodge_pull_back.h>
#include <CGAL/Tangent_vector_fields/internal/Basis_rows.h>
#include <CGAL/Tangent_vector_fields/internal/Constraint_system.h>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <map>
#include <memory>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {

/// Options of soft-constrained design.
struct Soft_design_options
{
  /// Weight `omega` of the biharmonic energy, for the mesh scaled to unit area.
  double omega = 0;
};

/// \brief Common bookkeeping of the soft designs: constraints with weights.
///
/// Weights are for the mesh scaled to unit area: divergence and curl rows (one
/// inverse length) are multiplied by `sqrt(area)`, so results do not depend on scale.
/// Soft constraints never conflict: contradictory ones give a weighted compromise.
/// Harmonic directions seen by no constraint carry no energy at all; they are set
/// to zero (minimum-norm answer).
class Soft_field_design
{
public:
  virtual ~Soft_field_design();
  /// \throws Invalid_input for a malformed constraint or a weight that is not positive and finite.
  int add(const Field_constraint& constraint, double weight = 1);
  void remove(int id);
  /// Changes a constraint's values (same kind and place) or replaces it.
  void change(int id, const Field_constraint& constraint, double weight = 1);
  int number_of_constraints() const { return static_cast<int>(entries_.size()); }
  /// The field as frame coordinates (`2nf`).
  virtual Eigen::VectorXd field() const = 0;
  /// `E_D + omega E_B` of the last solution (without the constraint term).
  virtual double energy() const = 0;
  /// Harmonic directions that no constraint determines (set to zero).
  int undetermined_harmonic() const { return undetermined_; }
  const Operator_matrices& operators() const { return *operators_; }

protected:
  Soft_field_design(std::shared_ptr<const Operator_matrices> operators, const Soft_design_options& options);

  struct Weighted_row
  {
    Constraint_row row;
    double weight = 0;       // w_i times the unit-area scale squared
    Eigen::VectorXd in_basis; // the row in a spectral basis (reduced design only)
    Eigen::VectorXd y;        // its pull-back Q^+ r^T (full design only)
    Eigen::VectorXd harmonic; // its harmonic part (full design only)
  };
  struct Entry
  {
    Field_constraint constraint;
    double weight = 1; // as given
    std::vector<Weighted_row> rows;
  };
  /// Called with the rows of a new constraint (which the solver may annotate) before they are stored.
  virtual void rows_added(std::vector<Weighted_row>& rows) = 0;
  virtual void rows_removed(const std::vector<Weighted_row>& rows) = 0;
  virtual void values_changed() = 0;
  /// Null space of the weighted harmonic rows (`nh x k`, orthonormal columns), given
  /// the harmonic parts `h_i` of all rows.
  Eigen::MatrixXd undetermined_directions(const std::vector<std::pair<Eigen::VectorXd, double>>& harmonic_rows,
                                          int harmonic_dimension) const;

  std::shared_ptr<const Operator_matrices> operators_;
  Soft_design_options options_;
  double omega_;       // for the mesh as given
  double energy_scale_; // E_D + omega E_B of a unit field of frequency 1/area
  std::map<int, Entry> entries_;
  mutable int undetermined_ = 0;

private:
  int next_id_ = 0;
};

/// \brief Soft design in the span of the first `d` elements of a spectral basis:
/// `(Lambda + omega Lambda^2 + C^T W C) a = C^T W c`, a dense `d x d` Cholesky factor
/// updated by one rank-one update per constraint row added or removed; a value change
/// re-solves with the same factor (two triangular solves).
class Reduced_soft_design : public Soft_field_design
{
public:
  Reduced_soft_design(std::shared_ptr<const Eigenfield_basis> basis, int basis_size = 0,
                      const Soft_design_options& options = Soft_design_options());
  int basis_size() const { return d_; }
  /// Coefficients in the basis (solves if needed).
  const Eigen::VectorXd& coefficients() const;
  Eigen::VectorXd field() const override;
  double energy() const override;
  /// Refactors from scratch (done automatically when the undetermined harmonic directions change).
  void refactor();

protected:
  void rows_added(std::vector<Weighted_row>& rows) override;
  void rows_removed(const std::vector<Weighted_row>& rows) override;
  void values_changed() override { solved_ = false; }

private:
  // Recomputes the undetermined harmonic directions from the stored rows and `extra`
  // (rows being added) minus `removed`; true if they changed.
  bool update_harmonic(const std::vector<Weighted_row>& extra, const std::vector<Weighted_row>* removed);
  void refactor_with(const std::vector<Weighted_row>& extra);

  std::shared_ptr<const Eigenfield_basis> basis_;
  int d_;
  internal::Basis_rows rows_in_basis_;
  Eigen::VectorXd diagonal_;       // lambda + omega lambda^2
  Eigen::MatrixXd undetermined_directions_; // nh x k
  Eigen::LLT<Eigen::MatrixXd> factor_;
  mutable bool solved_ = false;
  mutable Eigen::VectorXd coefficients_;
};

/// \brief Soft design on all `2nf` unknowns: the minimiser of
/// `x^T Q x + sum_i w_i (r_i x - c_i)^2` with `Q = S + omega B`, through the Hodge structure.
///
/// `Q` is never formed or factored with the constraints.  Each row is pulled back once,
/// when its constraint is added, to `y_i = Q^+ r_i^T` (two chained solves with the Hodge
/// solver's factorisations of `W` and `W*`, three when `omega > 0`:
/// `internal::Hodge_pull_back`); then `x = sum_i t_i y_i + U_h z` with
/// \code
///   [ K + W^-1   C_h ] [ t ]   [ c ]
///   [ C_h^T      0   ] [ z ] = [ 0 ],      K_ij = r_i y_j,  C_h = rows' harmonic parts
/// \endcode
/// (`t` are the weighted residuals `w_i (c_i - r_i x)`; `z` spans the harmonic directions
/// some constraint sees).  Adding a constraint costs its pull-backs, removing one nothing, a
/// value edit one small dense solve and the product `Y t`: no sparse factorisation depends
/// on the constraints.
class Full_soft_design : public Soft_field_design
{
public:
  explicit Full_soft_design(std::shared_ptr<const Hodge_solver> hodge,
                            const Soft_design_options& options = Soft_design_options());
  ~Full_soft_design();
  Eigen::VectorXd field() const override;
  double energy() const override;
  /// Seconds spent factoring `W`, `W*` (and their screened forms when `omega > 0`).
  double factor_seconds() const { return factor_seconds_; }
  /// Seconds spent pulling rows back, in total.
  double pull_back_seconds() const { return pull_back_seconds_; }
  /// Seconds of the last solve (small system and the product with the pull-backs).
  double solve_seconds() const { return solve_seconds_; }
  /// Largest relative residual of the second-order solves of the pull-backs (solver precision).
  double residual() const { return residual_; }

protected:
  void rows_added(std::vector<Weighted_row>& rows) override;
  void rows_removed(const std::vector<Weighted_row>&) override { solved_ = false; }
  void values_changed() override { solved_ = false; }

private:
  void solve() const;

  std::shared_ptr<const Hodge_solver> hodge_;
  double length_unit_;
  internal::Hodge_pull_back pull_back_;
  mutable bool solved_ = false;
  mutable Eigen::VectorXd x_;
  double factor_seconds_ = 0, pull_back_seconds_ = 0, residual_ = 0;
  mutable double solve_seconds_ = 0;
};

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
