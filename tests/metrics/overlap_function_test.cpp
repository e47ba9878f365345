#include <gtest/gtest.h>

#include "metrics_fixtures.hpp"

using namespace pak;
using namespace pak::test;

TEST(OverlapFunction, SquareGridOverlapsOnlyPastHalfGap) {
  const double s = 2, g = 0.5;
  const PackingGeometry p = squareGrid(4, s, g);
  EXPECT_EQ(overlapFunction(p, 0.0), 0.0);
  EXPECT_EQ(overlapFunction(p, 0.49 * g), 0.0);
  EXPECT_GT(overlapFunction(p, 0.51 * g), 0.0);
}

TEST(OverlapFunction, StripesOverlapInBandsOfTwiceTheExcess) {
  const double W = 100, b = 3, g = 1;
  const PackingGeometry p = stripes(W, 5, b, g);
  // Each of the 5 gaps is covered twice over a band 2r - g wide.
  const double r = 0.75;
  EXPECT_NEAR(overlapFunction(p, r), (2 * r - g) / (g + b), 1e-6);
}
