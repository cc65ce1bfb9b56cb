// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_INTERNAL_N_FIELD_PAIRS_H
#define CGAL_TANGENT_VECTOR_FIELDS_INTERNAL_N_FIELD_PAIRS_H

// Eigenvectors of an operator that commutes with J (multiplication by i per face),
// rearranged into pairs (phi, J phi).

#include <Eigen/Core>

namespace CGAL {
namespace Tangent_vector_fields {
namespace internal {

/// From mass-orthonormal eigenvectors in ascending order of `values`, up to `count` columns
/// `(phi_1, J phi_1, phi_2, J phi_2, ...)`, mass-orthonormal, spanning the same `J`-invariant
/// eigenspaces.  Returns the number of columns filled (even).
int pair_up(const Eigen::VectorXd& values, const Eigen::MatrixXd& vectors, const Eigen::VectorXd& mass, int count,
            Eigen::VectorXd& paired_values, Eigen::MatrixXd& paired);

} // namespace internal
} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
