// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SPLINE_APPROXIMATION_INTERNAL_SPLINE_NUMERICS_H
#define CGAL_SPLINE_APPROXIMATION_INTERNAL_SPLINE_NUMERICS_H

// The compiled numerics shared by the algorithms (src/spline_approximation): banded rows of
// the design and jump matrices, a banded Cholesky, the least-squares finish.

#include <CGAL/Spline_approximation/Spline_fit.h>

#include <Eigen/Core>

#include <algorithm>

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

namespace CGAL {
namespace Spline_approximation {
namespace internal {

// A matrix whose row r has its nonzeros in the consecutive columns first[r] .. first[r] + values.cols() - 1,
// taken modulo `wrap` when it is positive (the wrapped control points of a closed curve; two
// entries of a row may then land in one column, where they add).
struct Band_rows
{
  Eigen::VectorXi first;
  Eigen::MatrixXd values;
  Eigen::Index wrap = 0;
  Eigen::Index rows() const { return first.size(); }
  Eigen::Index column(Eigen::Index r, Eigen::Index q) const { return wrap > 0 ? (first[r] + q) % wrap : first[r] + q; }
  Eigen::MatrixXd times(const Eigen::MatrixXd& X) const;                    // R X
  void add_transpose_times(const Eigen::MatrixXd& Y, double w, Eigen::MatrixXd& out) const; // out += w R^T Y
};

// The B-spline basis on a set of knots: clamped on [0, 1] (open curves; `knots` interior), or
// periodic of period 1 (closed curves; `knots` in [0, 1) on the circle, the knot vector
// extended by whole periods and the control points wrapped: basis function i and i + m are
// translates by one period and share control point i mod m).  A closed spline without knots is
// constant (a periodic polynomial): it is built on the single knot 0 with one control point.
struct Basis
{
  Eigen::VectorXd U;           // the full knot vector (clamped, or extended periodically)
  int degree = 3;
  bool closed = false;
  Eigen::Index controls = 0;   // number of control points
  Eigen::Index knots = 0;      // number of (interior or circle) knots: one jump row each
};
Basis make_basis(const Eigen::VectorXd& knots, int degree, bool closed);
// The clamped knot vector of `interior` knots for `degree`.
Eigen::VectorXd clamped_knots(const Eigen::VectorXd& interior, int degree);
// The span s (k <= s < number of control points) with U[s] <= t < U[s+1]; the last span for t at the end.
inline Eigen::Index find_span(const Eigen::VectorXd& U, int k, double t)
{
  const Eigen::Index n_ctrl = U.size() - k - 1;
  if(t >= U[n_ctrl]) return n_ctrl - 1;
  if(t <= U[k]) return k;
  const double* it = std::upper_bound(U.data() + k, U.data() + n_ctrl + 1, t);
  return Eigen::Index(it - U.data()) - 1;
}

// The k + 1 basis functions N_{s-k..s} nonzero on span s, at t (Cox-de Boor, triangular scheme).
inline void basis_functions(const Eigen::VectorXd& U, int k, Eigen::Index s, double t, double* N)
{
  double left[4], right[4];
  N[0] = 1.0;
  for(int j = 1; j <= k; ++j) {
    left[j] = t - U[s + 1 - j];
    right[j] = U[s + j] - t;
    double saved = 0.0;
    for(int r = 0; r < j; ++r) {
      const double tmp = N[r] / (right[r + 1] + left[j - r]);
      N[r] = saved + right[r + 1] * tmp;
      saved = left[j - r] * tmp;
    }
    N[j] = saved;
  }
}

// The k + 1 basis functions nonzero at one parameter after another: increasing parameters
// (every fit's) walk the spans in order, others are searched for.  Inline: it is the inner loop
// of every least-squares fit.
class Basis_at
{
public:
  explicit Basis_at(const Basis& b) : b_(b), last_span_(b.U.size() - b.degree - 2) {}
  // N_{s-k}(t) .. N_s(t) into N[0..k]; returns s - k, the column of N[0] (modulo the number of
  // control points of a closed basis).
  Eigen::Index operator()(double t, double* N)
  {
    const Eigen::VectorXd& U = b_.U;
    int steps = 0; // a few steps at most, so that jumping parameters cost a search, not a walk
    if(s_ >= 0 && t >= U[s_])
      while(steps < 8 && s_ < last_span_ && t >= U[s_ + 1]) ++s_, ++steps;
    if(s_ < 0 || t < U[s_] || (s_ < last_span_ && t >= U[s_ + 1])) s_ = find_span(U, b_.degree, t);
    basis_functions(U, b_.degree, s_, t, N);
    return s_ - b_.degree;
  }

private:
  const Basis& b_;
  Eigen::Index last_span_, s_ = -1;
};
// Rows of the design matrix A: A(j, i) = N_i(t_j) (t in [0, 1) if closed).
Band_rows design_rows(const Basis& b, const Eigen::VectorXd& t);
// One row per knot: the jump of the degree-th derivative there, scaled to unit norm
// (removing the knot is exactly asking the row times X to vanish; the scale makes the
// penalty read in data units whatever the knot spacing).
Band_rows jump_rows(const Basis& b);

// Symmetric positive definite matrix of half-bandwidth w, factored by banded Cholesky:
// O(n w^2), which for w <= 4 beats any general sparse solver by a wide margin.
class Banded_spd
{
public:
  Banded_spd(Eigen::Index n, int w) : band_(Eigen::MatrixXd::Zero(n, w + 1)), w_(w) {}
  Eigen::Index size() const { return band_.rows(); }
  int bandwidth() const { return w_; }
  double& at(Eigen::Index i, Eigen::Index j) { return band_(i, i - j); } // i >= j, i - j <= w
  double at(Eigen::Index i, Eigen::Index j) const { return band_(i, i - j); }
  void add_gram(const Band_rows& R, double w); // += w R^T R
  void add(const Banded_spd& B) { band_ += B.band_; } // += B, of the same size and band
  Banded_spd plus(const Banded_spd& B, double beta) const; // this + beta B (B's band may be wider)
  double max_diagonal() const { return band_.col(0).maxCoeff(); }
  // Factors in place; false if a pivot falls below `relative_pivot` times its diagonal entry.
  bool factor(double relative_pivot);
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const;

private:
  Eigen::MatrixXd band_; // band_(i, d) = M(i, i - d)
  int w_;
};

// The normal matrices of a fit: banded for open curves; for closed curves the wrapped control
// points add corners to the band, and Eigen's sparse LDL^T (AMD ordering: fill stays within the
// band and a border of width w) factors them.  Same interface as Banded_spd.
class Spd_matrix
{
public:
  Spd_matrix(Eigen::Index n, int w, bool cyclic);
  void add_gram(const Band_rows& R, double w); // += w R^T R
  Spd_matrix plus(const Spd_matrix& B, double beta) const;
  double max_diagonal() const;
  bool factor(double relative_pivot);
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const;
  Banded_spd& band() { return band_; } // the matrix of an open curve (not cyclic)

private:
  struct Cyclic; // the sparse matrix and its factor
  bool cyclic_;
  Banded_spd band_;
  std::shared_ptr<Cyclic> sparse_;
};

// The problem every algorithm sees.
struct Problem
{
  const Eigen::MatrixXd* samples = nullptr;
  Eigen::VectorXd t;          // in [0, 1], strictly increasing
  int degree = 3;
  Eigen::VectorXd candidates; // interior candidate knots, increasing (closed: in [0, 1), on the circle)
  bool closed = false;        // a periodic spline of period 1
};

// What is asked: a penalty, or a bound on the max or RMS error.
struct Goal
{
  double lambda = 0;
  std::optional<double> max_error, rms_error;
  bool is_bound() const { return max_error || rms_error; }
  bool met(const Spline_fit& f) const
  {
    return max_error ? f.max_error <= *max_error : (!rms_error || f.rms_error <= *rms_error);
  }
};

// The least-squares fit on the kept candidates, with its errors (the finish of every algorithm):
// the max and total always, the error of every sample when `kept` (the entry points fill them
// in for the answer if an algorithm's trial fit did not).
enum class Sample_errors { kept, summary_only };
Spline_fit finish(const Problem& p, const std::vector<std::size_t>& kept, double lambda,
                  Sample_errors detail = Sample_errors::kept);

// Rounding-level ties.  On a symmetric curve many choices (which knot to remove, where a knot
// slides) cost the same in exact arithmetic, and a moved or scaled copy of the data rounds
// them into another order: a choice by the computed order alone makes the fit depend on the
// motion.  Values closer than a tolerance are taken as equal and chosen among by index.
//
// The samples' spread: the largest squared distance from their centroid (the same for a moved
// copy, s^2 times it for a copy scaled by s).
inline double squared_spread(const Eigen::MatrixXd& samples)
{
  if(samples.rows() == 0) return 0;
  const Eigen::RowVectorXd centre = samples.colwise().mean();
  return (samples.rowwise() - centre).rowwise().squaredNorm().maxCoeff();
}
// The tolerance on a squared error summed over w samples is 1e-11 w times the spread: each
// term is at most the spread on centred data (fit_spline centres it), rounded at some 1e-16 of
// it.  Measured (test Invariance.SymmetricClosedCurvesUnderMotionAndScale, copies moved by 300
// times the size and scaled by 1e3 and 1e-3): 1e-15 is enough there, 1e-17 is not; 1e-11 leaves
// room for longer sums and worse-conditioned solves, and stays far below any difference that
// matters for a bound (a max error of 1e-4 of the size is a squared error of 1e-8 of the spread
// a sample).  A copy moved 3e5 times its size away is not the same data at this level (its
// coordinates are rounded at 1e-16 of 3e5): there the ties break again.
constexpr double squared_error_tie = 1e-11;
// Indices 0 .. size - 1 by increasing value; values that follow within a tolerance of each
// other in that order (a chain; the larger of the two values' tolerances) are one group, taken
// in index order.
inline std::vector<std::size_t> order_with_ties(const std::vector<double>& value, const std::vector<double>& tolerance)
{
  std::vector<std::size_t> order(value.size());
  for(std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return value[a] < value[b]; });
  for(std::size_t first = 0; first < order.size();) {
    std::size_t last = first + 1;
    for(; last < order.size(); ++last) {
      const std::size_t a = order[last - 1], b = order[last];
      if(value[b] - value[a] > std::max(tolerance[a], tolerance[b])) break;
    }
    std::sort(order.begin() + std::ptrdiff_t(first), order.begin() + std::ptrdiff_t(last));
    first = last;
  }
  return order;
}

// Strictly better for the goal: penalty mode by objective; bound mode by meeting the bound,
// then fewer knots, then smaller squared error.
bool better(const Spline_fit& a, const Spline_fit& b, const Goal& goal);

// The problem restricted to the candidates `kept` (increasing indices into p.candidates).
Problem restricted(const Problem& p, const std::vector<std::size_t>& kept);
// A start for the heuristics on many candidates: knots refined coarse to fine until every span
// meets the goal tightened by `margin` (coarse_start.cpp).
std::vector<std::size_t> coarse_start(const Problem& p, const Goal& goal, double margin);

// The algorithms (each returns a finished fit).
Spline_fit penalty_decomposition(const Problem& p, double lambda);
// Greedy removal from `start` (indices into the candidates; every candidate if null).
Spline_fit greedy_removal(const Problem& p, const Goal& goal, const std::vector<std::size_t>* start = nullptr);
Spline_fit dynamic_programming(const Problem& p, const Goal& goal); // degree 1, open or closed
// Its closed curves (exact_optimum_closed.cpp): refused (Invalid_input) past `work_limit` path
// comparisons or as many sample visits, 5-10 s each.
constexpr std::size_t closed_dp_work_limit = std::size_t(1) << 29;
Spline_fit closed_dynamic_programming(const Problem& p, const Goal& goal, std::size_t work_limit = closed_dp_work_limit);
Spline_fit brute_force(const Problem& p, const Goal& goal);
// Degree 1: knots slid to better candidates and removed while the goal allows
// (knot_relocation.cpp); other degrees, and closed curves of fewer than five knots, are
// returned as they are.
Spline_fit relocate_and_remove(const Problem& p, const Goal& goal, Spline_fit fit);

} // namespace internal
} // namespace Spline_approximation
} // namespace CGAL

#endif
