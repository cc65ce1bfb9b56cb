// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_INTERNAL_SINGULARITY_CONNECTION_H
#define CGAL_TANGENT_VECTOR_FIELDS_INTERNAL_SINGULARITY_CONNECTION_H

// The change of the connection that prescribed singularities make (see N_field_operators).

#include <CGAL/Tangent_vector_fields/N_field_operators.h>

#include <Eigen/Core>

namespace CGAL {
namespace Tangent_vector_fields {
namespace internal {

/// `delta_e` per interior edge (order of `Intrinsic_mesh::interior_edges`), added to the
/// transport from the edge's second face into its first.
Eigen::VectorXd singularity_connection(const N_field_operators& operators);

} // namespace internal
} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
