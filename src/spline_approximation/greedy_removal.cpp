// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Greedy knot removal, the baseline (in the spirit of Lyche and Morken): start from every
// candidate, rank the kept knots by the jump of the k-th derivative of the current fit (a knot
// whose jump vanishes can go at no cost), remove a batch of the smallest, refit, and keep the
// batch if the goal allows it (the objective falls, or the bound still holds); on refusal
// halve the batch.  Batches keep it to O(log) refits on long curves.

#include <CGAL/Spline_approximation/internal/spline_numerics.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace CGAL {
namespace Spline_approximation {
namespace internal {

Spline_fit greedy_removal(const Problem& p, const Goal& goal, const std::vector<std::size_t>* start)
{
  std::vector<std::size_t> kept(static_cast<std::size_t>(p.candidates.size()));
  std::iota(kept.begin(), kept.end(), std::size_t(0));
  if(start) kept = *start;
  Spline_fit fit = finish(p, kept, goal.lambda, Sample_errors::summary_only);
  if(goal.is_bound() && !goal.met(fit)) return fit; // removing knots cannot help
  std::size_t batch = std::max<std::size_t>(1, kept.size() / 8);
  std::size_t tried_singles = 0; // at batch 1, the next few ranked knots are tried before giving up
  const double spread = std::sqrt(squared_spread(*p.samples));
  while(!kept.empty()) {
    const Eigen::VectorXd knots = p.closed ? fit.spline.knots : fit.spline.interior_knots();
    const Band_rows J = jump_rows(make_basis(knots, p.degree, p.closed));
    const Eigen::VectorXd jump = J.times(fit.spline.control_points).rowwise().norm();
    // Smallest first, jumps equal up to rounding (a symmetric curve's, whose moved copy rounds
    // them otherwise) by index.  Equal within 1e-10 of the largest jump or 1e-13 of the
    // samples' spread (jumps are in the data's units, rounded at some 1e-16 of its size): a
    // larger threshold in those units would tie the genuine jumps of dense candidates, some
    // 1e-11 of the size at degree 3 on 20,000 candidates (test CoarseStartRecoversExactKnots).
    const double jump_tie = std::max(1e-10 * jump.maxCoeff(), 1e-13 * spread);
    const std::vector<std::size_t> order =
        order_with_ties(std::vector<double>(jump.data(), jump.data() + jump.size()),
                        std::vector<double>(kept.size(), jump_tie));
    // The batch: smallest jumps first, never two neighbours (their removals interact).
    std::vector<char> out(kept.size(), 0), blocked(kept.size(), 0);
    std::size_t chosen = 0;
    for(std::size_t q = (batch == 1 ? tried_singles : 0); q < order.size() && chosen < batch; ++q) {
      const std::size_t i = order[q];
      if(blocked[i]) continue;
      out[i] = 1;
      ++chosen;
      if(i > 0) blocked[i - 1] = 1;
      if(i + 1 < kept.size()) blocked[i + 1] = 1;
      if(p.closed && i == 0) blocked[kept.size() - 1] = 1; // on a closed curve the ends are neighbours
      if(p.closed && i + 1 == kept.size()) blocked[0] = 1;
    }
    if(chosen == 0) break;
    std::vector<std::size_t> trial_kept;
    for(std::size_t i = 0; i < kept.size(); ++i) if(!out[i]) trial_kept.push_back(kept[i]);
    Spline_fit trial = finish(p, trial_kept, goal.lambda, Sample_errors::summary_only);
    const bool accept = goal.is_bound() ? goal.met(trial) : trial.objective < fit.objective;
    if(accept) {
      kept = std::move(trial_kept);
      fit = std::move(trial);
      tried_singles = 0;
      batch = std::max<std::size_t>(1, std::min(batch, kept.size() / 8));
    } else if(batch > 1) {
      batch /= 2;
    } else if(++tried_singles >= std::min<std::size_t>(8, kept.size())) {
      break;
    }
  }
  return fit;
}

} // namespace internal
} // namespace Spline_approximation
} // namespace CGAL
