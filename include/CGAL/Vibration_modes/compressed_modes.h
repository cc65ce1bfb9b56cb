// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_VIBRATION_MODES_COMPRESSED_MODES_H
#define CGAL_VIBRATION_MODES_COMPRESSED_MODES_H

/// \file compressed_modes.h
/// Compressed vibration modes (SPEC 13.3): mode `i` minimises
/// `u^T H u + mu |u|_{1,M}` on `u^T M u = 1`, `M`-orthogonal to the kernel and to the
/// earlier modes, with `|u|_{1,M} = sum_v m_v |u_v|` over vertices (the Euclidean length
/// of a vertex's displacement: rotation invariant).  Computed one after the other by
/// iterative convexification (ICCM: the sphere replaced by its tangent plane at the
/// current iterate), each convex problem by ADMM with `2H + rho M` factored once per rho.

#include <CGAL/Vibration_modes/Mode_problem.h>
#include <CGAL/Vibration_modes/Modes.h>

#include <functional>
#include <limits>

namespace CGAL {
namespace Vibration_modes {

/// Reported after every outer iteration.
struct Compressed_mode_progress
{
  int mode = 0, count = 0;   ///< mode being computed (0-based) and modes wanted
  int outer_iteration = 0;   ///< ICCM iterations of this mode so far
  int inner_iterations = 0;  ///< ADMM iterations of this mode so far
  double objective = 0;      ///< at the current unit iterate
  double support_fraction = 1; ///< vertices where the sparse iterate is nonzero, over all
};

/// Where ICCM starts each mode (the problem is not convex: the start picks the local minimum).
enum class Compressed_mode_start
{
  lowest_modes, ///< the i-th ordinary mode outside the kernel (with mu = 0, the answer itself)
  random        ///< a random vector (seeded by `eigensolver.seed`): not rotation invariant
};

struct Compressed_mode_options
{
  /// `mu >= 0`, in units of `H`'s eigenvalues per `|u|_{1,M}` (0: the ordinary modes).
  double sparsity_weight = 0;
  /// The L1-constrained variant (when finite): each mode minimises `u^T H u` with
  /// `|u|_{1,M} <= l1_budget` (> 0; `sparsity_weight` must then be 0).  A unit vector has
  /// `|u|_{1,M} <= sqrt(total mass)` (Cauchy-Schwarz), so budgets from that value up give the
  /// ordinary modes, and smaller ones more local modes; the objective reported is the energy.
  double l1_budget = std::numeric_limits<double>::infinity();
  /// ICCM stops when the objective decreased by less than this relative amount and the
  /// unit iterate moved by less than `step_tolerance` (in the M-norm) in one iteration.
  double objective_tolerance = 1e-7;
  double step_tolerance = 1e-4;
  int max_outer_iterations = 200;
  /// ADMM: relative primal and dual residual tolerance of each convex problem, and the
  /// most iterations it gets per ICCM step (it is warm-started from the previous one).
  double admm_tolerance = 1e-6;
  int max_inner_iterations = 500;
  /// Solve every convex step to `admm_tolerance` (ICCM as derived: the objective never
  /// increases).  By default a step whose plane is about to move is solved to a tenth of
  /// the last step's length (at most 1e-2), and to `admm_tolerance` once the iterate
  /// settles: the same modes with about 5x fewer ADMM iterations (4 modes of a 162-vertex
  /// shell at four sparsity weights: objectives equal to 5 digits).
  bool exact_convex_steps = false;
  /// ICCM on working sets: once a mode's support, grown by two rings of `H`'s pattern,
  /// fills less than half of the vertices, its convex problems are solved on those
  /// vertices only (a smaller factorisation, and earlier modes elsewhere drop out of the
  /// constraints); the set shrinks again with the support, and grows to the support and
  /// three rings when the support reaches its edge (the ADMM warm-started across sets).
  /// A set's answer is the whole problem's once the first-order conditions also hold
  /// outside it (else the vertices where they fail join it).  Only with a sparsity weight
  /// (not a budget).  Fertility as a shell, 10 modes at mu 64 lambda_10 (supports 13-33 %):
  /// 32.8 s against 70.9 s on the whole mesh, objective sum 7998.85 against 7997.65 (the
  /// same local minima but two, within 0.15 %).
  bool working_sets = true;
  /// The problem's ordinary modes (`lowest_vibration_modes`), if the caller has them: the
  /// starting vectors and rho's scale are taken from them instead of being computed again.
  /// They must be at least `min(count, modes outside the kernel)` and belong to `problem`.
  const Modes* ordinary_modes = nullptr;
  /// Modes M-orthogonal to the kernel (the rigid motions of a shell), as SPEC 13.3 asks.
  /// False gives the problem of compressed manifold modes (Neumann et al.), where the
  /// constants of a Laplacian may take part in a mode.
  bool orthogonal_to_kernel = true;
  Compressed_mode_start start = Compressed_mode_start::lowest_modes;
  /// The eigensolver giving the starting vectors (the ordinary modes).
  Model_reduction::Eigensolver_options eigensolver;
  /// Called after every ICCM iteration; return false to cancel (throws `Cancelled`).
  std::function<bool(const Compressed_mode_progress&)> progress;
};

/// `count` compressed modes of `problem`, started from its ordinary modes.  Needs the
/// problem's ordinary modes (computed unless given in `options.ordinary_modes`).
/// \throws Invalid_input for `mu < 0` or not finite, an L1 budget that is not finite, is
///         <= 0 while asked for, or comes with `mu > 0`, `count < 1`, or more modes than the
///         space outside the kernel holds; Cancelled when `progress` returns false;
///         Numerical_failure if a factorisation fails or no unit vector of the budget meets
///         a mode's constraints (the budget is too small for it).
Modes compressed_modes(const Mode_problem& problem, int count, const Compressed_mode_options& options = {});

/// The objective `u^T H u + mu sum_v m_v |u_v|` of a vector over the free unknowns.
double compressed_objective(const Mode_problem& problem, const Eigen::VectorXd& u, double mu);

/// `sum_v m_v |u_v|` over the vertices (groups) of the free unknowns.
double mass_weighted_l1(const Mode_problem& problem, const Eigen::VectorXd& u);

} // namespace Vibration_modes
} // namespace CGAL

#endif
