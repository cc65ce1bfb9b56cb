// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_INTERNAL_HODGE_PULL_BACK_H
#define CGAL_TANGENT_VECTOR_FIELDS_INTERNAL_HODGE_PULL_BACK_H

/// \file Hodge_pull_back.h
/// Pull-backs `Q^+ r^T` of constraint rows through the Hodge structure, for the two
/// energies of field design: `E_B + omega E_D` (splines) and `E_D + omega E_B` (soft design).

#include <CGAL/Tangent_vector_fields/Hodge_solver.h>
#include <CGAL/Model_reduction/Sparse_spd_solver.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <atomic>
#include <memory>
#include <mutex>

namespace CGAL {
namespace Tangent_vector_fields {
namespace internal {

/// The energy `Q` whose pseudo-inverse a pull-back applies.
enum class Design_energy
{
  biharmonic, ///< `B + omega S = MX (L^2 + omega L)`: tangent vector field splines
  dirichlet   ///< `S + omega B = MX (L + omega L^2)`: soft-constrained design
};

/// \brief `Y = Q^+ Pi R` for columns `R` (rows of constraints), never forming `Q`.
///
/// `L G p = G M^-1 W p` and `L J G* p = J G* M*^-1 W* p`, so with `MX^-1 r^T = G f + J G* g + h`
/// every pull-back is a chain of scalar second-order solves per part (exact part shown;
/// the coexact part is the same with `W*`, `M*`, `G*`):
/// \code
///   biharmonic: W f = G^T r,  W q = M f,  (W + omega M) p = M q            y = G p
///   dirichlet:  W f = G^T r,  W q = M f,  (M + omega W) p = M q  (p = q if omega = 0)
/// \endcode
/// `W` and `W*` are the Hodge solver's CHOLMOD factorisations; a screened form `W + a M` is
/// factored only when `omega > 0`.  The mesh is measured in `length_unit` (G times u,
/// masses over u^2) so that the intermediate potentials stay near the size of the rows at
/// any mesh size; `omega` is given in that unit.
class Hodge_pull_back
{
public:
  Hodge_pull_back(std::shared_ptr<const Hodge_solver> hodge, Design_energy energy, double omega, double length_unit);
  ~Hodge_pull_back();

  /// Factors what the pull-backs need (done by the first `apply` otherwise); returns seconds.
  double factor() const;
  /// `Y` (`2nf x m`) for the rows `R` (`2nf x m`, frame coordinates, sparse); `harmonic` receives
  /// their harmonic parts `U_h^T R u` (`nh x m`, orthonormal for MX / u^2).  The first call
  /// raises `residual` to the largest relative residual of its second-order solves (the
  /// solver precision; later calls share the factorisations and leave it).
  Eigen::MatrixXd apply(const Eigen::SparseMatrix<double>& R, Eigen::MatrixXd& harmonic, double& residual) const;
  /// `Q X` in the length unit (S MX^-1 S formed as products only).
  Eigen::MatrixXd apply_energy(const Eigen::MatrixXd& X) const;
  /// Fields of harmonic coefficients `z` (in the orthonormal basis of `apply`).
  Eigen::VectorXd harmonic_field(const Eigen::VectorXd& z) const;
  /// Squared norm of the harmonic coefficients of a field, in that basis.
  double harmonic_squared_norm(const Eigen::VectorXd& x) const;

private:
  struct Screened;
  struct Transposes;
  const Transposes& transposes() const;
  // The chain of one part: `solve` is W or W*, masses M or M*.
  template <class Solve, class Screened_solve>
  Eigen::MatrixXd chain(const Eigen::MatrixXd& rhs, const Eigen::SparseMatrix<double>& laplacian,
                        const Eigen::VectorXd& masses, const Solve& solve, const Screened_solve& screened,
                        double* residual) const;

  std::shared_ptr<const Hodge_solver> hodge_;
  Design_energy energy_;
  double omega_, u_;
  mutable std::unique_ptr<Screened> screened_;
  mutable std::once_flag transposes_made_;
  mutable std::unique_ptr<Transposes> transposes_;
  mutable bool factored_ = false;
  mutable std::atomic<bool> residual_measured_{false};
};

} // namespace internal
} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
