// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PROJECTIVE_DYNAMICS_PROJECTIONS_H
#define CGAL_PROJECTIVE_DYNAMICS_PROJECTIONS_H

/// \file projections.h
/// The local step of Projective Dynamics for each element type: the closest point of an
/// element's current value `S_i q` in its constraint set `C_i` (SPEC 12).  Every projection
/// commutes with rotations, `P(R F) = R P(F)`, so the energy is invariant under rigid motions.

#include <Eigen/Core>

namespace CGAL {
namespace Projective_dynamics {

/// Edge spring: the vector `d` with its length clamped to `[min_length, max_length]`.  A zero
/// `d` (no direction to keep) becomes `fallback` (the rest edge) scaled into the range.
Eigen::Vector3d project_spring(const Eigen::Vector3d& d, double min_length, double max_length,
                               const Eigen::Vector3d& fallback);

/// Triangle strain: the 3x2 deformation gradient `F = U S V^T` (thin SVD) with its singular
/// values clamped to `[smin, smax]`: `U clamp(S) V^T`.  `[1, 1]` projects on the isometries.
Eigen::Matrix<double, 3, 2> project_triangle_strain(const Eigen::Matrix<double, 3, 2>& F, double smin, double smax);

/// Tetrahedron strain: `F = U S V^T`; if `det U det V < 0` (an inverted tetrahedron) the sign
/// of the smallest singular value and of its column of `U` are flipped, so that `U` and `V` are
/// rotations, then the singular values are clamped to `[smin, smax]` (`0 < smin <= smax`).
/// The result has a positive determinant; `[1, 1]` gives the closest rotation (for
/// `det F > 0` the rotation of the polar decomposition).
Eigen::Matrix3d project_tet_strain(const Eigen::Matrix3d& F, double smin, double smax);

/// Bending: the current mean-curvature vector `h` rescaled to the rest length `rest_norm`
/// (0 for a flat rest shape).  A zero `h` becomes `fallback` (the rest vector).
Eigen::Vector3d project_bending(const Eigen::Vector3d& h, double rest_norm, const Eigen::Vector3d& fallback);

} // namespace Projective_dynamics
} // namespace CGAL

#endif
