// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_INTERNAL_N_FIELD_GEOMETRY_H
#define CGAL_TANGENT_VECTOR_FIELDS_INTERNAL_N_FIELD_GEOMETRY_H

// Angles in the faces' own layouts (Intrinsic_mesh), shared by the n-field operators
// and the singularity index.

#include <CGAL/Tangent_vector_fields/Intrinsic_mesh.h>

#include <array>

namespace CGAL {
namespace Tangent_vector_fields {
namespace internal {

/// Position of local corner `k` of face `f` in its frame.
std::array<double, 2> corner_layout(const Intrinsic_mesh& mesh, int f, int k);
/// Local corner of vertex `v` in face `f`, or -1.
int local_corner(const Intrinsic_mesh& mesh, int f, int v);
/// Angle, in the frame of `f`, of the edge vector from vertex `from` to vertex `to` (both of `f`).
double edge_angle(const Intrinsic_mesh& mesh, int f, int from, int to);
/// Interior angle at local corner `k` of face `f`.
double corner_angle(const Intrinsic_mesh& mesh, int f, int k);
/// `a` wrapped into `[-pi, pi)`.
double wrap_angle(double a);

} // namespace internal
} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
