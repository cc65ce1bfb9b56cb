// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The entry points: input checks, parameters, candidate knots, and the choice of algorithm.

#include <CGAL/Spline_approximation/Spline_fit.h>
#include <CGAL/Spline_approximation/internal/spline_numerics.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <string>

namespace CGAL {
namespace Spline_approximation {
namespace {

void check_samples(const Eigen::MatrixXd& samples, int degree, bool closed = false)
{
  if(degree < 1 || degree > 3)
    throw Invalid_input("spline fit: the degree must be 1, 2 or 3, not " + std::to_string(degree));
  if(samples.cols() < 1) throw Invalid_input("spline fit: the samples have no coordinates");
  // A closed curve needs a polygon (three samples) and, like an open one, degree + 1 samples.
  if(closed && samples.rows() < std::max(3, degree + 1))
    throw Invalid_input("spline fit: a closed curve of degree " + std::to_string(degree) + " needs at least " +
                        std::to_string(std::max(3, degree + 1)) + " samples, got " + std::to_string(samples.rows()));
  if(samples.rows() < degree + 1)
    throw Invalid_input("spline fit: degree " + std::to_string(degree) + " needs at least " +
                        std::to_string(degree + 1) + " samples, got " + std::to_string(samples.rows()));
  for(Eigen::Index j = 0; j < samples.rows(); ++j)
    if(!samples.row(j).allFinite())
      throw Invalid_input("spline fit: sample " + std::to_string(j) + " has a NaN or infinite coordinate");
}

void check_goal(const Fit_options& o)
{
  const int set = int(bool(o.penalty)) + int(bool(o.max_error)) + int(bool(o.rms_error));
  if(set != 1)
    throw Invalid_input("spline fit: give exactly one of a knot penalty, a max error bound and an RMS error bound");
  if(o.penalty && !(*o.penalty >= 0 && std::isfinite(*o.penalty)))
    throw Invalid_input("spline fit: the knot penalty lambda must be finite and >= 0");
  for(const std::optional<double>& b : {o.max_error, o.rms_error})
    if(b && !(*b > 0 && std::isfinite(*b)))
      throw Invalid_input("spline fit: an error bound (tolerance) must be finite and > 0");
}

// Finds the fewest knots within a bound by the penalty decomposition: geometric bisection on
// lambda between 0 (every knot) and the squared error of one polynomial piece (beyond which
// no knot pays for itself), keeping the best fit that meets the bound.
Spline_fit penalty_decomposition_within(const internal::Problem& p, const internal::Goal& goal)
{
  Spline_fit best = internal::finish(p, {}, 0);
  if(goal.met(best)) return best;
  double hi = best.squared_error, lo = 1e-12 * hi;
  Spline_fit at_lo = internal::penalty_decomposition(p, lo);
  if(!goal.met(at_lo)) return internal::better(at_lo, best, goal) ? at_lo : best;
  best = at_lo;
  while(hi > 1.05 * lo) { // about ten fits: the knot count rarely changes within 5 % of lambda
    const double mid = std::sqrt(lo * hi);
    Spline_fit fit = internal::penalty_decomposition(p, mid);
    if(goal.met(fit)) {
      lo = mid;
      if(internal::better(fit, best, goal)) best = std::move(fit);
    } else {
      hi = mid;
    }
  }
  // The same removal pass as in penalty mode, now while the bound holds.
  return internal::greedy_removal(p, goal, &best.kept);
}

// Exact data whose knot falls inside a short span of the coarse start is fitted within the
// bound by a cluster of knots around it, which the removal cannot trade for the one knot the
// start lacks.  The answer's knots, joined by every candidate of the start's spans next to
// them where those are short (the start refined there, at most `short_span` candidates): a
// second start, on which the fit puts its jump where the data has it.
std::vector<std::size_t> densified_around(const std::vector<std::size_t>& answer, const std::vector<std::size_t>& start,
                                          std::size_t N, bool closed)
{
  constexpr long long short_span = 64;
  std::vector<char> in(N, 0);
  for(std::size_t a : answer) in[a] = 1;
  const long long n = (long long)N, m = (long long)start.size();
  for(std::size_t a : answer) {
    const long long pos = std::lower_bound(start.begin(), start.end(), a) - start.begin();
    const long long left = pos > 0 ? (long long)start[pos - 1] : (closed ? (long long)start[m - 1] - n : -1);
    const long long right = pos + 1 < m ? (long long)start[pos + 1] : (closed ? (long long)start[0] + n : n);
    for(long long side = 0; side < 2; ++side) {
      const long long lo = side == 0 ? left : (long long)a, hi = side == 0 ? (long long)a : right;
      if(hi - lo <= short_span)
        for(long long c = lo + 1; c < hi; ++c) in[std::size_t(((c % n) + n) % n)] = 1;
    }
  }
  std::vector<std::size_t> out;
  for(std::size_t c = 0; c < N; ++c) if(in[c]) out.push_back(c);
  return out;
}

// The candidates nearest to K uniformly spaced parameters, increasing (a repeat is dropped).
std::vector<std::size_t> uniform_candidates(const internal::Problem& p, std::size_t K)
{
  std::vector<std::size_t> kept;
  const double* c = p.candidates.data();
  const std::size_t m = std::size_t(p.candidates.size());
  for(std::size_t i = 0; i < K && m > 0; ++i) {
    const double u = p.closed ? double(i) / double(K) : double(i + 1) / double(K + 1);
    std::size_t j = std::size_t(std::lower_bound(c, c + m, u) - c);
    if(j == m || (j > 0 && u - c[j - 1] < c[j] - u)) --j;
    if(kept.empty() || j > kept.back()) kept.push_back(j);
  }
  return kept;
}

// Least squares on uniformly spaced knots is the baseline any fit is held against.  The
// coarse-to-fine start places knots at dyadic splits, and on a smooth curve, whose best knots
// are nearly uniform, removal from them can keep more knots than uniform ones need (8 against
// 7 on a rose of a million samples).  Where the fewest uniform knots that meet the bound are
// fewer than the answer's, the answer is those, then greedy removal from them.  Long curves
// only: below the coarse start the removal starts from every candidate, and there a uniform
// restart made a jittery motion's regularisation worse (fewer knots, within the same bound).
Spline_fit with_fewer_uniform_knots(const internal::Problem& p, const internal::Goal& goal, Spline_fit fit)
{
  if(!goal.is_bound() || !goal.met(fit)) return fit;
  bool fewer = false;
  for(std::size_t K = fit.kept.size(); K-- > 0;) {
    Spline_fit uniform = internal::finish(p, uniform_candidates(p, K), goal.lambda, internal::Sample_errors::summary_only);
    if(!goal.met(uniform)) break;
    fit = std::move(uniform);
    fewer = true;
  }
  return fewer ? internal::greedy_removal(p, goal, &fit.kept) : fit;
}

// A heuristic on the candidates of `p`, or, past `coarse_start_above` candidates, on those of
// the coarse-to-fine start (the answer's `kept` mapped back to p's candidates), then on the
// answer densified where the start was fine (exact knots), the better of the two; where the
// bound is still missed, on every candidate.
Spline_fit heuristic_fit(const internal::Problem& p, const internal::Goal& goal, const Fit_options& options)
{
  auto run = [&](const internal::Problem& q) {
    if(options.algorithm == Fit_algorithm::greedy_removal) return internal::greedy_removal(q, goal);
    return goal.is_bound() ? penalty_decomposition_within(q, goal) : internal::penalty_decomposition(q, goal.lambda);
  };
  auto run_from = [&](const std::vector<std::size_t>& start) {
    Spline_fit fit = run(internal::restricted(p, start));
    for(std::size_t& i : fit.kept) i = start[i];
    return fit;
  };
  auto improved = [&](Spline_fit fit) {
    if(std::size_t(p.t.size()) > options.relocate_knots_up_to) return fit;
    return internal::relocate_and_remove(p, goal, std::move(fit));
  };
  auto finished = [&](Spline_fit fit) {
    fit = improved(std::move(fit));
    const std::size_t knots = fit.kept.size();
    fit = with_fewer_uniform_knots(p, goal, std::move(fit));
    return fit.kept.size() < knots ? improved(std::move(fit)) : fit;
  };
  if(std::size_t(p.candidates.size()) <= options.coarse_start_above) return improved(run(p));
  const std::vector<std::size_t> start = internal::coarse_start(p, goal, 0.5);
  Spline_fit fit = run_from(start);
  const std::vector<std::size_t> dense = densified_around(fit.kept, start, std::size_t(p.candidates.size()), p.closed);
  if(dense.size() > fit.kept.size()) {
    Spline_fit from_dense = run_from(dense);
    if(internal::better(from_dense, fit, goal)) fit = std::move(from_dense);
  }
  if(goal.is_bound() && !goal.met(fit)) fit = run(p);
  return finished(std::move(fit));
}

} // namespace

const char* algorithm_name(Fit_algorithm a)
{
  switch(a) {
  case Fit_algorithm::penalty_decomposition: return "penalty";
  case Fit_algorithm::greedy_removal: return "greedy";
  case Fit_algorithm::dynamic_programming: return "dp";
  case Fit_algorithm::brute_force: return "brute";
  }
  return "?";
}

Eigen::VectorXd chord_length_parameters(const Eigen::MatrixXd& samples, bool closed)
{
  if(samples.rows() < 2) throw Invalid_input("chord-length parameters: need at least two samples");
  if(closed && samples.rows() < 3) throw Invalid_input("chord-length parameters: a closed curve needs at least three samples");
  Eigen::VectorXd t(samples.rows());
  t[0] = 0;
  for(Eigen::Index j = 1; j < samples.rows(); ++j) {
    if(!samples.row(j).allFinite() || !samples.row(j - 1).allFinite())
      throw Invalid_input("chord-length parameters: sample " + std::to_string(samples.row(j).allFinite() ? j - 1 : j) +
                          " has a NaN or infinite coordinate");
    const double d = (samples.row(j) - samples.row(j - 1)).norm();
    if(!(d > 0))
      throw Invalid_input("chord-length parameters: samples " + std::to_string(j - 1) + " and " + std::to_string(j) +
                          " coincide (a zero-length piece of the curve)");
    t[j] = t[j - 1] + d;
  }
  if(!closed) return t / t[t.size() - 1];
  const double closing = (samples.row(0) - samples.row(samples.rows() - 1)).norm();
  if(!(closing > 0))
    throw Invalid_input("chord-length parameters: the last sample of a closed curve equals the first (do not repeat "
                        "the first sample; the closing segment is implied)");
  return t / (t[t.size() - 1] + closing);
}

Spline_fit fit_spline(const Eigen::MatrixXd& samples, const Fit_options& options)
{
  check_samples(samples, options.degree, options.closed_curve);
  return fit_spline(samples, chord_length_parameters(samples, options.closed_curve), options);
}

Spline_fit fit_spline(const Eigen::MatrixXd& samples, const Eigen::VectorXd& parameters, const Fit_options& options)
{
  const auto start = std::chrono::steady_clock::now();
  check_samples(samples, options.degree, options.closed_curve);
  check_goal(options);
  const Eigen::Index n = samples.rows();
  if(parameters.size() != n)
    throw Invalid_input("spline fit: " + std::to_string(parameters.size()) + " parameters for " + std::to_string(n) +
                        " samples");
  for(Eigen::Index j = 0; j < n; ++j) {
    if(!std::isfinite(parameters[j])) throw Invalid_input("spline fit: parameter " + std::to_string(j) + " is not finite");
    if(j > 0 && !(parameters[j] > parameters[j - 1]))
      throw Invalid_input("spline fit: the parameters must increase strictly (parameters " + std::to_string(j - 1) +
                          " and " + std::to_string(j) + ")");
  }
  // The algorithms see the samples about their centroid, the fit moved back at the end: the fit
  // does not depend on where the curve lies, and neither should its rounding (the sums of squares
  // would carry the distance from the origin); the tie tolerances (spline_numerics.h) are taken
  // relative to the curve's own spread.
  const Eigen::RowVectorXd centre = samples.colwise().mean();
  const Eigen::MatrixXd centred = samples.rowwise() - centre;
  internal::Problem p;
  p.samples = &centred;
  p.degree = options.degree;
  p.closed = options.closed_curve;
  const std::size_t g = options.candidate_grid_size;
  if(p.closed) { // period 1, shifted to start at 0; every sample (0 included) or i / g a candidate
    if(!(parameters[n - 1] - parameters[0] < 1))
      throw Invalid_input("spline fit: the parameters of a closed curve span less than its period 1 (last minus "
                          "first is " + std::to_string(parameters[n - 1] - parameters[0]) + ")");
    p.t = parameters.array() - parameters[0];
    if(g > 0) p.candidates = Eigen::VectorXd::LinSpaced(Eigen::Index(g), 0.0, double(g - 1) / double(g));
    else p.candidates = p.t;
  } else {
    p.t = (parameters.array() - parameters[0]) / (parameters[n - 1] - parameters[0]);
    p.t[n - 1] = 1; // exactly, whatever the rounding of the division
    if(g > 0) {
      p.candidates.resize(Eigen::Index(g));
      for(std::size_t i = 0; i < g; ++i) p.candidates[Eigen::Index(i)] = double(i + 1) / double(g + 1);
    } else {
      p.candidates = p.t.segment(1, n - 2);
    }
  }
  internal::Goal goal;
  goal.lambda = options.penalty.value_or(0.0);
  goal.max_error = options.max_error;
  goal.rms_error = options.rms_error;

  Spline_fit fit;
  switch(options.algorithm) {
  case Fit_algorithm::penalty_decomposition:
  case Fit_algorithm::greedy_removal:
    fit = heuristic_fit(p, goal, options);
    break;
  case Fit_algorithm::dynamic_programming:
    if(options.degree != 1)
      throw Invalid_input("spline fit: the dynamic programming optimum is known for degree 1 only");
    if(goal.max_error)
      throw Invalid_input("spline fit: the dynamic programming optimum is known for a penalty or an RMS bound, "
                          "not a max error bound (use brute force on small problems)");
    fit = internal::dynamic_programming(p, goal);
    break;
  case Fit_algorithm::brute_force:
    if(std::size_t(p.candidates.size()) > max_brute_force_candidates)
      throw Invalid_input("spline fit: brute force over " + std::to_string(p.candidates.size()) +
                          " candidate knots is not computable (at most " +
                          std::to_string(max_brute_force_candidates) + ")");
    fit = internal::brute_force(p, goal);
    break;
  }
  if(fit.errors.size() != n) fit = internal::finish(p, fit.kept, goal.lambda); // the errors of every sample
  fit.spline.control_points.rowwise() += centre;
  fit.parameters = p.t;
  fit.candidates = p.candidates;
  fit.algorithm = options.algorithm;
  fit.within_bound = goal.met(fit);
  fit.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return fit;
}

Spline_fit least_squares_spline(const Eigen::MatrixXd& samples, const Eigen::VectorXd& t, int degree,
                                const Eigen::VectorXd& interior_knots, bool closed)
{
  check_samples(samples, degree, closed);
  if(t.size() != samples.rows()) throw Invalid_input("least-squares spline: one parameter per sample is needed");
  for(Eigen::Index j = 0; j < t.size(); ++j)
    if(!(t[j] >= 0 && (closed ? t[j] < 1 : t[j] <= 1)) || (j > 0 && !(t[j] > t[j - 1])))
      throw Invalid_input(closed ? "least-squares spline: the parameters of a closed curve must increase strictly within [0, 1)"
                                 : "least-squares spline: the parameters must increase strictly within [0, 1]");
  for(Eigen::Index i = 0; i < interior_knots.size(); ++i)
    if(!(closed ? interior_knots[i] >= 0 : interior_knots[i] > 0) || !(interior_knots[i] < 1) ||
       (i > 0 && !(interior_knots[i] > interior_knots[i - 1])))
      throw Invalid_input(closed ? "least-squares spline: the knots of a closed curve must increase strictly within [0, 1)"
                                 : "least-squares spline: the interior knots must increase strictly within (0, 1)");
  // Centred as in fit_spline, so that a fit there on the same knots rounds alike.
  const Eigen::RowVectorXd centre = samples.colwise().mean();
  const Eigen::MatrixXd centred = samples.rowwise() - centre;
  internal::Problem p;
  p.samples = &centred;
  p.t = t;
  p.degree = degree;
  p.candidates = interior_knots;
  p.closed = closed;
  std::vector<std::size_t> all(std::size_t(interior_knots.size()));
  for(std::size_t i = 0; i < all.size(); ++i) all[i] = i;
  Spline_fit fit = internal::finish(p, all, 0);
  fit.spline.control_points.rowwise() += centre;
  fit.parameters = p.t;
  fit.candidates = p.candidates;
  return fit;
}

} // namespace Spline_approximation
} // namespace CGAL
