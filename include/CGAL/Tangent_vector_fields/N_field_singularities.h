// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_N_FIELD_SINGULARITIES_H
#define CGAL_TANGENT_VECTOR_FIELDS_N_FIELD_SINGULARITIES_H

/// \file N_field_singularities.h
/// The index of an n-field at every vertex (SPEC 10), interior and boundary, with
/// Poincare-Hopf exact on every mesh: the indices sum to `n chi`.

#include <CGAL/Tangent_vector_fields/N_field_operators.h>

#include <Eigen/Core>

#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {

/// A vertex where an n-field turns: its index is `index / n`.
struct N_field_singularity
{
  int vertex = -1;
  int index = 0;             ///< `k`: the field turns by `2 pi k / n` around the vertex
  bool on_boundary = false;  ///< a boundary vertex (see `n_field_indices`)
};

/// \brief `k_v` of every vertex: the index of the n-field `z` at `v` is `k_v / n`.
///
/// Interior vertex, faces `f_0 ... f_{m-1}` counter-clockwise:
/// `k_v = (sum_i wrap(arg z_{f_{i+1}} - arg(rho^n z_{f_i})) + n K_v) / 2 pi`, `K_v` the angle
/// defect: a field turning once counter-clockwise around a flat vertex has `k = +1`.
///
/// Boundary vertex, fan `f_first ... f_last` counter-clockwise, boundary edges `v -> w` in
/// `f_first` and `u -> v` in `f_last` (the surface on their left): the same sum over the fan's
/// interior edges, plus `n` times the boundary's turning `pi - sum of corner angles`, plus
/// the change of the field's angle relative to the boundary, `beta(v -> w) - beta(u -> v)`,
/// where `beta(e) = wrap(arg z_f - n angle(e))` is the n-field's angle to the boundary edge `e`.
/// So a field that keeps its angle to the boundary (e.g. aligned with it) has index 0 at a
/// straight boundary vertex and `n (pi - theta) / 2 pi` (rounded) at a corner of angle `theta`;
/// a field that turns against the boundary by a full period of `2 pi / n` has a singularity there.
/// Each boundary edge's `beta` enters its two end vertices with opposite signs and each
/// interior edge's turning enters its two end vertices with opposite signs, so the sum over all
/// vertices is `n` times the total curvature over `2 pi`: `n chi` (Gauss-Bonnet), exactly.
///
/// Faces with `z_f = 0` take angle 0; vertices in no face get 0.
std::vector<int> n_field_indices(const N_field_operators& operators, const Eigen::VectorXd& z);

/// The vertices with a non-zero index, in vertex order.
std::vector<N_field_singularity> n_field_singularities(const N_field_operators& operators, const Eigen::VectorXd& z);

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
