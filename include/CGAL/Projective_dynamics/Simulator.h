// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PROJECTIVE_DYNAMICS_SIMULATOR_H
#define CGAL_PROJECTIVE_DYNAMICS_SIMULATOR_H

/// \file Simulator.h
/// Full-space Projective Dynamics (Bouaziz et al. 2014; SPEC 12): implicit Euler as the
/// minimisation of
/// \f[ g(q) = \frac{1}{2h^2} |q - s|_M^2 + \sum_i \frac{w_i}{2} |S_i q - p_i|^2,
///     \quad s = q_t + h v_t + h^2 M^{-1} f_{ext}, \f]
/// by alternating a local step (each `p_i` the closest point of `S_i q` in `C_i`, elements in
/// parallel) and a global step (one constant SPD matrix `M/h^2 + S^T W S`, factored once by
/// CHOLMOD, solving x, y and z together).  A fixed number of iterations per step;
/// `v_{t+1} = (q_{t+1} - q_t) / h`.  Any time step is stable.
///
/// Pinned and grabbed vertices are held at their targets (removed from the unknowns; changing
/// which vertices are held refactors, moving the targets does not).  Floor planes and spheres
/// push vertices out before the iterations (the prediction `s`) and after them (the result),
/// then cancel the velocity into the obstacle and scale the tangential velocity by
/// `1 - friction`.  There is no self-collision.

#include <CGAL/Projective_dynamics/Elastic_model.h>
#include <CGAL/Projective_dynamics/errors.h>
#include <CGAL/Projective_dynamics/named_function_parameters.h>

#include <Eigen/Core>

#include <functional>
#include <memory>
#include <vector>

namespace CGAL {
namespace Projective_dynamics {

/// The simulator's settings (the named parameters of `Simulator`'s constructor).
struct Simulator_options
{
  double time_step = 1.0 / 30;               ///< `h > 0`, seconds
  int iterations = 10;                       ///< local/global iterations per step, at least 1
  Eigen::Vector3d gravity{0, 0, -9.81};      ///< an acceleration (z up)
  int threads = 0;                           ///< threads of the local steps; 0: all cores
  double friction = 0.5;                     ///< obstacles' friction factor in `[0, 1]`
};

/// Wall-clock seconds of the last step, and of the last factorisation.
struct Step_timings
{
  double local = 0;  ///< projections
  double global = 0; ///< right-hand sides and solves
  double total = 0;
  double factorization = 0;
};

class Simulator
{
public:
  /// Starts at rest in the model's rest positions, velocities zero.
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{time_step} `h > 0`; `double`; default 1/30 \cgalParamNEnd
  ///   \cgalParamNBegin{number_of_iterations} per step, at least 1; `int`; default 10 \cgalParamNEnd
  ///   \cgalParamNBegin{gravity} acceleration; `Eigen::Vector3d`; default `(0, 0, -9.81)` \cgalParamNEnd
  ///   \cgalParamNBegin{number_of_threads} local-step threads, 0 for all cores; `int`; default 0 \cgalParamNEnd
  ///   \cgalParamNBegin{friction} of the obstacles, in `[0, 1]`; `double`; default 0.5 \cgalParamNEnd
  /// \cgalNamedParamsEnd
  /// \throws Invalid_input for an option out of range.  The matrix is factored on the first step.
  template <class NamedParameters = parameters::Default_named_parameters>
  explicit Simulator(Elastic_model model, const NamedParameters& np = parameters::default_values())
    : Simulator(std::move(model), options_of(np))
  {}
  Simulator(Elastic_model model, const Simulator_options& options);
  ~Simulator();
  Simulator(Simulator&&) noexcept;
  Simulator& operator=(Simulator&&) noexcept;

  template <class NamedParameters>
  static Simulator_options options_of(const NamedParameters& np)
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    Simulator_options o;
    o.time_step = choose_parameter(get_parameter(np, internal_np::time_step), o.time_step);
    o.iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), o.iterations);
    o.gravity = choose_parameter(get_parameter(np, internal_np::gravity), o.gravity);
    o.threads = choose_parameter(get_parameter(np, internal_np::number_of_threads), o.threads);
    o.friction = choose_parameter(get_parameter(np, internal_np::friction), o.friction);
    return o;
  }

  /// One time step.  `after_iteration(k, q)`, if given, sees the positions after the global
  /// step of iteration `k` (before obstacles correct them).
  /// \throws Invalid_input for a free vertex of zero mass; Numerical_failure if the matrix is
  ///         not positive definite or the positions stop being finite (an absurd force): the
  ///         state before the step is kept.
  void step(const std::function<void(int, const Positions&)>& after_iteration = {});

  const Positions& positions() const;
  const Positions& velocities() const;
  /// \throws Invalid_input for a wrong size or a non-finite entry (naming the vertex).
  void set_positions(const Positions& q);
  void set_velocities(const Positions& v);
  /// Per-vertex forces added to gravity from now on (zero at the start).
  void set_external_forces(const Positions& f);

  /// Holds `vertices` where they are now (replacing earlier pins).
  /// \throws Invalid_input for an index out of range, naming it.
  void set_pinned_vertices(const std::vector<int>& vertices);
  /// Holds `vertices` at `targets` (one row each, replacing earlier grabs), which
  /// `move_grabbed` moves.  A grabbed vertex that is also pinned stays pinned.
  /// \throws Invalid_input as above, or for a wrong number of targets or a non-finite one.
  void grab(const std::vector<int>& vertices, const Positions& targets);
  void move_grabbed(const Positions& targets);
  void release_grabbed();

  /// A half-space obstacle: the side of `normal` from `point` is free.
  void add_floor(const Eigen::Vector3d& point, const Eigen::Vector3d& normal);
  /// A solid ball obstacle.  \throws Invalid_input for a radius that is not positive.
  void add_sphere(const Eigen::Vector3d& center, double radius);
  void clear_obstacles();

  /// A new time step or a group's new stiffness (`Elastic_model::set_stiffness`): the matrix
  /// is refactored on the next step.  \throws Invalid_input for a value out of range.
  void set_time_step(double h);
  void set_stiffness(int group, double stiffness);
  /// These take effect on the next step without refactoring.
  void set_iterations(int iterations);
  void set_friction(double friction);

  const Simulator_options& options() const;
  const Elastic_model& model() const;
  const Step_timings& last_step_timings() const;
  /// How many times the matrix was factored (a stiffness or time-step change adds one).
  int number_of_factorizations() const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace Projective_dynamics
} // namespace CGAL

#endif
