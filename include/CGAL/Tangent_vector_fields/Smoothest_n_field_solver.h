// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_SMOOTHEST_N_FIELD_SOLVER_H
#define CGAL_TANGENT_VECTOR_FIELDS_SMOOTHEST_N_FIELD_SOLVER_H

/// \file Smoothest_n_field_solver.h
/// The smoothest n-field on the index-based operators (the generic version on a
/// `TriangleMesh` is in `smoothest_n_field.h`).

#include <CGAL/Tangent_vector_fields/N_field_operators.h>

#include <Eigen/Core>

namespace CGAL {
namespace Tangent_vector_fields {

struct Smoothest_n_field_options
{
  /// Guide n-field (power representation, `2nf`); empty: none.
  Eigen::VectorXd alignment;
  /// `s` of `E_D(z) + s |z - guide|^2_MX` for the mesh scaled to unit area.
  double alignment_weight = 1;
  /// Relative residual required of the eigenpair (see `Model_reduction::Eigensolver_options::tolerance`).
  double tolerance = 1e-10;
};

/// \brief The smoothest n-field (power representation).
///
/// Without a guide: on each connected component, a parallel field if its holonomy is
/// trivial for n (zero energy), else an eigenvector of the lowest eigenvalue of `L_n`: the
/// minimiser of `E_D(z)` over `|z|_MX = 1` (its magnitude varies and vanishes at the
/// singularities).  With a guide `g`: the minimiser of `E_D(z) + s |z - g|^2_MX`, one sparse
/// solve.
/// \throws Invalid_input for a guide of the wrong size, non-finite, a weight <= 0, or a tolerance outside (0, 1).
Eigen::VectorXd smoothest_n_field(const N_field_operators& operators,
                                  const Smoothest_n_field_options& options = Smoothest_n_field_options());

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
