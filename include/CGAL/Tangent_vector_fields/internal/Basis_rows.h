// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_INTERNAL_BASIS_ROWS_H
#define CGAL_TANGENT_VECTOR_FIELDS_INTERNAL_BASIS_ROWS_H

/// \file Basis_rows.h
/// Constraint rows expressed in a spectral basis: `C~_i U` without forming `U`.

#include <CGAL/Tangent_vector_fields/Eigenfield_basis.h>
#include <CGAL/Tangent_vector_fields/Field_constraint.h>

#include <Eigen/SparseCore>

#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {
namespace internal {

/// `d` itself, or the whole basis for `d = 0`.
/// \throws Invalid_input if `d` is negative or larger than the basis.
int checked_basis_size(const Eigenfield_basis& basis, int d);

/// `r U = (G^T r)^T Phi Lambda^-1/2` on exact elements, `((J G*)^T r)^T Psi Mu^-1/2`
/// on coexact ones and `r U_h` on harmonic ones: a row touching a few faces touches a
/// few vertices and edges, so it costs `O(d)` per touched vertex or edge.
class Basis_rows
{
public:
  /// Rows over the first `d` elements of `basis`.
  Basis_rows(const Eigenfield_basis& basis, int d);

  int size() const { return d_; }
  /// Positions of the harmonic elements among the first `d`.
  const std::vector<int>& harmonic_positions() const { return harmonic_positions_; }
  Eigen::VectorXd operator()(const Constraint_row& row) const;

private:
  const Eigenfield_basis& basis_;
  int d_;
  Eigen::SparseMatrix<double, Eigen::RowMajor> G_rows_, JG_star_rows_;
  std::vector<int> harmonic_positions_;
  std::vector<int> exact_position_, coexact_position_; // basis position per element of each type (-1: beyond d)
  Eigen::VectorXd exact_scale_, coexact_scale_;        // 1/sqrt(lambda)
};

} // namespace internal
} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
