// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_INTERNAL_SCALAR_EIGENPROBLEM_H
#define CGAL_TANGENT_VECTOR_FIELDS_INTERNAL_SCALAR_EIGENPROBLEM_H

// The two scalar eigenproblems behind the eigenfield basis, exactly as its eigensolver
// receives them.  Shared by `Eigenfield_basis` and the benchmarks that compare other
// eigensolvers on the same matrices (bench/tangent_vector_fields/slepc_side_by_side.cpp).

#include <CGAL/Tangent_vector_fields/Eigenfield_basis.h>
#include <CGAL/Model_reduction/Generalized_eigensolver.h>
#include <CGAL/Tangent_vector_fields/Operator_matrices.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {
namespace internal {

/// `A x = lambda diag(d) x` restricted to the unknowns that carry mass, with `d` scaled
/// to unit total area: its eigenvalues are `area` times those of the mesh as given.
struct Scalar_eigenproblem
{
  Eigen::SparseMatrix<double> A;
  Eigen::VectorXd d;
  Eigen::MatrixXd kernel;    ///< columns span the null space of `A` (component constants)
  std::vector<int> unknowns; ///< positions in the full vector (empty: all)
  Eigen::Index full_size = 0;
  double area = 1;

  /// Model_reduction::Eigenpairs outside the kernel.
  int available() const { return static_cast<int>(A.rows() - kernel.cols()); }

  /// Rows of `X` (one per unknown) put back at their positions in the full vector, zero elsewhere.
  /// `factor X` on the full vector (zero off the unknowns).
  Eigen::MatrixXd expand(Eigen::MatrixXd X, double factor = 1) const;
  /// The same for float32 columns (each entry scaled in double, then rounded once more).
  Eigen::MatrixXf expand(Eigen::MatrixXf X, double factor = 1) const;
};

/// Exact problem (`type == exact`): `W phi = lambda M phi` on the vertices in faces, the
/// constants of each component as kernel.  Coexact problem (`type == coexact`):
/// `W* psi = mu M* psi` on interior edges, a constant on each closed component as kernel
/// (components with boundary have zero boundary values).  `area` is the mesh's total area.
/// \throws Invalid_input for `Eigenfield_type::harmonic`.
Scalar_eigenproblem scalar_eigenproblem(const Operator_matrices& ops, Eigenfield_type type, double area);

/// The eigensolver settings the basis uses for `options` (without progress reports).
Model_reduction::Eigensolver_options eigensolver_options(const Basis_options& options);

} // namespace internal
} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
