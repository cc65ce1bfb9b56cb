// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The penalty decomposition of SPEC 14: with Y standing in for the jumps J X,
//   min |A X - P|^2 + beta |J X - Y|^2 + lambda #{rows r: Y_r != 0},
// alternating the X-step (a banded SPD solve of (A^T A + beta J^T J) X = A^T P + beta J^T Y)
// and the Y-step (keep row r of J X iff beta |(J X)_r|^2 > lambda: a group hard threshold,
// one group per knot over all D coordinates) while beta grows, until the kept rows settle;
// then a removal pass over the kept knots.
//
// Continuation in lambda.  Run once at the target lambda from a cold start, the threshold
// starts at the largest jump of the full fit; on dense candidates over smooth data the
// jumps are spread over many candidates, each below it, the first X-step smooths them all
// further, and nothing is ever kept.  So lambda climbs a geometric schedule from far below the
// target (where the threshold is below nearly every jump and the fit stays the full
// least-squares one) up to it; each stage works on the knots the previous stage kept, started
// from its least-squares fit on them.  Removing a knot concentrates its neighbours' jumps (the
// least-squares fit on fewer knots must bend at them), so at the next, larger lambda the
// survivors are compared with the threshold at their grown size: the same mechanism that makes
// greedy removal work, with the penalty decomposition deciding each stage.  Stages only remove
// knots, so the knot sets are nested and later stages are cheaper than the first.

#include <CGAL/Spline_approximation/internal/spline_numerics.h>

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace Spline_approximation {
namespace internal {

namespace {

// One stage: the penalty decomposition at `lambda` on the candidates of `p`, from the full
// least-squares fit on them, finished by the removal pass.
Spline_fit penalty_decomposition_stage(const Problem& p, double lambda)
{
  const Eigen::MatrixXd& P = *p.samples;
  const int k = p.degree;
  const Eigen::Index m = p.candidates.size();
  std::vector<std::size_t> all(static_cast<std::size_t>(m));
  for(std::size_t i = 0; i < all.size(); ++i) all[i] = i;
  // Without a penalty keeping every knot is optimal: the squared error never grows with the knot set.
  if(lambda == 0 || m == 0) return finish(p, all, lambda);

  const Basis basis = make_basis(p.candidates, k, p.closed);
  const Band_rows A = design_rows(basis, p.t), J = jump_rows(basis);
  const Eigen::Index n_ctrl = basis.controls;
  Spd_matrix AtA(n_ctrl, k + 1, p.closed), JtJ(n_ctrl, k + 1, p.closed);
  AtA.add_gram(A, 1.0);
  JtJ.add_gram(J, 1.0);
  Eigen::MatrixXd AtP = Eigen::MatrixXd::Zero(n_ctrl, P.cols());
  A.add_transpose_times(P, 1.0, AtP);
  // Both beta ends are relative to A^T A (J's rows have unit norm): at 1e-6 the first solve
  // is a barely smoothed least-squares fit (and definite even where the candidates outnumber
  // the samples); at 1e10, J X is within 1e-10 of Y and no threshold decision can change.
  const double scale = AtA.max_diagonal();
  auto solve = [&](double beta, const Eigen::MatrixXd& Y) {
    Spd_matrix M = AtA.plus(JtJ, beta);
    if(!M.factor(1e-15)) throw Numerical_failure("penalty decomposition: A^T A + beta J^T J is not positive definite");
    Eigen::MatrixXd rhs = AtP;
    J.add_transpose_times(Y, beta, rhs);
    return std::make_pair(std::move(M), M.solve(rhs));
  };
  Eigen::MatrixXd Y = Eigen::MatrixXd::Zero(m, P.cols());
  double beta = 1e-6 * scale;
  Eigen::MatrixXd X = solve(beta, Y).second;
  Eigen::VectorXd z2 = J.times(X).rowwise().squaredNorm();
  const double z2_max = z2.maxCoeff();
  if(!(z2_max > 0)) return finish(p, {}, lambda); // the data is one polynomial piece
  // Start where the threshold lambda / beta equals the largest jump: nothing kept yet.
  beta = std::max(beta, lambda / z2_max);
  std::vector<char> kept(static_cast<std::size_t>(m), 0);
  int settled = 0;
  for(; beta <= 1e10 * scale; beta *= 2) {
    Spd_matrix M = AtA.plus(JtJ, beta);
    if(!M.factor(1e-15)) throw Numerical_failure("penalty decomposition: A^T A + beta J^T J is not positive definite");
    bool changed = false;
    for(int inner = 0; inner < 4; ++inner) { // a few alternations per beta; usually one settles it
      Eigen::MatrixXd rhs = AtP;
      J.add_transpose_times(Y, beta, rhs);
      X = M.solve(rhs);
      const Eigen::MatrixXd Z = J.times(X);
      z2 = Z.rowwise().squaredNorm();
      bool step_changed = false;
      for(Eigen::Index r = 0; r < m; ++r) {
        const char keep = beta * z2[r] > lambda;
        if(keep != kept[std::size_t(r)]) step_changed = true;
        kept[std::size_t(r)] = keep;
        if(keep) Y.row(r) = Z.row(r);
        else Y.row(r).setZero();
      }
      changed = changed || step_changed;
      if(!step_changed) break;
    }
    settled = changed ? 0 : settled + 1;
    // Settled: the same knots for three betas, and every dropped jump far below the threshold
    // (it only shrinks as beta grows, while the threshold falls as 1 / beta).
    double dropped = 0;
    for(Eigen::Index r = 0; r < m; ++r) if(!kept[std::size_t(r)]) dropped = std::max(dropped, z2[r]);
    if(settled >= 3 && beta * dropped < 1e-4 * lambda) break;
  }
  std::vector<std::size_t> out;
  for(Eigen::Index r = 0; r < m; ++r) if(kept[std::size_t(r)]) out.push_back(std::size_t(r));
  // Polish: a knot kept while beta was small stays kept (its row of Y follows J X, so nothing
  // pushes its jump down); on exact data whole clusters around a true knot survive.  Removing,
  // from the least-squares fit on the kept knots, those that do not pay for themselves (the
  // greedy pass, started here) fixes it; it only ever lowers the objective.
  Goal goal;
  goal.lambda = lambda;
  return greedy_removal(p, goal, &out);
}

// Where the continuation starts.  A stage's first beta is at least 1e-6 max diag(A^T A), so its
// first threshold is at most lambda_s / that; below the median squared jump of the full
// least-squares fit times that beta, the first stage keeps about half the candidates or more
// and cannot collapse (a fixed fraction of the target lambda cannot promise it: on 2000 dense
// samples of a smooth curve, lambda / 4^6 still lost every knot at lambda = 0.1).
double starting_lambda(const Problem& p, const Spline_fit& full)
{
  const Basis basis = make_basis(p.candidates, p.degree, p.closed);
  const Band_rows A = design_rows(basis, p.t);
  Eigen::VectorXd diagonal = Eigen::VectorXd::Zero(basis.controls);
  for(Eigen::Index r = 0; r < A.rows(); ++r)
    for(Eigen::Index q = 0; q < A.values.cols(); ++q) diagonal[A.column(r, q)] += A.values(r, q) * A.values(r, q);
  Eigen::VectorXd z2 = jump_rows(basis).times(full.spline.control_points).rowwise().squaredNorm();
  if(z2.size() == 0) return 0;
  std::nth_element(z2.data(), z2.data() + z2.size() / 2, z2.data() + z2.size());
  return 1e-6 * diagonal.maxCoeff() * z2[z2.size() / 2];
}

} // namespace

Spline_fit penalty_decomposition(const Problem& p, double lambda)
{
  std::vector<std::size_t> all(static_cast<std::size_t>(p.candidates.size()));
  for(std::size_t i = 0; i < all.size(); ++i) all[i] = i;
  if(lambda == 0 || all.empty()) return finish(p, all, lambda);
  Goal goal;
  goal.lambda = lambda;
  Spline_fit best = finish(p, all, lambda);
  // The schedule: from lambda / 4^6 (or lower, where the data asks for it: starting_lambda) up to
  // lambda by factors of at least 4 (small enough that a stage removes a fraction of the knots,
  // not all of them), in at most 12 stages (the factor grows beyond 4 for a range past 4^12).
  const double lambda_0 = std::max(1e-18 * lambda, std::min(lambda / 4096, starting_lambda(p, best)));
  const int stages = std::min(12, int(std::ceil(std::log(lambda / lambda_0) / std::log(4.0) - 1e-9)));
  const double ratio = std::pow(lambda / lambda_0, 1.0 / double(stages));
  std::vector<std::size_t> kept = all;
  for(int s = stages; s >= 0 && !kept.empty(); --s) {
    const double lambda_s = lambda * std::pow(ratio, -double(s));
    const Spline_fit stage = penalty_decomposition_stage(restricted(p, kept), lambda_s);
    std::vector<std::size_t> next;
    for(std::size_t i : stage.kept) next.push_back(kept[i]);
    kept = std::move(next);
    // Every stage's knots are a candidate answer at the target lambda (usually the last wins;
    // when a late stage collapses, an earlier one does).
    Spline_fit at_target = finish(p, kept, lambda);
    if(better(at_target, best, goal)) best = std::move(at_target);
  }
  // The removal pass at the target lambda (a no-op after the last stage, not after an earlier one).
  return greedy_removal(p, goal, &best.kept);
}

} // namespace internal
} // namespace Spline_approximation
} // namespace CGAL
