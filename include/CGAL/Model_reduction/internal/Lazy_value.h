// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_MODEL_REDUCTION_INTERNAL_LAZY_VALUE_H
#define CGAL_MODEL_REDUCTION_INTERNAL_LAZY_VALUE_H

/// \file Lazy_value.h
/// A value made on first request, once, whichever threads ask for it at the same time.

#include <atomic>
#include <mutex>
#include <optional>

namespace CGAL {
namespace Model_reduction {
namespace internal {

/// Holds the result of the first `get(make)`.  Threads that ask while it is being made wait
/// for it; after that a request costs one atomic read.  If `make` throws, nothing is kept and
/// the next request tries again.  (The operators' caches are shared by the editor's
/// sessions, each on its own thread: a matrix built by two of them at once crashed the
/// server.  Not `std::call_once`: with GCC before 14 a call after a throwing one can hang.)
template <class T>
class Lazy_value
{
public:
  template <class Make>
  const T& get(Make&& make) const
  {
    if(!ready_.load(std::memory_order_acquire))
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if(!ready_.load(std::memory_order_relaxed))
      {
        value_.emplace(make());
        ready_.store(true, std::memory_order_release);
      }
    }
    return *value_;
  }

private:
  mutable std::mutex mutex_;
  mutable std::atomic<bool> ready_{false};
  mutable std::optional<T> value_;
};

} // namespace internal
} // namespace Model_reduction
} // namespace CGAL

#endif
