// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Spectrum slicing.  The wanted part of the spectrum is cut into windows (lo, hi].
// An LDL^T factorisation of A - hi D gives, by Sylvester's law, the exact number of
// eigenvalues below hi, so each window's count is known before its run starts; a
// second factorisation, at the window middle, drives a short block shift-and-invert
// Lanczos run that stops once it has found exactly that many: completeness is proved
// window by window.  Orthogonalisation is against the run's own basis (about 3-4x
// the window count with blocks of 4) and the converged vectors next to the window,
// instead of against everything found so far.
//
// This file: a chain of windows (`Slicing_chain.h`), the split points between chains and
// their join; `sliced_eigenpairs.cpp` runs the chains of one or several problems at once.

#include <CGAL/Model_reduction/internal/Slicing_chain.h>
#include <CGAL/Model_reduction/errors.h>

#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <random>
#include <string>
#include <vector>

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace CGAL {
namespace Model_reduction {
namespace internal {

namespace {

// The LDL^T of the shifted matrix A - sigma D, one per chain (a factor is not shared
// between threads); the fill-reducing analysis is made once, for every chain.
template <class Scalar>
struct Shifted_factor
{
  const Basic_standard_eigenproblem<Scalar>& p;
  Basic_sparse_ldlt_solver<Scalar> solver;
  Shifted_factor(const Basic_standard_eigenproblem<Scalar>& problem, const Basic_sparse_ldlt_solver<Scalar>& analysis)
    : p(problem)
  {
    solver.copy_analysis(analysis);
  }
  int factor_at(double sigma)
  {
    solver.factor(p.shifted(sigma), "the shifted matrix of the eigenproblem");
    return solver.negative_pivots();
  }
};

// `join_at` makes the pairs within this relative distance of a split between two chains
// orthonormal again.
constexpr double join_reach = 0.05;

// For vectors returned in float32: rounds the found vectors of `chain` that no window needs
// in double any more, so that the finished part of the basis takes half the memory while the
// rest is solved.  Those are the pairs below both the reach of the window about to run
// (from `lo`; windows lock out only the pairs near them, a rounded one is skipped if a wider
// later window reaches down to it: it lies below that window, which collects only the pairs
// inside it) and the join reach of `lo` (a cut another thread makes lies above the running
// window), and above the join reach of the chain's start.
template <class Scalar>
void round_settled(const Basic_standard_eigenproblem<Scalar>& p, Basic_chain<Scalar>& chain, double lo, double reach)
{
  typedef typename Basic_ritz_pair<Scalar>::Float32 Float32;
  const double below = std::min(reach, (1 - join_reach) * lo), above = (1 + join_reach) * chain.lo;
  for(Basic_ritz_pair<Scalar>& pair : chain.found)
    if(pair.data && pair.value < below && pair.value > above)
    {
      Float32* column = chain.rounded.add_columns(pair.size, 1).front().first;
      Eigen::Map<Eigen::Matrix<Float32, Eigen::Dynamic, 1>>(column, pair.size) =
          p.inv_sqrt_d.cwiseProduct(pair.vector()).template cast<Float32>();
      chain.store.release(pair.data);
      pair.data = nullptr;
      pair.rounded = column;
    }
}

} // namespace

void give_back_freed_heap()
{
#ifdef __GLIBC__
  malloc_trim(0);
#endif
}

template <class Scalar>
void run_chain(const Basic_standard_eigenproblem<Scalar>& p, const Basic_sparse_ldlt_solver<Scalar>& analysis,
               Basic_chain<Scalar>& chain, const Eigensolver_options& options, Chain_monitor& monitor, int index)
{
  typedef Basic_ritz_set<Scalar> Ritz_set;
  const auto start = std::chrono::steady_clock::now();
  const Eigen::Index n = p.A.rows();
  const int c = static_cast<int>(p.kernel.cols());
  const double total_mass = p.d.sum();
  const int per_window = std::max(options.block_size, options.slice_size);
  double density = chain.density;
  Shifted_factor<Scalar> shifted(p, analysis);
  Lanczos_workspace<Scalar> space;
  std::mt19937_64 generator(chain.seed);
  Ritz_set& found = chain.found;
  Ritz_set carry;
  double lo = chain.lo;
  int below_lo = chain.below_lo;
  while(true)
  {
    if(monitor.abandon) throw Abandoned();
    // The end, which another thread may have lowered since the last window.
    double limit = 0;
    int below_limit = 0, count = 0;
    {
      std::lock_guard<std::mutex> lock(chain.mutex);
      limit = chain.limit;
      below_limit = chain.below_limit;
      count = chain.count;
    }
    if(static_cast<int>(found.size()) >= count)
    {
      // All the pairs below the end found short of it (a cut placed in a gap above the
      // window just run): by the inertia, nothing lies between, so the chain ends at its end.
      if(limit < std::numeric_limits<double>::infinity() && below_lo == below_limit) lo = limit;
      break;
    }
    const bool bounded = limit < std::numeric_limits<double>::infinity();
    const int remaining = count - static_cast<int>(found.size());
    double hi = 0;
    int below = 0;
    if(bounded && remaining <= per_window + per_window / 2)
    {
      hi = limit; // the last window of a bounded chain: its count is known
      below = below_limit;
    }
    else
    {
      const int step = remaining <= per_window + per_window / 2 ? remaining + std::max(2, remaining / 20) : per_window;
      hi = lo + step / density;
      for(int attempt = 0;; ++attempt)
      {
        if(bounded && hi >= limit)
        {
          hi = limit;
          below = below_limit;
          break;
        }
        below = shifted.factor_at(hi);
        // A boundary on top of an eigenvalue makes a tiny pivot: move it a little.
        if(shifted.solver.smallest_relative_pivot() < 1e-14 && attempt < 3)
        {
          hi += 1e-6 * (hi - lo);
          continue;
        }
        const int in_window = below - below_lo;
        if(in_window > 2 * per_window && attempt < 6)
        {
          hi = lo + (hi - lo) * per_window / in_window; // density underestimated: shrink
          continue;
        }
        if(in_window == 0 && attempt < 6)
        {
          hi = lo + 2 * (hi - lo);
          continue;
        }
        break;
      }
    }
    if(below > c && hi > 0) density = (below - c) / hi;
    {
      std::lock_guard<std::mutex> lock(chain.mutex);
      if(chain.limit < hi) // cut below this window while it was chosen: end it at the cut
      {
        hi = limit = chain.limit;
        below = chain.below_limit;
        count = chain.count;
      }
      chain.working_hi = hi;
      chain.below_working_hi = below;
      chain.density = density;
    }
    // The shift of the run in the middle, so both ends of the window are equally
    // far -- except for the first window: the residual floor of a Ritz pair grows like
    // |lambda - sigma| / lambda, and the lowest eigenvalues need a shift next to them
    // (just below 0; measured: a shift at the middle of (0, hi] left them at 1e-10).
    Window w{lo, hi, 0, hi == limit ? hi : hi + 0.5 * (hi - lo), lo == 0 ? -1e-2 / total_mass : 0.5 * (lo + hi)};
    // Lock the found vectors near the window (and the carried ones) out of the run.
    std::vector<const Scalar*> lock;
    const double reach = lo - 0.5 * (hi - lo);
    for(const Basic_ritz_pair<Scalar>& pair : found)
      if(pair.value > reach && pair.data) lock.push_back(pair.data);
    if(options.float32_vectors) round_settled(p, chain, lo, reach);
    int carried_in_window = 0;
    for(const Basic_ritz_pair<Scalar>& pair : carry)
    {
      lock.push_back(pair.data);
      if(pair.value <= hi) ++carried_in_window;
    }
    const Locked_columns<Scalar> locked(lock, n);
    // Ritz vectors of one run are orthonormal, of different runs orthogonal to the
    // accuracy of the pairs: no need to orthonormalise them again.
    w.wanted = below - below_lo - carried_in_window;
    if(w.wanted < 0)
      throw Numerical_failure("spectrum slicing: more eigenvalues carried into (" + std::to_string(lo) + ", " +
                              std::to_string(hi) + "] than the inertia count allows");
    Ritz_set window, new_carry;
    const int found_before = static_cast<int>(found.size()) + carried_in_window;
    auto report = [&](int in_window) {
      if(monitor.abandon) throw Abandoned();
      monitor.converged[index] = std::min(count, found_before + in_window);
      if(monitor.report) monitor.report();
    };
    if(w.wanted > 0) // else the carried pairs fill the window: no run, no factorisation
    {
      shifted.factor_at(w.sigma);
      if(shifted.solver.smallest_relative_pivot() < 1e-14) shifted.factor_at(w.sigma += 1e-6 * (hi - lo));
      int attempts = 0;
      auto run_window = [&](const Eigensolver_options& o) {
        // A polish in the attempt before may have left another shift factored.
        if(attempts++ > 0) shifted.factor_at(w.sigma);
        window = Ritz_set();
        new_carry = Ritz_set();
        lanczos_window(p, shifted.solver, w, locked, o, generator, space, window, new_carry,
                       chain.store, chain.applications, chain.basis_used, report);
      };
      // Unrefined solves; a window whose pairs miss their tolerance for want of
      // refinement, and which polishing (`lanczos_window`) does not repair, is run again
      // refined.  The next window starts unrefined again: whether one misses varies from
      // run to run (the bunny's Crouzeix-Raviart problem: no window of 504 pairs, one of
      // 500), and refining the rest of the chain made such a chain 1.2x slower per window
      // (500 pairs: 17.5-18.6 s against 21.4-25.4 s with the rest refined).  Refinement made
      // the vertex problems of the rocker arm and the bunny 1.15-1.2x slower, and they
      // never need it; their Crouzeix-Raviart problems miss by a little in a few windows
      // (solve residuals measured from 1e-11 to 8e-8 relative, varying from solve to solve).
      try
      {
        try
        {
          run_window(options);
        }
        catch(const Inaccurate_solves&)
        {
          w.refine = true;
          run_window(options);
        }
      }
      catch(const Numerical_failure&)
      {
        // A block Lanczos run finds at most `block_size` copies of a repeated
        // eigenvalue quickly (symmetric meshes have multiplicities up to 5 and more):
        // retry the window once with wider blocks (and refined solves).
        Eigensolver_options wider = options;
        wider.block_size = 4 * options.block_size;
        w.refine = true;
        run_window(wider);
      }
    }
    give_back_freed_heap();
    // Move the carried pairs of this window to `found`; keep the others.
    Ritz_set still_carried;
    for(auto& pair : carry) (pair.value <= hi ? found : still_carried).push_back(std::move(pair));
    for(auto& pair : window) found.push_back(std::move(pair));
    for(auto& pair : new_carry) still_carried.push_back(std::move(pair));
    carry = std::move(still_carried);
    lo = hi;
    below_lo = below;
    monitor.converged[index] = std::min(count, static_cast<int>(found.size()));
    if(monitor.report) monitor.report();
  }
  // Pairs carried beyond the end (the next chain's, or beyond the count), and the columns
  // the last window gave back for reuse: their pages would stay resident until the
  // result is copied out.
  for(const auto& pair : carry) chain.store.release(pair.data, false);
  chain.store.discard_kept();
  chain.rounded.discard_kept();
  chain.end = lo;
  chain.below_end = below_lo;
  chain.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Weyl's law gives the first guess, each further one rescales by the count found.
template <class Scalar>
int split_point(const Basic_standard_eigenproblem<Scalar>& p, const Basic_sparse_ldlt_solver<Scalar>& analysis,
                int target, int slack, double& density, double& split)
{
  const int c = static_cast<int>(p.kernel.cols());
  Shifted_factor<Scalar> shifted(p, analysis);
  split = target / density;
  int below = 0;
  for(int attempt = 0, nudges = 0;; ++attempt)
  {
    below = shifted.factor_at(split) - c;
    if(shifted.solver.smallest_relative_pivot() < 1e-14 && nudges++ < 3) // on an eigenvalue: move a little
    {
      split *= 1 + 1e-6;
      continue;
    }
    if(below > 0) density = below / split;
    // The count goes back with the shift it was made at: no move after the last attempt (a
    // move there returned another shift's count where Weyl's guess was far off -- a graph
    // Laplacian's -- and a chain ended at a shift with 50 more eigenvalues below it than said).
    if((below > 0 && std::abs(below - target) <= slack) || attempt >= 5) break;
    split = below > 0 ? target / density : 2 * split;
  }
  return below;
}

template <class Scalar>
double take_over_top(const Basic_standard_eigenproblem<Scalar>& p, const Basic_sparse_ldlt_solver<Scalar>& analysis,
                     Basic_chain<Scalar>& victim, int per_window, Basic_chain<Scalar>& taken)
{
  const double none = std::numeric_limits<double>::quiet_NaN();
  const int c = static_cast<int>(p.kernel.cols());
  int below_hi = 0, left = 0;
  double density = 1;
  {
    std::lock_guard<std::mutex> lock(victim.mutex);
    if(!victim.running) return none;
    below_hi = victim.below_working_hi;
    left = victim.below_end_wanted() - below_hi;
    density = victim.density;
  }
  if(left < 2 * per_window) return none;
  // Counted without the lock: the victim goes on meanwhile, and may pass the shift.
  double split = 0;
  const int below = c + split_point(p, analysis, below_hi - c + left / 2, left / 6, density, split);
  std::lock_guard<std::mutex> lock(victim.mutex);
  const int end = victim.below_end_wanted();
  if(!victim.running || !(split > victim.working_hi) || !(split < victim.limit) ||
     below - victim.below_working_hi < per_window / 2 || end - below < per_window / 2)
    return none;
  taken.lo = split;
  taken.below_lo = below;
  taken.count = end - below;
  taken.limit = victim.limit;
  taken.below_limit = victim.below_limit;
  taken.density = density;
  victim.limit = split;
  victim.below_limit = below;
  victim.count = below - victim.below_lo;
  return split;
}

// Pairs on both sides of a split were found by different chains, which did not lock
// each other's vectors out: a Rayleigh-Ritz step on the pairs near the split makes
// them orthonormal again (close pairs across the split are otherwise orthogonal only
// to their residual divided by their gap).  The vectors are read and rotated where the
// chains keep them, a band of rows at a time: copies of them (the vectors, their images
// and the rotated ones: about 4 x 25 vectors, 0.4 GB by count at the armadillo's 519k edges)
// came on top of the whole basis held when the chains end.
template <class Scalar>
void join_at(const Basic_standard_eigenproblem<Scalar>& p, double split, double tolerance, Basic_ritz_set<Scalar>& pairs)
{
  typedef Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> Matrix;
  std::vector<std::size_t> near;
  for(std::size_t i = 0; i < pairs.size(); ++i)
    if(std::abs(pairs[i].value - split) <= join_reach * split) near.push_back(i);
  if(near.size() < 2) return;
  for(std::size_t i : near) // `round_settled` keeps these double
    if(!pairs[i].data) throw Numerical_failure("spectrum slicing: a vector needed to join two chains was rounded");
  const Eigen::Index n = p.d.size(), k = static_cast<Eigen::Index>(near.size());
  auto y = [&](Eigen::Index j) { return pairs[near[static_cast<std::size_t>(j)]].vector(); };
  const Eigen::Index band = 1024;
  Matrix rows;
  auto gather = [&](Eigen::Index r0, Eigen::Index h) {
    rows.resize(h, k);
    for(Eigen::Index j = 0; j < k; ++j) rows.col(j) = y(j).segment(r0, h);
  };
  // a = Y^H D^-1/2 A D^-1/2 Y and m = Y^H Y, the images 8 columns at a time.
  Matrix a = Matrix::Zero(k, k), m = Matrix::Zero(k, k), AY;
  Eigen::Matrix<Scalar, Eigen::Dynamic, 1> x(n);
  for(Eigen::Index j0 = 0; j0 < k; j0 += 8)
  {
    const Eigen::Index w = std::min<Eigen::Index>(8, k - j0);
    AY.resize(n, w);
    for(Eigen::Index j = 0; j < w; ++j)
    {
      x = p.inv_sqrt_d.cwiseProduct(y(j0 + j));
      AY.col(j).noalias() = p.A * x;
      AY.col(j) = p.inv_sqrt_d.cwiseProduct(AY.col(j));
    }
    for(Eigen::Index r0 = 0; r0 < n; r0 += band)
    {
      const Eigen::Index h = std::min(band, n - r0);
      gather(r0, h);
      a.middleCols(j0, w).noalias() += rows.adjoint() * AY.middleRows(r0, h);
      if(j0 == 0) m.noalias() += rows.adjoint() * rows;
    }
  }
  a = (a + a.adjoint()).eval() / 2;
  m = (m + m.adjoint()).eval() / 2;
  Eigen::GeneralizedSelfAdjointEigenSolver<Matrix> small(a, m);
  if(small.info() != Eigen::Success) throw Numerical_failure("spectrum slicing: joining two chains failed");
  const Matrix& E = small.eigenvectors();
  Matrix turned;
  for(Eigen::Index r0 = 0; r0 < n; r0 += band)
  {
    const Eigen::Index h = std::min(band, n - r0);
    gather(r0, h);
    turned.noalias() = rows * E;
    for(Eigen::Index j = 0; j < k; ++j) y(j).segment(r0, h) = turned.col(j);
  }
  Eigen::VectorXd value(1), residual, reachable;
  for(Eigen::Index j = 0; j < k; ++j)
  {
    Basic_ritz_pair<Scalar>& pair = pairs[near[static_cast<std::size_t>(j)]];
    value[0] = small.eigenvalues()[j];
    p.residuals_of_standard(value, pair.vector(), tolerance, residual, &reachable);
    pair.value = value[0];
    pair.residual = residual[0];
    pair.tolerance = reachable[0];
  }
}

#define CGAL_MODEL_REDUCTION_INSTANTIATE_SLICING_CHAIN(Scalar)                                                 \
  template void run_chain(const Basic_standard_eigenproblem<Scalar>&, const Basic_sparse_ldlt_solver<Scalar>&,     \
                          Basic_chain<Scalar>&, const Eigensolver_options&, Chain_monitor&, int);                \
  template int split_point(const Basic_standard_eigenproblem<Scalar>&, const Basic_sparse_ldlt_solver<Scalar>&,    \
                           int, int, double&, double&);                                                          \
  template double take_over_top(const Basic_standard_eigenproblem<Scalar>&,                                      \
                                const Basic_sparse_ldlt_solver<Scalar>&, Basic_chain<Scalar>&, int,              \
                                Basic_chain<Scalar>&);                                                           \
  template void join_at(const Basic_standard_eigenproblem<Scalar>&, double, double, Basic_ritz_set<Scalar>&);
CGAL_MODEL_REDUCTION_INSTANTIATE_SLICING_CHAIN(double)
CGAL_MODEL_REDUCTION_INSTANTIATE_SLICING_CHAIN(std::complex<double>)
#undef CGAL_MODEL_REDUCTION_INSTANTIATE_SLICING_CHAIN

} // namespace internal
} // namespace Model_reduction
} // namespace CGAL
