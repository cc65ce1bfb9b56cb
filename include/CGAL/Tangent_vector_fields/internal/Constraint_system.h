// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_INTERNAL_CONSTRAINT_SYSTEM_H
#define CGAL_TANGENT_VECTOR_FIELDS_INTERNAL_CONSTRAINT_SYSTEM_H

/// \file Constraint_system.h
/// The small dense system of the range-space method (SPEC 7), shared by the reduced
/// and the full spline solvers.
///
/// With `Y = Q^+ C~^T` (one column per constraint row, energy `Q`, harmonic fields
/// removed) the spline is `x = Y mu + U_h z` where
/// \code
///   [ K      C_h ] [mu]   [c]          K = C~ Y   (nc x nc, SPD when the rows are independent)
///   [ C_h^T  0   ] [z ] = [0]          C_h = C~ U_h (constraint rows on the harmonic fields)
/// \endcode
/// `K = R^T R` is kept as a Cholesky factor that is updated when rows are appended
/// (one new column) or removed (re-triangularising the trailing block), never
/// refactored from scratch.  Eliminating `mu` leaves the least-squares problem
/// `min |R^-T c - V z|` with `V = R^-T C_h`: harmonic directions that no constraint
/// sees (tiny singular values of `V`) get coefficient 0, the minimum-norm answer.
/// With a harmonic energy `kappa |z|^2` the elimination gives the ridge problem
/// `min |R^-T c - V z|^2 + kappa |z|^2` instead.

#include <Eigen/Core>

namespace CGAL {
namespace Tangent_vector_fields {
namespace internal {

/// A harmonic direction whose squared singular value in the constraint rows is below
/// this times the energy scale is one no constraint sees: its coefficient would be
/// roundoff divided by roundoff.  Seen by a constraint, it is of the order of the scale or larger.
constexpr double undetermined_harmonic_threshold = 1e-10;

class Constraint_system
{
public:
  /// `harmonic_scale`: energy scale (`mu` of a unit field of the mesh's lowest
  /// frequencies) against which `V`'s singular values are judged.
  /// `harmonic_penalty`: energy `kappa |z|^2` of the harmonic coefficients (0: free).
  Constraint_system(int harmonic_dimension, double harmonic_scale, double harmonic_penalty = 0);

  int size() const { return n_; }
  int harmonic_dimension() const { return nh_; }

  /// `sin^2` of the angle between a new row and the span of the current rows, in
  /// the metric of `K`: `(kappa - |R^-T k|^2) / kappa` where `k` holds the new row's
  /// `K` entries against the current rows and `kappa` its diagonal entry.
  double independence(const Eigen::VectorXd& k, double kappa) const;
  /// Appends a row (call `independence` first to decide whether it is acceptable).
  /// `h` is the row's harmonic part (`C~_i U_h`).
  void append(const Eigen::VectorXd& k, double kappa, const Eigen::VectorXd& h);
  /// Removes rows `[first, first + count)`.
  void remove(int first, int count);

  /// `K^-1 b`.
  Eigen::VectorXd solve_K(const Eigen::VectorXd& b) const;
  /// `mu` and `z` for constraint values `c`.
  void solve(const Eigen::VectorXd& c, Eigen::VectorXd& mu, Eigen::VectorXd& z) const;

  /// Harmonic directions no constraint determines (given coefficient 0).
  int undetermined_harmonic() const { return undetermined_; }
  /// Smallest `sigma^2 / harmonic_scale` over the determined harmonic directions
  /// (infinity if none): small values mean a large, weakly determined harmonic part.
  double harmonic_determination() const { return determination_; }
  /// Smallest `R_jj^2 / K_jj` over the rows: how close the rows are to dependent.
  double smallest_independence() const;

private:
  void update_harmonic();

  int n_ = 0, nh_ = 0;
  double harmonic_scale_;
  double harmonic_penalty_;
  Eigen::MatrixXd R_;  // upper triangular, capacity >= n_
  Eigen::MatrixXd Ch_; // n_ x nh_ (capacity rows)
  // Pseudo-inverse of V on its determined directions: z = W S^-1 P^T g.
  Eigen::MatrixXd V_pinv_; // nh x n
  Eigen::MatrixXd V_;      // n x nh
  int undetermined_ = 0;
  double determination_;
};

} // namespace internal
} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
