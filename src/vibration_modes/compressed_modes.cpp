// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Vibration_modes/compressed_modes.h>
#include <CGAL/Vibration_modes/errors.h>
#include <CGAL/Vibration_modes/lowest_vibration_modes.h>

#include <CGAL/Model_reduction/internal/One_blas_thread.h>

#include "constrained_group_lasso.h"

#include <algorithm>
#include <random>
#include <cmath>
#include <string>

namespace CGAL {
namespace Vibration_modes {

namespace {

// Each ICCM step of the L1-constrained variant lowers the ball to this fraction of the
// current iterate's |u|_{1,M}, until the budget is reached.
constexpr double budget_continuation = 0.8;

// The free part of a vector given over the free or over all unknowns.
Eigen::VectorXd free_part(const Mode_problem& p, const Eigen::VectorXd& u)
{
  if(u.size() == p.H.rows()) return u;
  if(!p.free_unknowns.empty() && u.size() == p.full_size)
  {
    Eigen::VectorXd f(p.H.rows());
    for(std::size_t i = 0; i < p.free_unknowns.size(); ++i) f[Eigen::Index(i)] = u[p.free_unknowns[i]];
    return f;
  }
  throw Invalid_input("compressed modes: a vector of " + std::to_string(u.size()) + " entries for " +
                      std::to_string(p.H.rows()) + " unknowns");
}

// Columns made M-orthonormal (modified Gram-Schmidt twice); columns that are dependent on
// the earlier ones are dropped.
Eigen::MatrixXd m_orthonormal(const Eigen::MatrixXd& X, const Eigen::VectorXd& mass)
{
  Eigen::MatrixXd Q(X.rows(), 0);
  for(Eigen::Index j = 0; j < X.cols(); ++j)
  {
    Eigen::VectorXd v = X.col(j);
    const double before = std::sqrt(v.dot(mass.cwiseProduct(v)));
    for(int pass = 0; pass < 2; ++pass)
      for(Eigen::Index i = 0; i < Q.cols(); ++i) v -= Q.col(i).dot(mass.cwiseProduct(v)) * Q.col(i);
    const double after = std::sqrt(v.dot(mass.cwiseProduct(v)));
    if(!(after > 1e-10 * before)) continue;
    Q.conservativeResize(Eigen::NoChange, Q.cols() + 1);
    Q.col(Q.cols() - 1) = v / after;
  }
  return Q;
}

double support_fraction(const Mode_problem& p, const Eigen::VectorXd& u)
{
  Eigen::Index nonzero = 0;
  for(Eigen::Index v = 0; v < u.size(); v += p.group_size) nonzero += u.segment(v, p.group_size).squaredNorm() > 0;
  return double(nonzero) / double(u.size() / p.group_size);
}

} // namespace

double mass_weighted_l1(const Mode_problem& p, const Eigen::VectorXd& u_in)
{
  const Eigen::VectorXd u = free_part(p, u_in);
  double sum = 0;
  for(Eigen::Index g = 0; g < u.size(); g += p.group_size) sum += p.mass[g] * u.segment(g, p.group_size).norm();
  return sum;
}

double compressed_objective(const Mode_problem& p, const Eigen::VectorXd& u_in, double mu)
{
  const Eigen::VectorXd u = free_part(p, u_in);
  return u.dot(p.H * u) + mu * mass_weighted_l1(p, u);
}

Modes compressed_modes(const Mode_problem& p, int count, const Compressed_mode_options& options)
{
  const double mu = options.sparsity_weight;
  const double budget = std::isinf(options.l1_budget) && options.l1_budget > 0 ? 0 : options.l1_budget; // 0: none
  if(!(mu >= 0) || !std::isfinite(mu))
    throw Invalid_input("compressed modes: the sparsity weight mu must be finite and >= 0 (got " + std::to_string(mu) + ")");
  if(!(options.l1_budget > 0))
    throw Invalid_input("compressed modes: the L1 budget must be > 0 (got " + std::to_string(options.l1_budget) + ")");
  if(budget > 0 && mu > 0)
    throw Invalid_input("compressed modes: give either a sparsity weight mu or an L1 budget, not both");
  p.check();
  if(count > p.H.rows() - (options.orthogonal_to_kernel ? p.kernel.cols() : 0))
    throw Invalid_input("compressed modes: " + std::to_string(count) + " modes asked for, but only " +
                        std::to_string(p.H.rows() - (options.orthogonal_to_kernel ? p.kernel.cols() : 0)) +
                        " exist" + (options.orthogonal_to_kernel ? " outside the kernel" : ""));
  // The ordinary modes outside the kernel (their check proves the kernel by inertia) start
  // ICCM; a kernel vector never does, even where modes may use it: the constants of a
  // Laplacian are a stationary point of the free problem (one sign everywhere), so ICCM
  // started there stays there (fertility's scalar problem, 10 modes: objective 17.74 from
  // the constants, 17.23 without them).
  const Eigen::Index room = p.H.rows() - p.kernel.cols();
  const Modes ordinary = lowest_vibration_modes(p, int(std::min<Eigen::Index>(count, room)), options.eigensolver);
  const Eigen::Index known = ordinary.energies.size();
  Eigen::MatrixXd start(p.H.rows(), count);
  std::mt19937_64 rng(options.eigensolver.seed);
  std::normal_distribution<double> normal;
  for(int i = 0; i < count; ++i)
    if(options.start == Compressed_mode_start::random || i >= known)
      for(Eigen::Index j = 0; j < start.rows(); ++j) start(j, i) = normal(rng);
    else
      start.col(i) = free_part(p, ordinary.vectors.col(i));
  // The ADMM's rho is set from the mode's eigenvalue (Constrained_group_lasso::start).
  auto eigenvalue = [&](int i) { return ordinary.energies[std::min<Eigen::Index>(i, known - 1)]; };

  // Thousands of single-vector triangular solves: OpenBLAS's threads would spend the time
  // waking and yielding (fertility as a shell, 3 modes: 21 % of the time in the kernel's
  // scheduler).
  Model_reduction::internal::One_blas_thread one_blas_thread;
  internal::Constrained_group_lasso admm(p, mu, options.admm_tolerance);
  if(budget > 0) admm.set_l1_budget(budget);
  if(options.orthogonal_to_kernel) admm.set_fixed(m_orthonormal(p.kernel, p.mass));
  Modes modes;
  modes.kernel_dimension = int(p.kernel.cols());
  modes.sparsity_weight = mu;
  Eigen::MatrixXd found(p.H.rows(), count);
  modes.energies.resize(count), modes.objectives.resize(count), modes.l1_norms.resize(count);
  modes.support_fractions.resize(count);
  for(int i = 0; i < count; ++i)
  {
    // Start from the i-th ordinary mode, made orthogonal to the modes found so far.
    Eigen::VectorXd c = admm.project_out_fixed(start.col(i));
    if(!(admm.m_norm(c) > 1e-3)) c = admm.project_out_fixed(start.rightCols(count - i).rowwise().sum());
    c /= admm.m_norm(c);
    admm.start(c, eigenvalue(i));
    double f = compressed_objective(p, c, mu);
    int outer = 0, inner = 0;
    // Inexact steps while the iterate still moves: the convex problem of a plane that is
    // about to change is solved to a tenth of the last step (at most 1e-2), down to the
    // requested tolerance near the end.
    double step = 1;
    for(bool done = false; !done && outer < options.max_outer_iterations;)
    {
      ++outer;
      const double tolerance = options.exact_convex_steps ? options.admm_tolerance : std::min(1e-2, 0.1 * step);
      // The budget is approached from the start's own |c|_{1,M}: the plane c^T M u = 1
      // meets the ball of radius beta only if beta max_v |c_v| >= 1, which a spread-out
      // start (an ordinary mode) may miss; a ball at 0.8 |c|_{1,M} keeps meeting it as long
      // as c is not flat (max_v |c_v| >= 1 / |c|_{1,M} always), and c shrinks with it.
      double level = budget;
      if(budget > 0)
      {
        level = std::max(budget, budget_continuation * mass_weighted_l1(p, c));
        admm.set_l1_budget(level);
      }
      inner += admm.solve_on_plane(c, options.max_inner_iterations, tolerance);
      const Eigen::VectorXd& u = admm.u();
      const double norm = admm.m_norm(u); // >= 1: u lies on the tangent plane c^T M u = 1
      const Eigen::VectorXd next = u / norm;
      const double f_next = compressed_objective(p, next, mu);
      step = admm.m_norm(next - c);
      done = admm.converged() && f - f_next <= options.objective_tolerance * std::abs(f_next) &&
             step <= options.step_tolerance && level == budget;
      admm.rescale(1 / norm);
      c = next;
      f = f_next;
      if(options.progress && !options.progress({i, count, outer, inner, f, support_fraction(p, admm.z())}))
        throw Cancelled("compressed modes: cancelled at mode " + std::to_string(i + 1) + " of " + std::to_string(count));
    }
    // The mode: the sparse iterate (exact zeros) if it is feasible on its support.
    const Eigen::VectorXd sparse = admm.feasible_sparse_iterate();
    if(sparse.size() > 0 && admm.m_norm(admm.project_out_fixed(sparse) - sparse) < 1e-10) c = sparse;
    // The budget holds up to the ADMM's tolerance (the unit iterate is the ball's point
    // rescaled by its M-norm, 1 within the residuals); far beyond it, the plane never met
    // the ball: no unit vector within the budget satisfies this mode's constraints.
    if(budget > 0 && !(mass_weighted_l1(p, c) <= budget * (1 + 1e-3)))
      throw Numerical_failure("compressed modes: the L1 budget " + std::to_string(budget) + " is too small for mode " +
                              std::to_string(i + 1) + " (its best unit vector has |u|_{1,M} = " +
                              std::to_string(mass_weighted_l1(p, c)) + ")");
    found.col(i) = c;
    admm.add_fixed(c);
    modes.energies[i] = c.dot(p.H * c);
    modes.objectives[i] = compressed_objective(p, c, mu);
    modes.l1_norms[i] = mass_weighted_l1(p, c);
    modes.support_fractions[i] = support_fraction(p, c);
    modes.outer_iterations.push_back(outer);
    modes.inner_iterations.push_back(inner);
  }
  modes.vectors = p.expand(found);
  return modes;
}

} // namespace Vibration_modes
} // namespace CGAL
