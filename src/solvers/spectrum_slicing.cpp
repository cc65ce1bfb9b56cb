// Copyright (c) 2026 The Tangent_vector_fields authors.
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
// The windows of one chain follow each other (each locks out its neighbour's vectors
// and carries the pairs it found beyond its end into the next).  A large request is
// cut at an inertia-counted split into chains that run at once, one per core, each
// with one BLAS thread: the sparse factorisations and solves are sequential code, and
// the orthogonalisation is memory-bound products of a tall basis with a block of 4
// columns, which a second BLAS thread barely speeds up.

#define EIGEN_USE_BLAS

#include <CGAL/Tangent_vector_fields/internal/Lanczos_window.h>
#include <CGAL/Tangent_vector_fields/internal/Standard_eigenproblem.h>
#include <CGAL/Tangent_vector_fields/Sparse_ldlt_solver.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <Eigen/Dense>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <functional>
#include <limits>
#include <mutex>
#include <random>
#include <sstream>
#include <thread>
#include <vector>

// OpenBLAS's thread count, where OpenBLAS is the BLAS (weak: absent with another BLAS).
extern "C" void openblas_set_num_threads(int) __attribute__((weak));
extern "C" int openblas_get_num_threads(void) __attribute__((weak));

namespace CGAL {
namespace Tangent_vector_fields {
namespace internal {

namespace {

typedef Eigen::SparseMatrix<double> Sparse_matrix;

// Thrown inside a chain when another chain failed: its own work is of no use any more.
struct Abandoned
{
};

// What the chains share while they run: converged counts for the progress report,
// and a flag that stops every chain once one has failed.
struct Chain_monitor
{
  std::vector<std::atomic<int>> converged;
  std::atomic<bool> abandon{false};
  int wanted = 0;
  std::function<void()> report; // set when the chain runs on the caller's thread
  explicit Chain_monitor(int chains) : converged(chains) {}
  int total() const
  {
    int t = 0;
    for(const auto& c : converged) t += c.load();
    return std::min(t, wanted);
  }
};

// The shifted matrix A - sigma D and its LDL^T, one per chain (a factor is not shared
// between threads); the fill-reducing analysis is made once, for every chain.
struct Shifted_factor
{
  const Standard_eigenproblem& p;
  Sparse_matrix K;
  Sparse_ldlt_solver solver;
  Shifted_factor(const Standard_eigenproblem& problem, const Sparse_ldlt_solver& analysis) : p(problem)
  {
    solver.copy_analysis(analysis);
  }
  int factor_at(double sigma)
  {
    K = p.A;
    K.diagonal() -= sigma * p.d;
    solver.factor(K, "the shifted matrix of the eigenproblem");
    return solver.negative_pivots();
  }
};

// A chain of windows: from `lo` (with `below_lo` eigenvalues, kernel included, at or
// below it) either up to `limit`, whose inertia `below_limit` is known, or -- with an
// infinite limit -- until `count` pairs above `lo` are found.
struct Chain
{
  double lo = 0;
  int below_lo = 0;
  int count = 0;
  double limit = std::numeric_limits<double>::infinity();
  int below_limit = 0;
  double density = 1; // estimated eigenvalues per unit of lambda
  std::uint64_t seed = 1;
  // Results.
  Vector_store store; // the vectors of `found`
  Ritz_set found;
  double end = 0;    // every eigenvalue in (lo, end] is in `found`
  int below_end = 0; // inertia at `end`
  int applications = 0, basis_used = 0;
};

void run_chain(const Standard_eigenproblem& p, const Sparse_ldlt_solver& analysis, Chain& chain,
               const Eigensolver_options& options, Chain_monitor& monitor, int index)
{
  const Eigen::Index n = p.A.rows();
  const int c = static_cast<int>(p.kernel.cols());
  const double total_mass = p.d.sum();
  const int per_window = std::max(options.block_size, options.slice_size);
  const bool bounded = chain.limit < std::numeric_limits<double>::infinity();
  double density = chain.density;
  Shifted_factor shifted(p, analysis);
  Lanczos_workspace space;
  std::mt19937_64 generator(chain.seed);
  Ritz_set& found = chain.found;
  Ritz_set carry;
  double lo = chain.lo;
  int below_lo = chain.below_lo;
  while(static_cast<int>(found.size()) < chain.count)
  {
    if(monitor.abandon) throw Abandoned();
    const int remaining = chain.count - static_cast<int>(found.size());
    double hi = 0;
    int below = 0;
    if(bounded && remaining <= per_window + per_window / 2)
    {
      hi = chain.limit; // the last window of a bounded chain: its count is known
      below = chain.below_limit;
    }
    else
    {
      const int step = remaining <= per_window + per_window / 2 ? remaining + std::max(2, remaining / 20) : per_window;
      hi = lo + step / density;
      for(int attempt = 0;; ++attempt)
      {
        if(bounded && hi >= chain.limit)
        {
          hi = chain.limit;
          below = chain.below_limit;
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
    // The shift of the run in the middle, so both ends of the window are equally
    // far -- except for the first window: the residual floor of a Ritz pair grows like
    // |lambda - sigma| / lambda, and the lowest eigenvalues need a shift next to them
    // (just below 0; measured: a shift at the middle of (0, hi] left them at 1e-10).
    Window w{lo, hi, 0, hi == chain.limit ? hi : hi + 0.5 * (hi - lo), lo == 0 ? -1e-2 / total_mass : 0.5 * (lo + hi)};
    // Lock the found vectors near the window (and the carried ones) out of the run.
    std::vector<const double*> lock;
    const double reach = lo - 0.5 * (hi - lo);
    for(const Ritz_pair& pair : found)
      if(pair.value > reach) lock.push_back(pair.data);
    int carried_in_window = 0;
    for(const Ritz_pair& pair : carry)
    {
      lock.push_back(pair.data);
      if(pair.value <= hi) ++carried_in_window;
    }
    auto locked = Lanczos_workspace::columns(space.locked, n, static_cast<Eigen::Index>(lock.size()), per_window);
    for(Eigen::Index i = 0; i < locked.cols(); ++i)
      locked.col(i) = Eigen::Map<const Eigen::VectorXd>(lock[static_cast<std::size_t>(i)], n);
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
      monitor.converged[index] = std::min(chain.count, found_before + in_window);
      if(monitor.report) monitor.report();
    };
    if(w.wanted > 0) // else the carried pairs fill the window: no run, no factorisation
    {
      shifted.factor_at(w.sigma);
      if(shifted.solver.smallest_relative_pivot() < 1e-14) shifted.factor_at(w.sigma += 1e-6 * (hi - lo));
      auto run_window = [&](const Eigensolver_options& o) {
        window = Ritz_set();
        new_carry = Ritz_set();
        lanczos_window(p, shifted.K, shifted.solver, w, locked, o, generator, space, window, new_carry,
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
    // Move the carried pairs of this window to `found`; keep the others.
    Ritz_set still_carried;
    for(Ritz_pair& pair : carry) (pair.value <= hi ? found : still_carried).push_back(std::move(pair));
    for(Ritz_pair& pair : window) found.push_back(std::move(pair));
    for(Ritz_pair& pair : new_carry) still_carried.push_back(std::move(pair));
    carry = std::move(still_carried);
    lo = hi;
    below_lo = below;
    monitor.converged[index] = std::min(chain.count, static_cast<int>(found.size()));
    if(monitor.report) monitor.report();
  }
  chain.end = lo;
  chain.below_end = below_lo;
}

// A shift with about `target` eigenvalues (kernel excluded) below it, counted exactly
// by the inertia; returns that count.  Weyl's law gives the first guess, each further
// one rescales by the count found.
int split_point(const Standard_eigenproblem& p, const Sparse_ldlt_solver& analysis, int target, double& density,
                double& split)
{
  const int c = static_cast<int>(p.kernel.cols());
  Shifted_factor shifted(p, analysis);
  split = target / density;
  int below = 0;
  for(int attempt = 0; attempt < 6; ++attempt)
  {
    below = shifted.factor_at(split) - c;
    if(shifted.solver.smallest_relative_pivot() < 1e-14)
    {
      split *= 1 + 1e-6;
      continue;
    }
    if(below > 0) density = below / split;
    if(below > 0 && std::abs(below - target) <= target / 5) break;
    split = below > 0 ? target / density : 2 * split;
  }
  return below;
}

// Pairs on both sides of a split were found by different chains, which did not lock
// each other's vectors out: a Rayleigh-Ritz step on the pairs near the split makes
// them orthonormal again (close pairs across the split are otherwise orthogonal only
// to their residual divided by their gap).
void join_at(const Standard_eigenproblem& p, double split, double tolerance, Ritz_set& pairs)
{
  std::vector<std::size_t> near;
  for(std::size_t i = 0; i < pairs.size(); ++i)
    if(std::abs(pairs[i].value - split) <= 0.05 * split) near.push_back(i);
  if(near.size() < 2) return;
  const Eigen::Index n = p.d.size(), k = static_cast<Eigen::Index>(near.size());
  Eigen::MatrixXd Y(n, k);
  for(Eigen::Index j = 0; j < k; ++j) Y.col(j) = pairs[near[j]].vector();
  const Eigen::MatrixXd X = p.inv_sqrt_d.asDiagonal() * Y;
  Eigen::MatrixXd a = X.transpose() * (p.A * X), m = Y.transpose() * Y;
  a = (a + a.transpose()).eval() / 2;
  m = (m + m.transpose()).eval() / 2;
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> small(a, m);
  if(small.info() != Eigen::Success) throw Numerical_failure("spectrum slicing: joining two chains failed");
  const Eigen::MatrixXd rotated = Y * small.eigenvectors();
  Eigen::VectorXd residuals, tolerances;
  p.residuals_of_standard(small.eigenvalues(), rotated, tolerance, residuals, &tolerances);
  for(Eigen::Index j = 0; j < k; ++j)
  {
    Ritz_pair& pair = pairs[near[j]];
    pair.value = small.eigenvalues()[j];
    pair.vector() = rotated.col(j);
    pair.residual = residuals[j];
    pair.tolerance = tolerances[j];
  }
}

// Sets OpenBLAS to one thread while the chains run, and back afterwards.
struct One_blas_thread
{
  int before = 0;
  One_blas_thread()
  {
    if(openblas_get_num_threads && openblas_set_num_threads)
    {
      before = openblas_get_num_threads();
      openblas_set_num_threads(1);
    }
  }
  ~One_blas_thread()
  {
    if(before > 0) openblas_set_num_threads(before);
  }
};

} // namespace

Eigenpairs sliced_eigenpairs(const Standard_eigenproblem& p, int count, const Eigensolver_options& options)
{
  const Eigen::Index n = p.A.rows();
  const int c = static_cast<int>(p.kernel.cols());
  const int per_window = std::max(options.block_size, options.slice_size);
  // Weyl's law on a surface of area |D|: about |D| lambda / (4 pi) eigenvalues below lambda.
  double density = p.d.sum() / (4 * M_PI);
  const unsigned cores = options.threads > 0 ? static_cast<unsigned>(options.threads)
                                             : std::max(1u, std::thread::hardware_concurrency());
  // A chain per core, each at least a window long.
  const int chains = static_cast<int>(std::min<unsigned>(cores, std::max(1, count / per_window)));

  // Each window factors A - sigma D twice: an ordering that costs more to find but
  // factors and solves faster pays on large problems.
  Sparse_ldlt_solver analysis;
  analysis.analyze(p.A, true);
  std::vector<Chain> chain(1);
  chain[0].below_lo = c;
  chain[0].count = count;
  chain[0].density = density;
  chain[0].seed = options.seed;
  std::vector<double> splits;
  for(int k = 1; k < chains; ++k)
  {
    double split = 0;
    const int below = split_point(p, analysis, count * k / chains, density, split);
    const int previous = chain.back().below_lo - c;
    if(below <= previous || below >= count) continue; // no use: leave it to the chain before
    Chain& last = chain.back();
    last.limit = split;
    last.below_limit = below + c;
    last.count = below - previous;
    Chain next;
    next.lo = split;
    next.below_lo = below + c;
    next.count = count - below;
    next.density = density;
    next.seed = options.seed + 0x9e3779b97f4a7c15ull * static_cast<std::uint64_t>(k);
    chain.push_back(std::move(next));
    splits.push_back(split);
  }
  for(Chain& ch : chain) ch.density = density;

  Chain_monitor monitor(static_cast<int>(chain.size()));
  monitor.wanted = count;
  std::vector<std::exception_ptr> failure(chain.size());
  auto run = [&](std::size_t k) {
    try
    {
      run_chain(p, analysis, chain[k], options, monitor, static_cast<int>(k));
    }
    catch(const Abandoned&)
    {
    }
    catch(...)
    {
      failure[k] = std::current_exception();
      monitor.abandon = true;
    }
  };
  if(chain.size() == 1)
  {
    // One chain runs on the caller's thread and reports after every Rayleigh-Ritz step.
    if(options.progress) monitor.report = [&] { options.progress({monitor.total(), count, 0}); };
    run(0);
  }
  else
  {
    // The caller's thread only waits and reports progress: the callback is never
    // called from another thread, and a callback that throws (a cancel) stops all.
    One_blas_thread one_thread;
    std::mutex mutex;
    std::condition_variable done_signal;
    std::size_t done = 0;
    std::vector<std::thread> threads;
    for(std::size_t k = 0; k < chain.size(); ++k)
      threads.emplace_back([&, k] {
        run(k);
        std::lock_guard<std::mutex> lock(mutex);
        ++done;
        done_signal.notify_one();
      });
    std::exception_ptr callback_failure;
    {
      std::unique_lock<std::mutex> lock(mutex);
      while(done < chain.size())
      {
        done_signal.wait_for(lock, std::chrono::milliseconds(200));
        if(options.progress && !callback_failure)
        {
          lock.unlock();
          try
          {
            options.progress({monitor.total(), count, 0});
          }
          catch(...)
          {
            callback_failure = std::current_exception();
            monitor.abandon = true;
          }
          lock.lock();
        }
      }
    }
    for(std::thread& t : threads) t.join();
    if(callback_failure) std::rethrow_exception(callback_failure);
  }
  for(const std::exception_ptr& f : failure)
    if(f) std::rethrow_exception(f);

  // Merge the chains; the pairs a chain carried beyond its limit are the next one's.
  Ritz_set found;
  int applications = 0, basis_used = 0;
  for(Chain& ch : chain)
  {
    for(Ritz_pair& pair : ch.found)
      if(pair.value <= ch.limit) found.push_back(std::move(pair));
      else ch.store.release(pair.data); // the next chain's
    ch.found.clear();
    applications += ch.applications;
    basis_used = std::max(basis_used, ch.basis_used);
  }
  for(double split : splits) join_at(p, split, options.tolerance, found);

  // Sort, keep the lowest `count`.  Every pair met its tolerance on its true residual
  // when its window (or the join) accepted it.
  std::vector<int> order(found.size());
  for(std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return found[a].value < found[b].value; });
  if(static_cast<int>(order.size()) < count)
    throw Numerical_failure("spectrum slicing: the chains found " + std::to_string(order.size()) + " of " +
                            std::to_string(count) + " eigenpairs");
  // The peak memory is one copy of the basis (and a block of vectors per chain), not two:
  // the vectors not returned are given back first, the others as they are copied.
  auto release = [&](const Ritz_pair& pair) {
    for(Chain& ch : chain)
      if(ch.store.release(pair.data)) return;
  };
  for(std::size_t i = static_cast<std::size_t>(count); i < order.size(); ++i) release(found[order[i]]);
  Eigenpairs result;
  result.values.resize(count);
  result.residuals.resize(count);
  resize_in_huge_pages(result.vectors, n, count);
  for(int i = 0; i < count; ++i)
  {
    Ritz_pair& pair = found[order[i]];
    if(!(pair.residual <= pair.tolerance))
    {
      std::ostringstream message;
      message << "spectrum slicing: an eigenpair misses the tolerance (residual " << pair.residual << " > "
              << pair.tolerance << ")";
      throw Numerical_failure(message.str());
    }
    result.values[i] = pair.value;
    result.residuals[i] = pair.residual;
    result.vectors.col(i) = p.inv_sqrt_d.cwiseProduct(pair.vector());
    release(pair);
  }
  result.basis_size = basis_used;
  result.operator_applications = applications;
  const Chain& last = chain.back();
  result.completeness.shift = last.end;
  result.completeness.inertia = last.below_end;
  result.completeness.expected = c + static_cast<int>(found.size());
  result.complete_below = static_cast<int>(found.size()) > count ? found[order[count]].value : last.end;
  return result;
}

} // namespace internal
} // namespace Tangent_vector_fields
} // namespace CGAL
