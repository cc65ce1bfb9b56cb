// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PROJECTIVE_DYNAMICS_PROJECTION_SUBSPACE_H
#define CGAL_PROJECTIVE_DYNAMICS_PROJECTION_SUBSPACE_H

/// \file Projection_subspace.h
/// The constraint-projection subspace of hyper-reduced Projective Dynamics (SPEC 12): for
/// one element group, a second set of farthest-point samples gives element weights (the mean
/// of the element's vertex weights, renormalised); the candidate columns are the weights times
/// the rest-state projections (per coordinate) and the weights themselves; the rest projections
/// themselves are kept exactly (so the rest state stays at rest) and the rest of the candidates is
/// compressed by mass-weighted PCA, keeping the leading eigenvectors.

#include <CGAL/Projective_dynamics/Elastic_model.h>

#include <Eigen/Core>

namespace CGAL {
namespace Projective_dynamics {

/// The `l` leading principal directions of the columns of `C` in the inner product
/// `<x, y> = x^T diag(weights) y` (uncentred): with `G = C^T diag(weights) C = E diag(lambda) E^T`,
/// eigenvalues decreasing, returns `C E_l diag(lambda_l)^{-1/2}`, whose columns are orthonormal
/// for that inner product and span the `l`-dimensional subspace that best approximates the
/// columns of `C` in the weighted norm.
/// \throws Invalid_input for `l < 0`, `l > C.cols()`, a weight count unlike `C.rows()`, a
///         negative weight, or `l` above the numerical rank of `C` (the `l`-th eigenvalue below
///         `1e-12` times the largest: those directions are rounding noise).
Eigen::MatrixXd mass_weighted_pca(const Eigen::MatrixXd& C, const Eigen::VectorXd& weights, int l);

/// The projection subspace `V` (rows of `group`'s elements x `l`) of element group `group` of
/// `model`: samples `constraint_samples` (farthest points), radius `radius_multiplier` times their
/// covering radius, candidates as above; the first columns (up to 3) span the rest
/// projections, the others are `mass_weighted_pca` of the candidates with that span removed,
/// with the element measures as weights.
/// \throws Invalid_input as `make_position_subspace` and `mass_weighted_pca`.
Eigen::MatrixXd projection_subspace(const Elastic_model& model, int group, int constraint_samples, double radius_multiplier,
                                    int l);

} // namespace Projective_dynamics
} // namespace CGAL

#endif
