// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Vibration_modes/compressed_modes.h>
#include <CGAL/Vibration_modes/errors.h>
#include <CGAL/Vibration_modes/lowest_vibration_modes.h>

#include <CGAL/Model_reduction/internal/One_blas_thread.h>

#include "constrained_group_lasso.h"
#include "free_unknowns.h"
#include "working_set.h"

#include <algorithm>
#include <random>
#include <cmath>
#include <functional>
#include <memory>
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

double support_fraction(const Mode_problem& p, const Eigen::VectorXd& u)
{
  Eigen::Index nonzero = 0;
  for(Eigen::Index v = 0; v < u.size(); v += p.group_size) nonzero += u.segment(v, p.group_size).squaredNorm() > 0;
  return double(nonzero) / double(u.size() / p.group_size);
}


// The state of one mode's ICCM, carried from one working set to the next.
struct Iccm_run
{
  Eigen::VectorXd c; // the unit iterate, over the current problem's unknowns
  double f = 0;      // its objective
  double step = 1;   // the M-norm of the last step
  int outer = 0, inner = 0;
  bool done = false;
};

// ICCM on `p` (the whole problem or a working set's) from run.c until it settles or
// `leave()` asks for another working set after a step.  Inexact steps while the iterate
// still moves: the convex problem of a plane that is about to change is solved to a tenth
// of the last step (at most 1e-2), down to the requested tolerance near the end.
void iccm(const Mode_problem& p, internal::Constrained_group_lasso& admm, double mu, double budget,
          const Compressed_mode_options& options, Iccm_run& run, const std::function<bool()>& leave,
          const std::function<void()>& report)
{
  for(run.done = false; !run.done && run.outer < options.max_outer_iterations;)
  {
    ++run.outer;
    const double tolerance = options.exact_convex_steps ? options.admm_tolerance : std::min(1e-2, 0.1 * run.step);
    // The budget is approached from the start's own |c|_{1,M}: the plane c^T M u = 1
    // meets the ball of radius beta only if beta max_v |c_v| >= 1, which a spread-out
    // start (an ordinary mode) may miss; a ball at 0.8 |c|_{1,M} keeps meeting it as long
    // as c is not flat (max_v |c_v| >= 1 / |c|_{1,M} always), and c shrinks with it.
    double level = budget;
    if(budget > 0)
    {
      level = std::max(budget, budget_continuation * mass_weighted_l1(p, run.c));
      admm.set_l1_budget(level);
    }
    run.inner += admm.solve_on_plane(run.c, options.max_inner_iterations, tolerance);
    const Eigen::VectorXd& u = admm.u();
    const double norm = admm.m_norm(u); // >= 1: u lies on the tangent plane c^T M u = 1
    const Eigen::VectorXd next = u / norm;
    const double f_next = compressed_objective(p, next, mu);
    run.step = admm.m_norm(next - run.c);
    run.done = admm.converged() && run.f - f_next <= options.objective_tolerance * std::abs(f_next) &&
               run.step <= options.step_tolerance && level == budget;
    admm.rescale(1 / norm);
    run.c = next;
    run.f = f_next;
    report();
    if(!run.done && leave()) return;
  }
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
  const int wanted = int(std::min<Eigen::Index>(count, room));
  Modes computed;
  if(options.ordinary_modes)
  {
    const Modes& given = *options.ordinary_modes;
    if(given.energies.size() < wanted || given.vectors.cols() != given.energies.size() ||
       (given.vectors.rows() != p.H.rows() && given.vectors.rows() != p.full_size))
      throw Invalid_input("compressed modes: the ordinary modes given hold " + std::to_string(given.energies.size()) +
                          " vectors of " + std::to_string(given.vectors.rows()) + " entries; " +
                          std::to_string(wanted) + " of " + std::to_string(internal::full_size_of(p)) +
                          " entries are needed");
  }
  else
    computed = lowest_vibration_modes(p, wanted, options.eigensolver);
  const Modes& ordinary = options.ordinary_modes ? *options.ordinary_modes : computed;
  const Eigen::Index known = std::min<Eigen::Index>(ordinary.energies.size(), wanted);
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
  // The fixed directions (admm.fixed()): the kernel (M-orthonormal) and then each mode found.
  admm.set_fixed(options.orthogonal_to_kernel ? internal::m_orthonormal(p.kernel, p.mass)
                                              : Eigen::MatrixXd(p.H.rows(), 0));
  const bool working_sets = options.working_sets && budget == 0 && mu > 0;
  const std::size_t groups = std::size_t(p.H.rows() / p.group_size);
  Modes modes;
  modes.kernel_dimension = int(p.kernel.cols());
  modes.sparsity_weight = mu;
  Eigen::MatrixXd found(p.H.rows(), count);
  modes.energies.resize(count), modes.objectives.resize(count), modes.l1_norms.resize(count);
  modes.support_fractions.resize(count);
  for(int i = 0; i < count; ++i)
  {
    // Start from the i-th ordinary mode, made orthogonal to the modes found so far.
    Iccm_run run;
    run.c = admm.project_out_fixed(start.col(i));
    if(!(admm.m_norm(run.c) > 1e-3)) run.c = admm.project_out_fixed(start.rightCols(count - i).rowwise().sum());
    run.c /= admm.m_norm(run.c);
    run.f = compressed_objective(p, run.c, mu);
    admm.start(run.c, eigenvalue(i));
    // The working set (all vertices at first), its problem and ADMM.
    internal::Group_set set(groups, 1), next_set;
    std::unique_ptr<internal::Restricted_problem> restricted;
    std::unique_ptr<internal::Constrained_group_lasso> restricted_admm;
    auto z_over_all = [&] { return restricted ? restricted->expand(restricted_admm->z(), p.H.rows()) : admm.z(); };
    // The working set follows the support: it shrinks to the support and two rings of H's
    // pattern once that fills less than half of it, and grows to the support and three
    // rings (room to grow: each change costs a factorisation) when the support and one
    // ring leave it; after the first-order conditions have failed outside a set, it only
    // grows.
    bool may_shrink = working_sets;
    auto leave = [&] {
      if(!working_sets) return false;
      const internal::Group_set support = internal::support_of(p, z_over_all());
      if(internal::size_of(support) == 0) return false; // no set from an empty sparse iterate
      internal::Group_set near = support;
      internal::grow(p, near, 1);
      bool outside = false;
      for(std::size_t v = 0; v < groups && !outside; ++v) outside = near[v] && !set[v];
      next_set = near;
      internal::grow(p, next_set, outside ? 2 : 1);
      if(outside)
      {
        for(std::size_t v = 0; v < groups; ++v) next_set[v] |= set[v] && !may_shrink;
        return true;
      }
      return may_shrink && double(internal::size_of(next_set)) < 0.5 * double(internal::size_of(set));
    };
    auto report = [&] {
      if(options.progress &&
         !options.progress({i, count, run.outer, run.inner, run.f, support_fraction(p, z_over_all())}))
        throw Cancelled("compressed modes: cancelled at mode " + std::to_string(i + 1) + " of " + std::to_string(count));
    };
    for(;;)
    {
      if(restricted)
        iccm(restricted->problem, *restricted_admm, mu, budget, options, run, leave, report);
      else
        iccm(p, admm, mu, budget, options, run, leave, report);
      if(!run.done && run.outer >= options.max_outer_iterations) break;
      if(run.done)
      {
        if(!restricted) break;
        // The whole problem's first-order conditions outside the set; where they fail,
        // those vertices and their two rings join it.
        const Eigen::VectorXd sparse = restricted_admm->feasible_sparse_iterate();
        const std::vector<Eigen::Index> violated = internal::violations_outside(
            p, admm.fixed(), restricted->expand(sparse.size() > 0 ? sparse : run.c, p.H.rows()), mu, set, 1e-3);
        if(violated.empty()) break;
        internal::Group_set joining(groups, 0);
        for(Eigen::Index v : violated) joining[std::size_t(v)] = 1;
        internal::grow(p, joining, 2);
        next_set = set;
        for(std::size_t v = 0; v < groups; ++v) next_set[v] |= joining[v];
        may_shrink = false;
      }
      // ICCM goes on in the next working set from the current iterate restricted to it, the
      // ADMM warm-started from the current sparse iterate and dual.
      auto over_all = [&](const Eigen::VectorXd& x) { return restricted ? restricted->expand(x, p.H.rows()) : x; };
      const Eigen::VectorXd c_over_all = over_all(run.c);
      internal::Constrained_group_lasso& before = restricted ? *restricted_admm : admm;
      const Eigen::VectorXd z_over_all_before = over_all(before.z()), w_over_all = over_all(before.w());
      set.swap(next_set);
      auto next = std::make_unique<internal::Restricted_problem>(p, set);
      auto next_admm = std::make_unique<internal::Constrained_group_lasso>(next->problem, mu, options.admm_tolerance);
      next_admm->set_fixed(internal::m_orthonormal(next->restrict(admm.fixed()), next->problem.mass));
      run.c = next_admm->project_out_fixed(next->restrict(c_over_all));
      run.c /= next_admm->m_norm(run.c);
      run.f = compressed_objective(next->problem, run.c, mu);
      next_admm->start(run.c, eigenvalue(i), before.rho());
      next_admm->set_state(next->restrict(z_over_all_before), next->restrict(w_over_all), before.rho());
      restricted = std::move(next);
      restricted_admm = std::move(next_admm);
    }
    // The mode: the sparse iterate (exact zeros) if it is feasible on its support.
    internal::Constrained_group_lasso& last = restricted ? *restricted_admm : admm;
    Eigen::VectorXd c = run.c;
    const Eigen::VectorXd sparse = last.feasible_sparse_iterate();
    if(sparse.size() > 0 && last.m_norm(last.project_out_fixed(sparse) - sparse) < 1e-10) c = sparse;
    if(restricted) c = restricted->expand(c, p.H.rows());
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
    modes.outer_iterations.push_back(run.outer);
    modes.inner_iterations.push_back(run.inner);
    modes.converged.push_back(run.done ? 1 : 0);
  }
  modes.vectors = p.expand(found);
  return modes;
}

} // namespace Vibration_modes
} // namespace CGAL
