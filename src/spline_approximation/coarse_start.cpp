// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A coarse-to-fine start for long curves.  Greedy removal from every candidate refits all n
// samples with up to n knots, O(log n) times: seconds at a million samples.  Instead, start from
// a few knots spread evenly over the candidates and, round by round, split every knot span whose
// samples miss a tightened goal at the candidate in the middle of the span (by index, so that a
// span halves each round: at most log2(candidates) rounds, each one least-squares fit).  Where
// the data needs a knot exactly (a spline on a few candidates), the spans around it keep
// splitting until it is a span end, so the exact knots are in the start set.  The removal then
// works on a set a few times larger than its answer instead of on every candidate.

#include <CGAL/Spline_approximation/internal/spline_numerics.h>

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace Spline_approximation {
namespace internal {

namespace {

// What a span is measured by against the tightened goal: its max error, its RMS error, or (a
// penalty) its squared error.
double span_badness(const Goal& goal, double max_error, double squared_error, std::size_t samples)
{
  if(goal.max_error) return max_error;
  if(goal.rms_error) return samples > 0 ? std::sqrt(squared_error / double(samples)) : 0.0;
  return squared_error;
}

// The tightened goal of a span: `margin` times the bound (max or RMS error over the span's
// samples), or, with a penalty, a squared error margin^2 lambda (a knot in a span whose squared
// error is below lambda cannot pay for itself).
double span_threshold(const Goal& goal, double margin)
{
  if(goal.max_error) return margin * *goal.max_error;
  if(goal.rms_error) return margin * *goal.rms_error;
  return margin * margin * goal.lambda;
}

} // namespace

Problem restricted(const Problem& p, const std::vector<std::size_t>& kept)
{
  Problem q = p;
  q.candidates.resize(Eigen::Index(kept.size()));
  for(std::size_t i = 0; i < kept.size(); ++i) q.candidates[Eigen::Index(i)] = p.candidates[Eigen::Index(kept[i])];
  return q;
}

std::vector<std::size_t> coarse_start(const Problem& p, const Goal& goal, double margin)
{
  const std::size_t N = std::size_t(p.candidates.size());
  // Sixteen spans to start with: enough that the first fits resolve the curve's large-scale
  // shape; the rounds add the rest where the samples ask for it.
  const std::size_t first = std::min<std::size_t>(N, 15);
  std::vector<std::size_t> kept;
  for(std::size_t i = 0; i < first; ++i) kept.push_back((2 * i + 1) * N / (2 * first));
  kept.erase(std::unique(kept.begin(), kept.end()), kept.end());
  const Eigen::Index n = p.t.size();
  for(;;) {
    const Spline_fit fit = finish(p, kept, goal.lambda);
    // Span s of an open curve lies between kept[s - 1] and kept[s] (the curve's ends beyond the
    // first and last); on a closed curve span 0 wraps from the last knot to the first.
    const std::size_t m = kept.size();
    std::vector<double> span_max(m + 1, 0.0), span_squares(m + 1, 0.0);
    std::vector<std::size_t> span_samples(m + 1, 0);
    std::size_t s = 0;
    for(Eigen::Index j = 0; j < n; ++j) {
      while(s < m && p.candidates[Eigen::Index(kept[s])] <= p.t[j]) ++s;
      const std::size_t span = (p.closed && s == m) ? 0 : s;
      span_max[span] = std::max(span_max[span], fit.errors[j]);
      span_squares[span] += fit.errors[j] * fit.errors[j];
      ++span_samples[span];
    }
    std::vector<std::size_t> added;
    for(std::size_t span = 0; span <= (p.closed ? m - 1 : m); ++span) {
      if(!(span_badness(goal, span_max[span], span_squares[span], span_samples[span]) > span_threshold(goal, margin))) continue;
      // The candidates strictly inside the span, as an index range [lo, hi) (closed: modulo N).
      std::size_t lo, hi;
      if(p.closed && span == 0) {
        lo = m > 0 ? kept[m - 1] + 1 : 0;
        hi = m > 0 ? kept[0] + N : N;
      } else {
        lo = span == 0 ? 0 : kept[span - 1] + 1;
        hi = span == m ? N : kept[span];
      }
      if(hi <= lo) continue; // no candidate left inside: the span is as fine as it gets
      added.push_back(((lo + hi) / 2) % N);
    }
    if(added.empty()) return kept;
    kept.insert(kept.end(), added.begin(), added.end());
    std::sort(kept.begin(), kept.end());
    kept.erase(std::unique(kept.begin(), kept.end()), kept.end());
  }
}

} // namespace internal
} // namespace Spline_approximation
} // namespace CGAL
