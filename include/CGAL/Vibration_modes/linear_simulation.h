// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_VIBRATION_MODES_LINEAR_SIMULATION_H
#define CGAL_VIBRATION_MODES_LINEAR_SIMULATION_H

/// \file linear_simulation.h
/// Linearised elastodynamics about the rest shape (SPEC 13, "Uses"):
/// \f[ M \ddot u + (\alpha M + \beta H)\dot u + H u = f(t), \f]
/// `u` the displacement of the free unknowns of a `Mode_problem` (pinned vertices stay at
/// zero), integrated by Newmark's average-acceleration rule (the trapezoidal rule: implicit,
/// unconditionally stable, second order, and without damping it conserves the energy
/// `v^T M v / 2 + u^T H u / 2` exactly).
///
/// Two solvers of the same equation: the full one factors `M + h/2 C + h^2/4 H` once by
/// CHOLMOD (the shared `Sparse_spd_solver`); the reduced one writes `u = B q` with `B` the
/// kernel of `H` (the rigid motions, optional) beside `k` modes, and steps the `k x k`
/// system `B^T M B`, `B^T H B`.  `relative_trajectory_error` measures one against the other.
///
/// The integrator's period error (derived): for one mode `H phi = lambda M phi` started at
/// `u = phi`, `v = 0` without damping or force, the rule gives exactly
/// `u_n = cos(n h Omega) phi` with `tan(h Omega / 2) = h sqrt(lambda) / 2`: the amplitude is
/// kept and the period grows by the factor `omega / Omega = 1 + (h omega)^2 / 12 + O(h^4)`.

#include <CGAL/Vibration_modes/Mode_problem.h>
#include <CGAL/Vibration_modes/Modes.h>

#include <Eigen/Core>

#include <functional>

namespace CGAL {
namespace Vibration_modes {

struct Linear_simulation_options
{
  /// `h > 0`.
  double time_step = 1e-2;
  /// Steps to take (>= 0); the trajectory holds `steps / output_every + 1` frames, the first at t = 0.
  int steps = 100;
  /// Keep every `output_every`-th state (>= 1).
  int output_every = 1;
  /// Rayleigh damping `C = alpha M + beta H` (both >= 0; 0 and 0: undamped).
  double rayleigh_mass = 0, rayleigh_stiffness = 0;
  /// Initial displacement and velocity over all `full_size` unknowns (or over the free ones);
  /// empty: zero.  Entries at pinned unknowns are ignored.
  Eigen::VectorXd initial_displacement, initial_velocity;
  /// A constant external force (nodal forces, same layout); empty: none.
  Eigen::VectorXd force;
  /// An optional force added at time `t`: the callback fills `f` (all unknowns, zeroed before
  /// the call).  Costs an `n x k` product per step in the reduced simulation.
  std::function<void(double t, Eigen::VectorXd& f)> force_at_time;
};

/// The states kept by a simulation.
struct Linear_trajectory
{
  /// Time of each frame.
  Eigen::VectorXd times;
  /// Displacement of each frame over all `full_size` unknowns (zero at pinned ones), one column per frame.
  Eigen::MatrixXd displacements;
  /// `v^T M v / 2 + u^T H u / 2` of each frame.
  Eigen::VectorXd energies;
};

/// The linear simulation at full resolution.
/// \throws Invalid_input for a bad option (time step not finite and positive, negative
///         steps or damping, a vector of the wrong size or with NaN), with the reason;
///         Numerical_failure if the step matrix cannot be factored.
Linear_trajectory full_linear_simulation(const Mode_problem& problem, const Linear_simulation_options& options);

/// The linear simulation in the span of `modes` (columns over all or over the free unknowns,
/// e.g. `Modes::vectors`), with the kernel of `H` added to the basis if `with_kernel` (a free
/// body then translates and turns under a net force as the full simulation does).
/// Initial states are `M`-orthogonally projected onto the basis.
/// \throws as `full_linear_simulation`, and Invalid_input for modes of the wrong height, with
///         NaN, or linearly dependent (with the kernel).
Linear_trajectory reduced_linear_simulation(const Mode_problem& problem, const Eigen::MatrixXd& modes,
                                            const Linear_simulation_options& options, bool with_kernel = true);

/// The same on the first `k` of `modes`.
/// \throws Invalid_input for `k < 1` or more than the modes computed.
Linear_trajectory reduced_linear_simulation(const Mode_problem& problem, const Modes& modes, int k,
                                            const Linear_simulation_options& options, bool with_kernel = true);

/// `sqrt(sum_t |u_t - r_t|_M^2 / sum_t |r_t|_M^2)` over the frames of two trajectories with the
/// same frames (`reference` e.g. the full simulation).
/// \throws Invalid_input for trajectories of different shapes or a reference that is zero.
double relative_trajectory_error(const Mode_problem& problem, const Linear_trajectory& approximation,
                                 const Linear_trajectory& reference);

} // namespace Vibration_modes
} // namespace CGAL

#endif
