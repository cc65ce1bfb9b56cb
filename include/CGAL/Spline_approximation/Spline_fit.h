// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SPLINE_APPROXIMATION_SPLINE_FIT_H
#define CGAL_SPLINE_APPROXIMATION_SPLINE_FIT_H

/// \file Spline_fit.h
/// Spline approximation with the fewest knots (thesis Chapter 6, SPEC 14): samples `p_j` in
/// R^D at parameters `t_j`, a dense set of candidate knots, and
/// `min |A X - P|^2 + lambda * #{candidate knots kept}` (or the fewest knots within an error
/// bound), solved by one of several algorithms; every answer is finished by the least-squares
/// fit on the knots it keeps.  Samples are the rows of an Eigen matrix; <approximate_curve.h>
/// is the front-end over ranges of CGAL points.

#include <CGAL/Spline_approximation/B_spline.h>
#include <CGAL/Spline_approximation/errors.h>

#include <Eigen/Core>

#include <cstddef>
#include <optional>
#include <vector>

namespace CGAL {
namespace Spline_approximation {

/// The algorithms, each selectable.
enum class Fit_algorithm {
  penalty_decomposition, ///< SPEC 14: banded SPD solves alternated with a group hard threshold while beta grows
  greedy_removal,        ///< baseline: remove the knots of smallest k-th derivative jump in batches, refit
  dynamic_programming,   ///< exact optimum for degree 1, open or closed curves (ordered subsets of the candidates)
  brute_force            ///< exact optimum over all subsets of at most `max_brute_force_candidates` candidates
};

/// The name of an algorithm, for tables ("penalty", "greedy", "dp", "brute").
const char* algorithm_name(Fit_algorithm a);

/// Up to 2^16 least-squares fits: seconds for small data, never more.
constexpr std::size_t max_brute_force_candidates = 16;

/// What to fit and how.  Exactly one of `penalty`, `max_error`, `rms_error` must be set.
struct Fit_options
{
  int degree = 3;                   ///< 1 to 3
  Fit_algorithm algorithm = Fit_algorithm::penalty_decomposition;
  std::optional<double> penalty;    ///< lambda >= 0: the cost of one knot, in squared data units
  std::optional<double> max_error;  ///< > 0: the fewest knots with every sample within this distance
  std::optional<double> rms_error;  ///< > 0: the fewest knots with the root-mean-square distance within this
  /// 0: every interior sample parameter is a candidate knot; g > 0: the uniform grid `i / (g + 1)`, i = 1..g.
  /// Closed curves: every sample parameter (0 included), or the grid `i / g`, i = 0..g-1.
  std::size_t candidate_grid_size = 0;
  /// The heuristics (penalty decomposition, greedy removal) on more candidates than this start
  /// from a coarse-to-fine knot set instead of every candidate: a few knots, each span halved
  /// while its samples miss half the bound (or, with a penalty, while its squared error
  /// exceeds lambda / 4).  Cost O(n log n) instead of O(n) fits of n knots; the knots of data
  /// that is exactly a spline on a few candidates are still found.  0: always; `SIZE_MAX`: never.
  std::size_t coarse_start_above = 4096;
  /// Degree 1 (open and closed curves), up to this many samples: the heuristics' answer is
  /// improved by a local search that slides each knot to the candidate between its neighbours
  /// where the squared error is least, and removes knots while the goal allows
  /// (`knot_relocation.cpp`).  It brings the vertex count within a few percent of the dynamic
  /// programming optimum, at 3-7 times the heuristic's time (a million samples: under a second).
  /// 0: never; `SIZE_MAX`: always.
  std::size_t relocate_knots_up_to = std::size_t(1) << 20;
  /// Fit a closed curve: the last sample joins the first (do not repeat it), chord length
  /// includes that closing segment, and the spline is periodic (`B_spline::closed`).  Every
  /// algorithm takes it (the dynamic programming, as for open curves, at degree 1 only).
  bool closed_curve = false;
};

/// A fitted spline with its errors.  The error of a sample is the Euclidean distance between
/// it and the spline at the sample's parameter (not the closest point of the curve).
struct Spline_fit
{
  B_spline spline;
  Eigen::VectorXd parameters;     ///< the samples' parameters in [0, 1]
  Eigen::VectorXd candidates;     ///< the candidate knots
  std::vector<std::size_t> kept;  ///< indices into `candidates` of the knots kept, increasing
  Eigen::VectorXd errors;         ///< per sample
  double max_error = 0, rms_error = 0;
  double squared_error = 0;       ///< sum over samples of the squared errors
  double objective = 0;           ///< `squared_error + lambda * number_of_knots()` (penalty mode)
  bool within_bound = true;       ///< bound modes: whether the bound was met (else the best fit found)
  Fit_algorithm algorithm = Fit_algorithm::penalty_decomposition;
  double seconds = 0;             ///< wall time of the fit

  std::size_t number_of_knots() const { return kept.size(); }
  bool closed() const { return spline.closed; } ///< a closed curve (periodic spline)
};

/// Normalised chord-length parameters of the rows of `samples` (0 at the first, 1 at the last;
/// `closed`: 1 would be the first again after the closing segment, so the last is below 1).
/// \throws Invalid_input for fewer than two rows (closed: three), a non-finite coordinate, or
///         two consecutive equal rows (closed: the last equal to the first too).
Eigen::VectorXd chord_length_parameters(const Eigen::MatrixXd& samples, bool closed = false);

/// Fits a curve (open, or closed if `options.closed_curve`) through the rows of `samples` at chord-length parameters.
/// \throws Invalid_input for fewer than `degree + 1` samples (closed: `max(3, degree + 1)`), NaN or infinite coordinates,
///         consecutive repeated samples (a zero-length piece), `lambda < 0`, a bound `<= 0`, not
///         exactly one of penalty and bounds, a degree outside 1..3, or an exact algorithm asked
///         where it is not computable (dynamic programming for degree > 1, a max-error bound or
///         past its work limit, brute force on more than `max_brute_force_candidates` candidates).
Spline_fit fit_spline(const Eigen::MatrixXd& samples, const Fit_options& options);

/// Same, at the caller's parameters (strictly increasing and finite; mapped affinely to [0, 1];
/// closed curves: the period is 1, so the last minus the first must be below 1, and they are shifted to start at 0).
Spline_fit fit_spline(const Eigen::MatrixXd& samples, const Eigen::VectorXd& parameters,
                      const Fit_options& options);

/// The least-squares spline of `degree` on the given interior knots (strictly inside (0, 1),
/// increasing) at the parameters `t` (in [0, 1]): the finish of every algorithm, and the
/// uniform-knot baseline.  Where the knots leave the fit under-determined (an interval without
/// enough samples), the fit with the smallest k-th derivative jumps among the best is returned.
/// `closed`: the periodic spline, knots and parameters in [0, 1).
Spline_fit least_squares_spline(const Eigen::MatrixXd& samples, const Eigen::VectorXd& t, int degree,
                                const Eigen::VectorXd& interior_knots, bool closed = false);

} // namespace Spline_approximation
} // namespace CGAL

#endif
