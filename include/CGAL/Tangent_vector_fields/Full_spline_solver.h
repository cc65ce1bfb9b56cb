// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_FULL_SPLINE_SOLVER_H
#define CGAL_TANGENT_VECTOR_FIELDS_FULL_SPLINE_SOLVER_H

/// \file Full_spline_solver.h
/// Tangent vector field splines on all `2nf` unknowns (SPEC 7): the yardstick for the
/// reduced solver.

#include <CGAL/Tangent_vector_fields/Hodge_solver.h>
#include <CGAL/Tangent_vector_fields/Spline_solver.h>
#include <CGAL/Tangent_vector_fields/internal/Hodge_pull_back.h>

#include <memory>

namespace CGAL {
namespace Tangent_vector_fields {

/// Cost and accuracy of the full solver's pull-backs.
struct Full_solve_statistics
{
  double factor_seconds = 0;    ///< factorisations (first pull-back, and after a new omega)
  double pull_back_seconds = 0; ///< all pull-backs so far
  /// Largest relative residual `|A Z - B|_F / |B|_F` of the second-order solves of a block
  /// of pull-backs (`A` = `W`, `W*` or their screened forms): the solver precision.
  /// (The residual through the fourth-order operator, `|(B + omega S) y - Pi r^T|`, would be
  /// about `eps cond(B)` — 1e-6 at 20k faces, 1e-3 at 70k — whatever the accuracy of `y`.)
  double residual = 0;
};

/// \brief The range-space method on the full field space, through the Hodge structure.
///
/// `Q = B + omega S = MX (L^2 + omega L)` is singular on the harmonic fields and, as a
/// fourth-order operator, badly conditioned (`cond ~ nf^2`).  It is never formed.
/// Since `L G p = G M^-1 W p` and `L J G* p = J G* M*^-1 W* p`, a pull-back
/// `y = Q^+ Pi r^T` splits into scalar second-order solves: with `u = MX^-1 r^T`
/// decomposed as `G f + J G* g + h`,
/// \code
///   W q = M f,    (W + omega M) p = M q,       y_exact   = G p
///   W* q* = M* g, (W* + omega M*) p* = M* q*,  y_coexact = J G* p*
/// \endcode
/// (with `omega = 0` the second solve is again `W`, `W*`).  These reuse the Hodge
/// solver's CHOLMOD factorisations of `W` and `W*`, plus the screened ones when
/// `omega > 0`: exact to solver precision, and far cheaper than factoring `B`.
class Full_spline_solver : public Spline_solver
{
public:
  explicit Full_spline_solver(std::shared_ptr<const Hodge_solver> hodge,
                              const Spline_options& options = Spline_options());
  ~Full_spline_solver();

  Eigen::VectorXd field() const override { return solution(); }
  const Full_solve_statistics& statistics() const { return statistics_; }

protected:
  void pull_back(std::vector<Row>& rows) const override;
  double apply(const Row& row, const Eigen::VectorXd& y) const override { return row.row.dot(y); }
  double energy(const Eigen::VectorXd& x) const override;
  void add_harmonic(const Eigen::VectorXd& z, Eigen::VectorXd& x) const override;
  int space_dimension() const override { return 2 * operators_->mesh().number_of_faces(); }
  void energy_changed() override;

private:
  std::shared_ptr<const Hodge_solver> hodge_;
  // The pull-back chains for the current omega (factored by the first pull-back).
  std::unique_ptr<internal::Hodge_pull_back> pull_back_;
  mutable Full_solve_statistics statistics_;
};


} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
