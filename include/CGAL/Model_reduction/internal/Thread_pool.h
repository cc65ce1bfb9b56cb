// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// A fixed set of worker threads that run one loop at a time, split into contiguous ranges:
// Projective_dynamics' local steps run every iteration, and starting threads each time would
// cost ~20-50 us per iteration (noticeable at small meshes); Spline_approximation's
// least-squares fits split their passes over a million samples.
//
// Waiting spins for up to `spin_microseconds` before it sleeps on a condition variable: a
// hyper-reduced step runs ten loops of ~0.25 ms a few tens of microseconds apart, and a sleeping
// worker's wake-up took ~0.1 ms each on this project's 2-core machine (a 68k-tet armadillo,
// 1,000 sampled tets: 0.34 ms per local step against 0.24 ms of work per thread).

#ifndef CGAL_MODEL_REDUCTION_INTERNAL_THREAD_POOL_H
#define CGAL_MODEL_REDUCTION_INTERNAL_THREAD_POOL_H

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace CGAL {
namespace Model_reduction {
namespace internal {

/// Threads for a job asked for `asked` (0: one per core), at most 256.
inline int thread_count(int asked)
{
  const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
  return std::min(asked == 0 ? cores : asked, 256);
}

class Thread_pool
{
public:
  /// `threads` workers in all, the calling thread counted (so `threads - 1` are started).
  explicit Thread_pool(int threads)
  {
    for(int i = 1; i < threads; ++i) workers_.emplace_back([this, i] { work(i); });
  }
  ~Thread_pool()
  {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
      ++generation_;
    }
    start_.notify_all();
    for(std::thread& t : workers_) t.join();
  }
  Thread_pool(const Thread_pool&) = delete;
  Thread_pool& operator=(const Thread_pool&) = delete;

  int size() const { return int(workers_.size()) + 1; }

  /// Runs `body(begin, end)` over `[0, n)` cut into `size()` ranges, one per thread, and waits.
  /// An exception of any range is rethrown here (the first one).
  void run(std::size_t n, const std::function<void(std::size_t, std::size_t)>& body)
  {
    if(workers_.empty() || n < 2 * workers_.size() + 2)
    {
      body(0, n);
      return;
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      body_ = &body;
      n_ = n;
      pending_.store(int(workers_.size()));
      error_ = nullptr;
      generation_.fetch_add(1); // after body_ and n_: a spinning worker reads them once it sees this
    }
    start_.notify_all();
    std::exception_ptr mine;
    try { body(0, range_end(0)); }
    catch(...) { mine = std::current_exception(); }
    spin_until([this] { return pending_.load() == 0; });
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [this] { return pending_.load() == 0; });
    body_ = nullptr;
    if(mine) std::rethrow_exception(mine);
    if(error_) std::rethrow_exception(error_);
  }

private:
  static constexpr int spin_microseconds = 50;

  std::size_t range_end(int i) const { return n_ * std::size_t(i + 1) / std::size_t(size()); }

  // Busy-waits until `ready()` or `spin_microseconds` have passed; returns `ready()`.
  template <class Ready>
  static bool spin_until(const Ready& ready)
  {
    const auto end = std::chrono::steady_clock::now() + std::chrono::microseconds(spin_microseconds);
    for(int i = 1;; ++i)
    {
      if(ready()) return true;
#if defined(__x86_64__) || defined(__i386__)
      _mm_pause();
#endif
      if(i % 64 == 0 && std::chrono::steady_clock::now() > end) return ready();
    }
  }

  void work(int i)
  {
    unsigned long long seen = 0;
    for(;;)
    {
      const std::function<void(std::size_t, std::size_t)>* body;
      {
        spin_until([&] { return generation_.load() != seen; });
        std::unique_lock<std::mutex> lock(mutex_);
        start_.wait(lock, [&] { return generation_.load() != seen; });
        seen = generation_.load();
        if(stop_) return;
        body = body_;
      }
      std::exception_ptr error;
      try { (*body)(range_end(i - 1), range_end(i)); }
      catch(...) { error = std::current_exception(); }
      if(error)
      {
        std::lock_guard<std::mutex> lock(mutex_);
        if(!error_) error_ = error;
      }
      if(pending_.fetch_sub(1) == 1)
      {
        // Under the mutex: the caller checks pending_ under it before it sleeps.
        std::lock_guard<std::mutex> lock(mutex_);
        done_.notify_one();
      }
    }
  }

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable start_, done_;
  const std::function<void(std::size_t, std::size_t)>* body_ = nullptr;
  std::size_t n_ = 0;
  std::atomic<int> pending_{0};
  std::atomic<unsigned long long> generation_{0};
  bool stop_ = false;
  std::exception_ptr error_;
};

} // namespace internal
} // namespace Model_reduction
} // namespace CGAL

#endif
