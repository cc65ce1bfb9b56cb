// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PROJECTIVE_DYNAMICS_POSITION_SUBSPACE_H
#define CGAL_PROJECTIVE_DYNAMICS_POSITION_SUBSPACE_H

/// \file Position_subspace.h
/// The position subspace of reduced Projective Dynamics (SPEC 12, the thesis' "skinning"
/// construction): `m` samples by farthest-point sampling with graph (Dijkstra) distances on the
/// element edge graph, a radius `r` = multiplier times the covering radius, weights
/// `w_j(d) = (1 - d^2/r^2)^2` for `d < r` normalised per vertex, and four columns per sample,
/// `w_j x`, `w_j y`, `w_j z`, `w_j` (rest coordinates).  `q = U a` with `a` of `k = 4m` rows
/// and 3 columns; `U` spans every affine map of the rest shape (so rigid motions are exact),
/// stays sparse and is not orthonormalised.  No extra constant column: it would duplicate the
/// sum of the `w_j` columns and make `U^T M U` singular.

#include <CGAL/Projective_dynamics/Elastic_model.h>

#include <Eigen/SparseCore>

#include <vector>

namespace CGAL {
namespace Projective_dynamics {

/// A sparse basis of positions, row `i` for vertex `i`, `4 m` columns.
struct Position_subspace
{
  Eigen::SparseMatrix<double, Eigen::RowMajor> basis; ///< `U`, n x 4m
  std::vector<int> samples;                           ///< the `m` sample vertices, in sampling order
  double covering_radius = 0;                         ///< largest graph distance of a vertex to its nearest sample
  double radius = 0;                                  ///< the weights' support radius `r`
  /// The coefficients `a` (4m x 3) with `U a` = the rest positions.
  Eigen::MatrixXd rest_coordinates() const;
};

/// `count` vertices by farthest-point sampling with graph distances on the element edge graph
/// (the edges within each element except bending, whose vertices the strain elements connect;
/// Euclidean rest lengths).  The first sample is the vertex farthest from vertex 0; each next is
/// the vertex farthest from all earlier ones (a vertex of another connected component is at
/// infinite distance, so every component gets a sample before any gets two).
/// `distances`, if given, receives each vertex's distance to its nearest sample.
/// \throws Invalid_input for `count < 1` or `count > ` the number of vertices.
std::vector<int> farthest_point_samples(const Elastic_model& model, int count, std::vector<double>* distances = nullptr);

/// Per-vertex weights of `samples`: `(1 - d^2/r^2)^2` for graph distance `d < r` (the sample
/// itself always 1 before normalising, so `r = 0` is allowed), normalised per vertex to sum 1;
/// an n x m sparse matrix.
/// \throws Invalid_input if a vertex is reached by no sample, naming it (it lies in a connected
///         component without sample, or `r` is too small).
Eigen::SparseMatrix<double, Eigen::RowMajor> sample_weights(const Elastic_model& model, const std::vector<int>& samples,
                                                            double radius);

/// The position subspace of `samples` samples with radius `radius_multiplier` times the
/// covering radius (reference 1.1).  A vertex reached by no sample is an error (see
/// `sample_weights`): with farthest-point samples this happens only when the element graph has
/// more connected components than samples.
/// \throws Invalid_input for `samples` out of `[1, n]` or a multiplier not above 1 (then some
///         vertex at the covering radius would get weight 0 from every sample), with the reason.
Position_subspace make_position_subspace(const Elastic_model& model, int samples, double radius_multiplier = 1.1);

} // namespace Projective_dynamics
} // namespace CGAL

#endif
