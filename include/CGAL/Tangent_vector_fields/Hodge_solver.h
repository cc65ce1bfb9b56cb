// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_HODGE_SOLVER_H
#define CGAL_TANGENT_VECTOR_FIELDS_HODGE_SOLVER_H

/// \file Hodge_solver.h
/// The discrete Hodge decomposition (SPEC section 4) on frame-coordinate vectors:
/// `v = G f + J G* g + h`.  Factorisations and the harmonic basis are built on first
/// use and kept for later decompositions.

#include <CGAL/Tangent_vector_fields/Operator_matrices.h>
#include <CGAL/Model_reduction/Sparse_spd_solver.h>

#include <Eigen/Core>

#include <cstdint>
#include <memory>

namespace CGAL {
namespace Tangent_vector_fields {

/// Which results a decomposition computes (combine with `|`).
enum Hodge_output : unsigned {
  hodge_exact = 1u,       ///< the curl-free part `G f`
  hodge_coexact = 2u,     ///< the divergence-free part `J G* g`
  hodge_harmonic = 4u,    ///< the harmonic part `h`
  hodge_potential = 8u,   ///< `f`, one value per vertex
  hodge_copotential = 16u ///< `g`, one value per edge (zero on boundary edges)
};

/// Results of `Hodge_solver::decompose`; entries not asked for stay empty.
struct Hodge_parts
{
  Eigen::VectorXd exact, coexact, harmonic; ///< `2nf` frame coordinates each
  Eigen::VectorXd potential;                ///< `nv`, zero mean (in `M`) per component
  Eigen::VectorXd copotential;              ///< `ne`, zero on boundary edges, zero mean (in `M*`) per closed component
};

/// Hodge decomposition with cached factorisations.
///
/// Potentials: `W f = G^T MX v` with one vertex pinned per component, then shifted
/// to zero mean; `W* g = -G*^T J MX v` on interior edges with one edge pinned per
/// closed component (components with boundary are regular thanks to the zero
/// boundary values), then shifted to zero mean.  Pinning keeps both systems
/// positive definite, so no solver is ever handed a singular matrix.
///
/// The const member functions may be called from several threads at once (each
/// factorisation is made and used under its own lock, so a vertex solve and an edge solve can
/// run side by side).
class Hodge_solver
{
public:
  explicit Hodge_solver(std::shared_ptr<const Operator_matrices> operators);
  ~Hodge_solver();

  const Operator_matrices& operators() const { return *ops_; }

  /// Decomposes `field` (`2nf`), computing only what `outputs` asks for (and what
  /// that needs: the harmonic part needs both potentials).
  /// \throws Invalid_input if `field` has the wrong size or non-finite entries.
  Hodge_parts decompose(const Eigen::VectorXd& field, unsigned outputs) const;

  /// `f` with `W f = G^T MX v` for each column `v` of `fields` (`2nf x k`).
  Eigen::MatrixXd potentials(const Eigen::MatrixXd& fields) const;
  /// `g` (all edges, 0 on the boundary) with `W* g = -G*^T J MX v` per column.
  Eigen::MatrixXd copotentials(const Eigen::MatrixXd& fields) const;

  /// Solves `W f = b` for each column (`nv x k`); each column must sum to zero over
  /// every component (then the system is consistent).  Returns the solution with
  /// zero `M`-mean per component; vertices in no face get 0.
  Eigen::MatrixXd solve_vertex_laplacian(const Eigen::MatrixXd& b) const;
  /// Solves `W* g = b` on interior edges (`ne_int x k`); on closed components each
  /// column must sum to zero.  Returns the solution with zero `M*`-mean per closed component.
  Eigen::MatrixXd solve_edge_laplacian(const Eigen::MatrixXd& b) const;

  /// Dimension of the harmonic space predicted by the topology.
  int harmonic_dimension() const;
  /// An `MX`-orthonormal basis of the harmonic fields (`2nf x dim`), computed on
  /// first call by projecting `dim + 2` random fields (seeded by `seed`) and
  /// orthonormalising them.
  /// \throws Numerical_failure if the numerical rank of the projections differs from
  ///         the topological dimension: the mesh is not what its connectivity claims.
  const Eigen::MatrixXd& harmonic_basis(std::uint64_t seed = 0x5eed) const;
  /// Singular values (relative to the largest) of the projected random fields, from
  /// the last harmonic basis computation: the first `dim` are O(1), the rest roundoff.
  const Eigen::VectorXd& harmonic_rank_spectrum() const;

  /// Whether the factorisation for the potential / copotential exists yet.
  bool has_potential_factorization() const;
  bool has_copotential_factorization() const;

private:
  struct Impl;
  std::shared_ptr<const Operator_matrices> ops_;
  std::unique_ptr<Impl> impl_;
};

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
