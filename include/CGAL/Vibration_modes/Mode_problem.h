// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_VIBRATION_MODES_MODE_PROBLEM_H
#define CGAL_VIBRATION_MODES_MODE_PROBLEM_H

/// \file Mode_problem.h
/// The matrices of a vibration-mode problem `H u = lambda M u` (SPEC 13.2): a symmetric
/// positive semi-definite `H`, a lumped (diagonal) mass, the known kernel of `H` (the rigid
/// motions a body is free to make), and how unknowns group into vertices for the
/// per-vertex sparsity norm of compressed modes.  Built from a shell energy with pinned
/// vertices, or by the caller from any `H` (a scalar Laplacian: group size 1).

#include <CGAL/Discrete_shells/Shell_energy.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <vector>

namespace CGAL {
namespace Vibration_modes {

struct Mode_problem
{
  /// The stiffness: symmetric positive semi-definite on the free unknowns.
  Eigen::SparseMatrix<double> H;
  /// The lumped mass of each free unknown (> 0); the unknowns of a group share one mass.
  Eigen::VectorXd mass;
  /// A basis of the null space of `H` (may have no columns).
  Eigen::MatrixXd kernel;
  /// Unknowns per vertex: 3 for displacements, 1 for a scalar field.
  int group_size = 3;
  /// The full index of each free unknown (empty: all unknowns are free); modes are returned
  /// over `full_size` unknowns, zero at the others.
  std::vector<Eigen::Index> free_unknowns;
  Eigen::Index full_size = 0;

  /// Checks sizes, symmetry of the pattern, finite and positive masses, equal masses within
  /// a group, and a kernel of the right height.
  /// \throws Invalid_input with the reason.
  void check() const;
  /// Spreads vectors over the free unknowns (rows) to all `full_size` unknowns.
  Eigen::MatrixXd expand(const Eigen::MatrixXd& free_vectors) const;
};

/// The shell's rest Hessian and lumped mass with the vertices `pinned` held in place
/// (their unknowns removed, as are those of vertices in no triangle).  The kernel is the
/// rigid motions left to each connected component: 6 for a free one, 3 with one pinned
/// vertex (rotations about it), 1 with pinned vertices on one line, 0 otherwise.
/// \throws Invalid_input for a pinned index outside the mesh.
Mode_problem shell_mode_problem(const Discrete_shells::Shell_energy& energy, const std::vector<int>& pinned = {});

/// The scalar problem of compressed manifold modes: the cotangent stiffness `K` (weight
/// `(cot a + cot b) / 2` per edge, positive semi-definite), a third of the incident faces'
/// area as mass, the constants of each connected component as kernel; one unknown per
/// vertex (vertices in no triangle are left out, as pinned ones are).
/// \throws Invalid_mesh as the shell energy does for bad triangles; Invalid_input for a
///         pinned index outside the mesh.
Mode_problem laplacian_mode_problem(const Eigen::VectorXd& positions,
                                    const std::vector<Discrete_shells::Shell_energy::Triangle>& triangles,
                                    const std::vector<int>& pinned = {});

/// The rigid motions `t + omega x p` of each connected component of `triangles` on the
/// stacked `positions`, that vanish at the `pinned` vertices: columns over all 3n unknowns.
Eigen::MatrixXd rigid_motions(const Eigen::VectorXd& positions,
                              const std::vector<Discrete_shells::Shell_energy::Triangle>& triangles,
                              const std::vector<int>& pinned = {});

} // namespace Vibration_modes
} // namespace CGAL

#endif
