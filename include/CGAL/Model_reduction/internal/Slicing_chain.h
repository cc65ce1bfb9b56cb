// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_MODEL_REDUCTION_INTERNAL_SLICING_CHAIN_H
#define CGAL_MODEL_REDUCTION_INTERNAL_SLICING_CHAIN_H

/// \file Slicing_chain.h
/// A chain of spectrum-slicing windows: consecutive windows of one eigenproblem, each
/// locking out its neighbour's vectors and carrying the pairs it found beyond its end into
/// the next.  A request is cut at inertia-counted split points into chains that run at once;
/// a thread that runs out of chains takes over the top of a running one's range.

#include <CGAL/Model_reduction/Sparse_ldlt_solver.h>
#include <CGAL/Model_reduction/internal/Lanczos_window.h>
#include <CGAL/Model_reduction/internal/Standard_eigenproblem.h>

#include <atomic>
#include <cstdint>
#include <functional>
#include <limits>
#include <mutex>
#include <vector>

namespace CGAL {
namespace Model_reduction {
namespace internal {

/// Thrown inside a chain when another one failed: its own work is of no use any more.
struct Abandoned
{
};

/// What the chains share while they run: converged counts for the progress report, and a
/// flag that stops every chain once one has failed.
struct Chain_monitor
{
  std::vector<std::atomic<int>> converged; ///< per chain, over all the problems of a solve
  std::atomic<bool> abandon{false};
  std::function<void()> report; ///< set when the chains run on the caller's thread
  explicit Chain_monitor(std::size_t chains) : converged(chains) {}
  int total() const
  {
    int t = 0;
    for(const auto& c : converged) t += c.load();
    return t;
  }
};

/// A chain of windows: from `lo` (with `below_lo` eigenvalues, kernel included, at or below
/// it) either up to `limit`, whose inertia `below_limit` is known, or -- with an infinite
/// limit -- until `count` pairs above `lo` are found.  While it runs, another thread may
/// lower its end (`limit`, `below_limit`, `count`) to a shift above the window being run
/// (`take_over_top`); `mutex` guards those fields, `working_hi` and `density`.
template <class Scalar>
struct Basic_chain
{
  double lo = 0;
  int below_lo = 0;
  int count = 0;
  double limit = std::numeric_limits<double>::infinity();
  int below_limit = 0;
  double density = 1; ///< estimated eigenvalues per unit of lambda
  std::uint64_t seed = 1;
  // Results.
  Column_store<Scalar> store;   ///< the double vectors of `found`
  Column_store<typename Float32_of<Scalar>::type> rounded; ///< those rounded to float32 (`Basic_ritz_pair::rounded`)
  Basic_ritz_set<Scalar> found;
  double end = 0;    ///< every eigenvalue in (lo, end] is in `found`
  int below_end = 0; ///< inertia at `end`
  int applications = 0, basis_used = 0;
  double seconds = 0; ///< thread time the chain took
  // Shared while the chain runs.
  std::mutex mutex;
  bool running = false;
  double working_hi = 0;    ///< top of the window being run (or `lo` before the first)
  int below_working_hi = 0; ///< its inertia, kernel included

  /// Eigenvalues (kernel included) at or below the chain's end: `limit`'s inertia, or the
  /// index it counts up to.
  int below_end_wanted() const { return below_lo + count; }
};
typedef Basic_chain<double> Chain;

/// Gives the calling thread's freed heap memory back to the system (glibc; elsewhere
/// nothing).  Where the process keeps freed memory (`keep_freed_memory`, as the tool and the
/// benches do), a thread's heap otherwise keeps what a window freed -- a polish's
/// factorisation and blocks, about 60 MB at 104k unknowns -- and a chain's solves' blocks and
/// shifted matrices.  Called after every window and every chain: bench peaks fell from 1.27 to
/// 1.15 GB (bunny, per chain), then driver peaks from 914 to 830 MiB (bunny's two problems,
/// per window).
void give_back_freed_heap();

/// Runs `chain` of problem `p` (`analysis`: the fill-reducing analysis of its `A`), reporting
/// its converged count as `monitor.converged[index]`.
/// \throws Abandoned once `monitor.abandon` is set, Numerical_failure.
template <class Scalar>
void run_chain(const Basic_standard_eigenproblem<Scalar>& p, const Basic_sparse_ldlt_solver<Scalar>& analysis,
               Basic_chain<Scalar>& chain, const Eigensolver_options& options, Chain_monitor& monitor, int index);

/// A shift with `target` eigenvalues (kernel excluded), give or take `slack`, below it,
/// counted exactly by the inertia; returns the count at the shift it stopped at, `split` (after
/// at most six factorisations, and three more if shifts fall on eigenvalues).  Starts from
/// `density` (eigenvalues per unit of lambda) and updates it from the counts found.
template <class Scalar>
int split_point(const Basic_standard_eigenproblem<Scalar>& p, const Basic_sparse_ldlt_solver<Scalar>& analysis,
                int target, int slack, double& density, double& split);

/// Lowers the end of `victim`, a running chain of problem `p`, to an inertia-counted shift
/// about halfway through what remains of its range above the window it is running, and
/// makes `taken` (a new chain) the rest: from that shift to the victim's old end.  Both then
/// run at once.  `per_window` is the window size; a victim with less than two windows left
/// is not cut.  Returns the shift, or NaN if nothing was taken (the victim ran on past the
/// shift while it was counted, or too little was left).
template <class Scalar>
double take_over_top(const Basic_standard_eigenproblem<Scalar>& p, const Basic_sparse_ldlt_solver<Scalar>& analysis,
                     Basic_chain<Scalar>& victim, int per_window, Basic_chain<Scalar>& taken);

/// Gives the vector of `pair` back, pages included, to the store of `chain` that holds it;
/// false if neither does.
template <class Scalar>
bool release_vector(Basic_chain<Scalar>& chain, const Basic_ritz_pair<Scalar>& pair)
{
  return pair.data ? chain.store.release(pair.data, false) : chain.rounded.release(pair.rounded, false);
}

/// Rayleigh-Ritz on the pairs near `split`, found by two chains that did not lock each other's
/// vectors out: makes them orthonormal again.
template <class Scalar>
void join_at(const Basic_standard_eigenproblem<Scalar>& p, double split, double tolerance, Basic_ritz_set<Scalar>& pairs);

} // namespace internal
} // namespace Model_reduction
} // namespace CGAL

#endif
