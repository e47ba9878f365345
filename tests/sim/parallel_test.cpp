#include "sim/parallel.hpp"

#include <gtest/gtest.h>

#include <numeric>

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
