#include "sim/parallel.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <numeric>
#include <thread>

using namespace pak;

TEST(ThreadPool, CoversEveryIndexExactlyOnce) {
  for (int threads : {1, 2, 4}) {
    ThreadPool pool(threads);
    EXPECT_EQ(pool.threadCount(), threads);
    std::vector<int> hits(10007, 0);
    for (int round = 0; round < 50; ++round)
      pool.parallelFor(hits.size(), 64, [&](std::size_t b, std::size_t e) {
        for (std::size_t i = b; i < e; ++i) ++hits[i];
      });
    for (int h : hits) ASSERT_EQ(h, 50);
  }
}

TEST(ThreadPool, EmptyAndTinyRanges) {
  ThreadPool pool(3);
  int calls = 0;
  pool.parallelFor(0, 8, [&](std::size_t, std::size_t) { ++calls; });
  EXPECT_EQ(calls, 0);
  std::size_t covered = 0;
  pool.parallelFor(5, 8, [&](std::size_t b, std::size_t e) { covered += e - b; });
  EXPECT_EQ(covered, 5u);
}

// The caller's first chunk waits until another thread has run a chunk of the caller's share:
// only the taking from the back of another's share lets that happen. Every index is still
// covered once.
TEST(ThreadPool, AThreadOutOfWorkTakesTheRestOfAnothersShare) {
  ThreadPool pool(2);
  const auto caller = std::this_thread::get_id();
  constexpr std::size_t n = 64;  // grain 1: the caller's share is [0, 32)
  std::vector<std::atomic<int>> hits(n);
  std::atomic<bool> helped{false};
  pool.parallelFor(n, 1, [&](std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i) {
      hits[i].fetch_add(1);
      if (i < n / 2 && std::this_thread::get_id() != caller) helped = true;
      if (i == 0) {
        const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
        while (!helped && std::chrono::steady_clock::now() < give_up) std::this_thread::yield();
      }
    }
  });
  EXPECT_TRUE(helped.load());
  for (const auto& h : hits) EXPECT_EQ(h.load(), 1);
}

// Shares of unequal length (chunks not a multiple of the threads) and a last short chunk.
TEST(ThreadPool, UnevenSharesCoverEveryIndexOnce) {
  for (int threads : {2, 3, 5}) {
    ThreadPool pool(threads);
    for (std::size_t n : {7u, 13u, 1000u, 1001u}) {
      std::vector<std::atomic<int>> hits(n);
      pool.parallelFor(n, 3, [&](std::size_t b, std::size_t e) {
        EXPECT_EQ(b % 3, 0u);
        EXPECT_EQ(e, std::min(n, b + 3));
        for (std::size_t i = b; i < e; ++i) hits[i].fetch_add(1);
      });
      for (const auto& h : hits) ASSERT_EQ(h.load(), 1) << threads << " threads, n " << n;
    }
  }
}
