// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_VIBRATION_MODES_LOWEST_VIBRATION_MODES_H
#define CGAL_VIBRATION_MODES_LOWEST_VIBRATION_MODES_H

/// \file lowest_vibration_modes.h
/// The lowest vibration modes after the kernel (SPEC 13.2), by the shared spectrum-slicing
/// eigensolver, with the kernel's dimension proved by an inertia count.

#include <CGAL/Vibration_modes/Mode_problem.h>
#include <CGAL/Vibration_modes/Modes.h>

namespace CGAL {
namespace Vibration_modes {

/// The `count` lowest pairs of `H u = lambda M u` outside `problem.kernel`.
/// Before solving, Sylvester's inertia of `H - tau M` must show exactly `kernel.cols()`
/// eigenvalues below `tau = 1e-13 lambda_max` (Gershgorin bound of `M^-1/2 H M^-1/2`): a
/// larger count means the energy has a mechanism (a motion that costs nothing and is not
/// rigid, e.g. a flat sheet without bending stiffness), whose modes would be meaningless.
/// \throws Invalid_input for `count < 1`, more modes than unknowns outside the kernel, or
///         a mechanism (the message gives both counts); Numerical_failure as the eigensolver.
Modes lowest_vibration_modes(const Mode_problem& problem, int count,
                             const Model_reduction::Eigensolver_options& options = {});

/// Eigenvalues of `H u = lambda M u` below `tau` (inertia), for checking kernels.
int count_modes_below(const Mode_problem& problem, double tau);

/// The `tau` of the kernel check above for this problem.
double zero_mode_threshold(const Mode_problem& problem);

} // namespace Vibration_modes
} // namespace CGAL

#endif
