#include "sim/stall_window.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace pak;

TEST(StallWindow, RmsOfEquation47OnAKnownSequence) {
  // w = 3: the last four values. Steps 1, 2, 2 → sqrt((1 + 4 + 4) / 3) = sqrt(3).
  StallWindow window(3);
  const double values[] = {10.0, 0.0, 1.0, 3.0, 5.0};
  for (int it = 1; it <= 5; ++it) {
    window.record(it, values[it - 1]);
    EXPECT_EQ(window.full(), it >= 4) << it;
  }
  EXPECT_NEAR(window.rms(), std::sqrt(3.0), 1e-15);
  EXPECT_DOUBLE_EQ(window.rise(), 5.0);  // 5 − 0: the first value has left the window
  // Steady values: no step, no rise.
  for (int it = 6; it <= 9; ++it) window.record(it, 5.0);
  EXPECT_EQ(window.rms(), 0.0);
  EXPECT_EQ(window.rise(), 0.0);
}

TEST(StallWindow, RingIsIndexedByIteration) {
  StallWindow window(2);
  window.record(1, 0.25);
  window.record(2, 0.5);
  window.record(3, 1.0);
  // Slot = iteration mod 3.
  EXPECT_EQ(window.values(), (std::vector<double>{1.0, 0.25, 0.5}));
  EXPECT_EQ(window.recorded(), 3);
}

TEST(StallWindow, RestoredStateGivesTheSameAnswers) {
  StallWindow straight(4), resumed(4);
  for (int it = 1; it <= 6; ++it) straight.record(it, 0.1 * it * it);
  resumed.restore(straight.values(), straight.recorded(), 6);
  for (int it = 7; it <= 9; ++it) {
    straight.record(it, 1.0 / it);
    resumed.record(it, 1.0 / it);
    EXPECT_EQ(resumed.rms(), straight.rms());
    EXPECT_EQ(resumed.rise(), straight.rise());
  }
  EXPECT_EQ(resumed.values(), straight.values());
  EXPECT_EQ(resumed.recorded(), straight.recorded());
}
