// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Spectrum slicing of one or several eigenproblems on one pool of threads.  Each request
// is cut at inertia-counted split points into chains of windows (`Slicing_chain.h`); the
// chains of all the requests are queued, largest first, and each thread takes the next one
// as it comes free.  With one problem cut into one chain per core, a chain that needed
// more work (the lowest window, a rerun with refined solves) left the other core idle: on
// the bunny's Crouzeix-Raviart problem one chain took 22.8 s and the other 17.9 s.  Solving
// the basis's vertex and edge problems together in one queue fills most of that time; what
// is left is the end, when a thread finds the queue empty while another still has several
// windows to run (bunny: 5 s of 27 with a vertex chain taken just before the other thread
// finished).  That thread then takes over the top half of the range the busiest chain has
// left (`take_over_top`), at the price of one factorisation for the inertia at the cut.
//
// Each thread runs with one BLAS thread: the sparse factorisations and solves are
// sequential code, and the orthogonalisation is memory-bound products of a tall basis
// with a block of 4 columns, which a second BLAS thread barely speeds up.

#include <CGAL/Model_reduction/internal/Slicing_chain.h>
#include <CGAL/Model_reduction/errors.h>
#include <CGAL/Model_reduction/internal/One_blas_thread.h>

#include <Eigen/Dense>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <limits>
#include <mutex>
#include <sstream>
#include <thread>
#include <vector>

namespace CGAL {
namespace Model_reduction {
namespace internal {

namespace {

// Runs `tasks` on up to `threads` threads, each taking the next task in the list as it
// comes free, and then what `more` gives it (none: the thread ends).  The caller's thread
// only waits and calls `report` (so the progress callback is never called from another
// thread, and one that throws -- a cancel -- stops all); with one thread or one task, the
// tasks run on the caller's thread and report through `monitor.report` after every
// Rayleigh-Ritz step.  Rethrows the first failure.
void run_tasks(const std::vector<std::function<void()>>& tasks, unsigned threads, Chain_monitor& monitor,
               const std::function<void()>& report, const std::function<std::function<void()>()>& more = nullptr)
{
  std::exception_ptr failure;
  std::mutex mutex;
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    while(!monitor.abandon)
    {
      const std::size_t i = next++;
      try
      {
        if(i < tasks.size()) tasks[i]();
        else if(const std::function<void()> task = more ? more() : nullptr) task();
        else return;
      }
      catch(const Abandoned&)
      {
      }
      catch(...)
      {
        std::lock_guard<std::mutex> lock(mutex);
        if(!failure) failure = std::current_exception();
        monitor.abandon = true;
      }
    }
  };
  const unsigned workers = static_cast<unsigned>(std::min<std::size_t>(threads, tasks.size()));
  if(workers <= 1)
  {
    monitor.report = report;
    work();
    monitor.report = nullptr;
  }
  else
  {
    One_blas_thread one_thread;
    std::condition_variable done_signal;
    unsigned done = 0;
    std::vector<std::thread> pool;
    for(unsigned k = 0; k < workers; ++k)
      pool.emplace_back([&] {
        work();
        std::lock_guard<std::mutex> lock(mutex);
        ++done;
        done_signal.notify_one();
      });
    std::unique_lock<std::mutex> lock(mutex);
    while(done < workers)
    {
      done_signal.wait_for(lock, std::chrono::milliseconds(200));
      if(report && !failure)
      {
        lock.unlock();
        try
        {
          report();
        }
        catch(...)
        {
          lock.lock();
          if(!failure) failure = std::current_exception();
          monitor.abandon = true;
          continue;
        }
        lock.lock();
      }
    }
    lock.unlock();
    for(std::thread& t : pool) t.join();
  }
  if(failure) std::rethrow_exception(failure);
}

// One request while it is solved: its analysis, split points and chains.
template <class Scalar>
struct Slicing
{
  const Basic_standard_eigenproblem<Scalar>* p;
  int count;
  int pieces = 1;     // chains wanted
  double density = 1; // Weyl's estimate, eigenvalues per unit of lambda
  Basic_sparse_ldlt_solver<Scalar> analysis;
  std::vector<double> split, split_density;
  std::vector<int> split_below; // eigenvalues below each split (kernel excluded)
  std::vector<double> splits;   // those used, between consecutive chains
  std::deque<Basic_chain<Scalar>> chains; // a deque: a chain taken over is added while the others run
};

// The chains of `s` from its split points: splits that do not raise the count (two
// estimates on top of each other) or reach `count` are left to the chain before.
template <class Scalar>
void make_chains(Slicing<Scalar>& s, std::uint64_t seed)
{
  const int c = static_cast<int>(s.p->kernel.cols());
  s.chains.emplace_back();
  s.chains[0].below_lo = c;
  s.chains[0].count = s.count;
  s.chains[0].seed = seed;
  std::vector<std::size_t> order(s.split.size());
  for(std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return s.split[a] < s.split[b]; });
  // The density the lowest split measured is a better first guess than Weyl's law.
  s.chains[0].density = order.empty() ? s.density : s.split_density[order[0]];
  for(std::size_t k : order)
  {
    const int below = s.split_below[k];
    Basic_chain<Scalar>& last = s.chains.back();
    const int previous = last.below_lo - c;
    if(below <= previous || below >= s.count) continue;
    last.limit = s.split[k];
    last.below_limit = below + c;
    last.count = below - previous;
    Basic_chain<Scalar>& next = s.chains.emplace_back();
    next.lo = s.split[k];
    next.below_lo = below + c;
    next.count = s.count - below;
    next.density = s.split_density[k];
    next.seed = seed + 0x9e3779b97f4a7c15ull * static_cast<std::uint64_t>(s.chains.size());
    s.splits.push_back(s.split[k]);
  }
}

// The lowest `count` pairs found by the chains of `s`, joined at the splits and checked.
template <class Scalar>
Basic_eigenpairs<Scalar> merge(Slicing<Scalar>& s, const Eigensolver_options& options)
{
  typedef typename Basic_eigenpairs<Scalar>::Float32_matrix::Scalar Float32;
  const Basic_standard_eigenproblem<Scalar>& p = *s.p;
  const Eigen::Index n = p.A.rows();
  const int c = static_cast<int>(p.kernel.cols());
  const int count = s.count;
  // The pairs a chain carried beyond its limit are the next one's.
  Basic_ritz_set<Scalar> found;
  Basic_eigenpairs<Scalar> result;
  for(Basic_chain<Scalar>& ch : s.chains)
  {
    for(Basic_ritz_pair<Scalar>& pair : ch.found)
      if(pair.value <= ch.limit) found.push_back(std::move(pair));
      else release_vector(ch, pair);
    ch.found.clear();
    result.operator_applications += ch.applications;
    result.basis_size = std::max(result.basis_size, ch.basis_used);
    result.thread_seconds += ch.seconds;
  }
  for(double split : s.splits) join_at(p, split, options.tolerance, found);

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
  auto release = [&](const Basic_ritz_pair<Scalar>& pair) {
    for(Basic_chain<Scalar>& ch : s.chains)
      if(release_vector(ch, pair)) return;
  };
  for(std::size_t i = static_cast<std::size_t>(count); i < order.size(); ++i) release(found[order[i]]);
  result.values.resize(count);
  result.residuals.resize(count);
  const bool rounded = options.float32_vectors;
  if(rounded) resize_in_huge_pages(result.vectors_float32, n, count);
  else resize_in_huge_pages(result.vectors, n, count);
  for(int i = 0; i < count; ++i)
  {
    Basic_ritz_pair<Scalar>& pair = found[order[i]];
    if(!(pair.residual <= pair.tolerance))
    {
      std::ostringstream message;
      message << "spectrum slicing: an eigenpair misses the tolerance (residual " << pair.residual << " > "
              << pair.tolerance << ")";
      throw Numerical_failure(message.str());
    }
    result.values[i] = pair.value;
    result.residuals[i] = pair.residual;
    if(!rounded) result.vectors.col(i) = p.inv_sqrt_d.cwiseProduct(pair.vector());
    else if(pair.rounded)
      result.vectors_float32.col(i) = Eigen::Map<const Eigen::Matrix<Float32, Eigen::Dynamic, 1>>(pair.rounded, n);
    else result.vectors_float32.col(i) = p.inv_sqrt_d.cwiseProduct(pair.vector()).template cast<Float32>();
    release(pair);
  }
  const Basic_chain<Scalar>& last =
      *std::max_element(s.chains.begin(), s.chains.end(),
                        [](const Basic_chain<Scalar>& a, const Basic_chain<Scalar>& b) { return a.end < b.end; });
  result.completeness.shift = last.end;
  result.completeness.inertia = last.below_end;
  result.completeness.expected = c + static_cast<int>(found.size());
  result.complete_below = static_cast<int>(found.size()) > count ? found[order[count]].value : last.end;
  return result;
}

} // namespace

template <class Scalar>
std::vector<Basic_eigenpairs<Scalar>> sliced_eigenpairs(const std::vector<Sliced_request<Scalar>>& requests,
                                                        const Eigensolver_options& options)
{
  const unsigned cores = options.threads > 0 ? static_cast<unsigned>(options.threads)
                                             : std::max(1u, std::thread::hardware_concurrency());
  std::vector<Slicing<Scalar>> slicing(requests.size());
  int wanted = 0;
  for(std::size_t r = 0; r < requests.size(); ++r)
  {
    Slicing<Scalar>& s = slicing[r];
    s.p = &requests[r].problem;
    s.count = requests[r].count;
    // A chain per core, each at least a window long.
    const int per_window = std::max(options.block_size, options.slice_size);
    s.pieces = static_cast<int>(std::min<unsigned>(cores, static_cast<unsigned>(std::max(1, s.count / per_window))));
    // Weyl's law on a surface of area |D|: about |D| lambda / (4 pi) eigenvalues below lambda.
    s.density = s.p->d.sum() / (4 * M_PI);
    wanted += s.count;
  }
  Chain_monitor idle(0);
  auto run = [&](std::vector<std::function<void()>>& tasks, Chain_monitor& monitor, const std::function<void()>& report) {
    run_tasks(tasks, cores, monitor, report);
    tasks.clear();
  };
  std::vector<std::function<void()>> tasks;

  // Each window factors A - sigma D twice: an ordering that costs more to find but factors
  // and solves faster pays on large problems.  One analysis per problem, copied to its chains.
  for(Slicing<Scalar>& s : slicing) tasks.push_back([&s] { s.analysis.analyze(s.p->A, true); });
  run(tasks, idle, nullptr);
  for(Slicing<Scalar>& s : slicing)
  {
    s.split.assign(static_cast<std::size_t>(s.pieces - 1), 0.);
    s.split_density.assign(s.split.size(), s.density);
    s.split_below.assign(s.split.size(), 0);
    for(std::size_t k = 0; k < s.split.size(); ++k)
      tasks.push_back([&s, k] {
        const int target = s.count * static_cast<int>(k + 1) / s.pieces;
        s.split_below[k] = split_point(*s.p, s.analysis, target, target / 5, s.split_density[k], s.split[k]);
      });
  }
  run(tasks, idle, nullptr);

  // The chains of all the requests, the largest (unknowns times pairs) first.
  struct Job
  {
    Slicing<Scalar>* s;
    Basic_chain<Scalar>* chain;
    int index;
  };
  std::vector<Job> jobs;
  for(std::size_t r = 0; r < slicing.size(); ++r)
  {
    Slicing<Scalar>& s = slicing[r];
    make_chains(s, options.seed + 0x632be59bd9b4e019ull * r);
    for(Basic_chain<Scalar>& ch : s.chains) jobs.push_back({&s, &ch, static_cast<int>(jobs.size())});
  }
  auto work = [](const Job& j) { return static_cast<double>(j.s->p->A.rows()) * j.chain->count; };
  std::stable_sort(jobs.begin(), jobs.end(), [&](const Job& a, const Job& b) { return work(a) > work(b); });
  Chain_monitor monitor(jobs.size() + 4 * cores); // and slots for chains taken over
  auto run_job = [&monitor, &options](const Job& j) {
    Basic_chain<Scalar>& chain = *j.chain;
    {
      std::lock_guard<std::mutex> lock(chain.mutex);
      chain.running = true;
      chain.working_hi = chain.lo;
      chain.below_working_hi = chain.below_lo;
    }
    struct Stopped
    {
      Basic_chain<Scalar>& chain;
      ~Stopped()
      {
        std::lock_guard<std::mutex> lock(chain.mutex);
        chain.running = false;
      }
    } stopped{chain};
    run_chain(*j.s->p, j.s->analysis, chain, options, monitor, j.index);
    give_back_freed_heap(); // the chain's factor, shifted matrix and solves' blocks
  };
  for(const Job& j : jobs) tasks.push_back([&run_job, j] { run_job(j); });
  // Once the queue is empty: the top of the running chain with the most work left (unknowns
  // times pairs), one thread at a time.
  std::mutex take_over_mutex; // guards `jobs` and the chains and splits added
  const int per_window = std::max(options.block_size, options.slice_size);
  auto take_over = [&]() -> std::function<void()> {
    std::lock_guard<std::mutex> lock(take_over_mutex);
    if(jobs.size() >= monitor.converged.size()) return nullptr;
    Job victim{nullptr, nullptr, 0};
    double most = 0;
    for(const Job& j : jobs)
    {
      std::lock_guard<std::mutex> chain_lock(j.chain->mutex);
      const double left = static_cast<double>(j.s->p->A.rows()) * (j.chain->below_end_wanted() - j.chain->below_working_hi);
      if(j.chain->running && left > most)
      {
        most = left;
        victim = j;
      }
    }
    if(!victim.s) return nullptr;
    Slicing<Scalar>& s = *victim.s;
    Basic_chain<Scalar>& taken = s.chains.emplace_back();
    taken.seed = victim.chain->seed + 0x9e3779b97f4a7c15ull * static_cast<std::uint64_t>(s.chains.size());
    double split = std::numeric_limits<double>::quiet_NaN();
    try
    {
      split = take_over_top(*s.p, s.analysis, *victim.chain, per_window, taken);
    }
    catch(const Numerical_failure&) // a factorisation at a trial shift: the cut is optional
    {
    }
    if(std::isnan(split))
    {
      s.chains.pop_back();
      return nullptr;
    }
    s.splits.push_back(split);
    jobs.push_back({&s, &taken, static_cast<int>(jobs.size())});
    return [&run_job, j = jobs.back()] { run_job(j); };
  };
  std::function<void()> report;
  if(options.progress) report = [&] { options.progress({std::min(monitor.total(), wanted), wanted, 0}); };
  run_tasks(tasks, cores, monitor, report, take_over);
  tasks.clear();

  std::vector<Basic_eigenpairs<Scalar>> result;
  for(Slicing<Scalar>& s : slicing) result.push_back(merge(s, options));
  return result;
}

template std::vector<Eigenpairs> sliced_eigenpairs(const std::vector<Sliced_request<double>>&,
                                                   const Eigensolver_options&);
template std::vector<Complex_eigenpairs> sliced_eigenpairs(const std::vector<Sliced_request<std::complex<double>>>&,
                                                           const Eigensolver_options&);

} // namespace internal
} // namespace Model_reduction
} // namespace CGAL
