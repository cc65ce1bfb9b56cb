// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_VIBRATION_MODES_MODES_H
#define CGAL_VIBRATION_MODES_MODES_H

/// \file Modes.h
/// A basis of vibration modes, ordinary or compressed.

#include <CGAL/Model_reduction/Generalized_eigensolver.h>

#include <Eigen/Core>

#include <vector>

namespace CGAL {
namespace Vibration_modes {

struct Modes
{
  /// One column per mode over all unknowns (zero at pinned ones), `M`-orthonormal and
  /// `M`-orthogonal to the rigid motions.
  Eigen::MatrixXd vectors;
  /// `u^T H u` of each mode: the eigenvalue of an ordinary mode (ascending).
  Eigen::VectorXd energies;
  /// Dimension of the deflated kernel (the rigid motions).
  int kernel_dimension = 0;

  /// Ordinary modes: the eigensolver's relative residual per mode and its inertia proof
  /// that no eigenvalue below `complete_below` was missed.
  Eigen::VectorXd residuals;
  double complete_below = 0;
  Model_reduction::Completeness_check completeness;

  /// Compressed modes: the objective `u^T H u + mu |u|_{1,M}` and `|u|_{1,M}` of each mode,
  /// the fraction of vertices where it is non-zero (a mode is the ADMM's sparse iterate,
  /// made exactly feasible on its support: its zeros are exact), and the iterations of the
  /// outer (ICCM) and inner (ADMM) loops.
  double sparsity_weight = 0;
  Eigen::VectorXd objectives, l1_norms, support_fractions;
  std::vector<int> outer_iterations, inner_iterations;
  /// Compressed modes: 1 where ICCM met its stopping rule, 0 where it stopped at
  /// `Compressed_mode_options::max_outer_iterations` (the mode is the last iterate: feasible,
  /// but its objective may still fall).
  std::vector<int> converged;
};

} // namespace Vibration_modes
} // namespace CGAL

#endif
