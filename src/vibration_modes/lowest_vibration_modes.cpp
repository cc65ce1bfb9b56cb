// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Vibration_modes/lowest_vibration_modes.h>
#include <CGAL/Vibration_modes/errors.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace CGAL {
namespace Vibration_modes {

double zero_mode_threshold(const Mode_problem& p)
{
  // Gershgorin's bound on the largest eigenvalue of M^-1/2 H M^-1/2.
  Eigen::VectorXd row_sum = Eigen::VectorXd::Zero(p.H.rows());
  for(int k = 0; k < p.H.outerSize(); ++k)
    for(Eigen::SparseMatrix<double>::InnerIterator it(p.H, k); it; ++it)
      row_sum[it.row()] += std::abs(it.value()) / std::sqrt(p.mass[it.row()] * p.mass[it.col()]);
  // Rigid motions have eigenvalues of rounding size, about eps (2e-16) times the largest.
  // Gershgorin overestimates the largest where a mesh has tiny triangles (armadillo,
  // 43k vertices, unit area, k_b 1e-3: bound 5.7e11, lowest elastic modes 1 to 5), so the
  // threshold sits 1000x above rounding: 1e-13 of the bound.  A mode below it cannot be
  // told from a rigid motion in double precision.
  return 1e-13 * row_sum.maxCoeff();
}

int count_modes_below(const Mode_problem& p, double tau)
{
  return Model_reduction::count_eigenvalues_below(p.H, p.mass, tau);
}

Modes lowest_vibration_modes(const Mode_problem& p, int count, const Model_reduction::Eigensolver_options& options)
{
  p.check();
  const Eigen::Index room = p.H.rows() - p.kernel.cols();
  if(count < 1) throw Invalid_input("vibration modes: the number of modes must be at least 1 (got " + std::to_string(count) + ")");
  if(count > room)
    throw Invalid_input("vibration modes: " + std::to_string(count) + " modes asked for, but only " +
                        std::to_string(room) + " exist outside the " + std::to_string(p.kernel.cols()) +
                        " rigid motions");
  const int zero = count_modes_below(p, zero_mode_threshold(p));
  if(zero != p.kernel.cols())
    throw Invalid_input("vibration modes: the energy has " + std::to_string(zero) + " zero modes but " +
                        std::to_string(p.kernel.cols()) + " rigid motions" +
                        (zero > p.kernel.cols() ? std::string(": a mechanism moves without energy (a flat region without "
                                                              "bending stiffness, or a hinge), or modes are too soft to "
                                                              "tell from zero in double precision; add stiffness or pin it")
                                                : std::string(": the given kernel is not in the null space of H")));
  const Model_reduction::Eigenpairs pairs = Model_reduction::lowest_eigenpairs(p.H, p.mass, count, p.kernel, options);
  Modes modes;
  modes.vectors = p.expand(pairs.vectors.leftCols(count));
  modes.energies = pairs.values.head(count);
  modes.residuals = pairs.residuals.head(count);
  modes.kernel_dimension = int(p.kernel.cols());
  modes.complete_below = pairs.complete_below;
  modes.completeness = pairs.completeness;
  return modes;
}

} // namespace Vibration_modes
} // namespace CGAL
