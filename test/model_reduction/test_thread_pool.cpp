// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// The shared thread pool: every index of a loop run exactly once, loops back to back (caught by
// spinning workers) and after pauses longer than the spin (sleeping workers woken), an error
// thrown in a worker's range rethrown with its message, and the pool usable afterwards.

#include <CGAL/Model_reduction/internal/Thread_pool.h>

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace {

namespace MRI = CGAL::Model_reduction::internal;

// Runs a loop of n on the pool and checks that each index was visited once.
void expect_each_index_once(MRI::Thread_pool& pool, std::size_t n)
{
  std::vector<std::atomic<int>> visits(n);
  for(auto& v : visits) v.store(0);
  pool.run(n, [&](std::size_t begin, std::size_t end) {
    for(std::size_t i = begin; i < end; ++i) visits[i].fetch_add(1);
  });
  int wrong = 0;
  for(std::size_t i = 0; i < n; ++i) wrong += visits[i].load() != 1;
  ASSERT_EQ(wrong, 0) << "loop of " << n << " on " << pool.size() << " threads";
}

TEST(ThreadPool, RunsEveryIndexOnceBackToBackAndAfterPauses)
{
  for(int threads : {1, 2, 3, 5})
  {
    MRI::Thread_pool pool(threads);
    // Back to back: the workers are still spinning when the next loop starts.
    for(int round = 0; round < 2000; ++round) expect_each_index_once(pool, std::size_t(1 + round % 97));
    // Pauses of a millisecond (20x the spin): the workers sleep and must be woken.
    for(int round = 0; round < 20; ++round)
    {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      expect_each_index_once(pool, 1000);
    }
  }
}

TEST(ThreadPool, RethrowsAWorkersErrorAndStaysUsable)
{
  MRI::Thread_pool pool(3);
  // Index 999 lies in the last worker's range, not the caller's.
  try
  {
    pool.run(1000, [](std::size_t begin, std::size_t end) {
      if(begin <= 999 && 999 < end) throw std::runtime_error("index 999 failed");
    });
    FAIL() << "no error rethrown";
  }
  catch(const std::runtime_error& e)
  {
    EXPECT_EQ(std::string(e.what()), "index 999 failed");
  }
  expect_each_index_once(pool, 1000);
}

} // namespace
