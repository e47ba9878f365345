#include "sim/growth_rule.hpp"

#include <gtest/gtest.h>

using namespace pak;

TEST(GrowthRule, GrowsByRateTimesStepWhileThereIsRoom) {
  const GrowthRule rule(0.01, 0.1);  // k_g Δt = 0.001 (thesis 4.5.1)
  EXPECT_DOUBLE_EQ(rule.next(0.5, true), 0.501);
  EXPECT_DOUBLE_EQ(rule.next(0.5, false), 0.5);
  EXPECT_TRUE(rule.belowCap(1e9));  // no cap
}

TEST(GrowthRule, StopsAtTheCap) {
  const GrowthRule rule(1.0, 0.1, 1.5);
  EXPECT_DOUBLE_EQ(rule.grown(1.3), 1.4);
  EXPECT_DOUBLE_EQ(rule.grown(1.45), 1.5);
  EXPECT_DOUBLE_EQ(rule.next(1.5, true), 1.5);
  EXPECT_TRUE(rule.belowCap(1.45));
  EXPECT_FALSE(rule.belowCap(1.5));
}
