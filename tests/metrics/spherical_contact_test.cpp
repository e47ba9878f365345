#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "metrics_fixtures.hpp"

using namespace pak;
using namespace pak::test;

TEST(SphericalContact, StripesFallLinearlyToZeroAtHalfGap) {
  const double W = 100, b = 3, g = 1;
  const PackingGeometry p = stripes(W, 5, b, g);
  EXPECT_NEAR(sphericalContact(p, 0.0), g / (g + b), 1e-9);
  // Only the container's side walls bend the line: each gap loses r at both ends.
  auto exact = [&](double r) { return (W - 2 * r) * (g - 2 * r) / (W * (g + b)); };
  for (double r : {0.1, 0.25, 0.4}) {
    EXPECT_NEAR(sphericalContact(p, r), exact(r), 1e-6) << r;
    EXPECT_NEAR(sphericalContact(p, r), (g - 2 * r) / (g + b), 1e-3) << r;  // linear
  }
  EXPECT_NEAR(sphericalContact(p, g / 2), 0.0, 1e-3);
  EXPECT_EQ(sphericalContact(p, g / 2 * 1.001), 0.0);
  EXPECT_NEAR(estimateGap(p), g, 1e-2);
}

TEST(SphericalContact, SquareGridPocketsHoldDiscsOfHalfDiagonal) {
  const double s = 2, g = 0.5;
  const PackingGeometry p = squareGrid(4, s, g);
  EXPECT_NEAR(sphericalContact(p, 0.0), 1 - std::pow(s / (s + g), 2), 1e-9);
  const double pocket = g * std::sqrt(2.0) / 2;
  EXPECT_GT(sphericalContact(p, pocket * 0.99, 1e-7), 0.0);
  EXPECT_EQ(sphericalContact(p, pocket * 1.01, 1e-7), 0.0);
}

TEST(SphericalContact, DiscInSquareMatchesClosedForm) {
  const double s = 1, a = 0.2;
  PackingGeometry p;
  p.container = rect(0, 0, s, s);
  p.elements.push_back(disc({0.5, 0.5}, a));
  for (double r : {0.0, 0.05, 0.1, 0.15}) {
    const double expected = ((s - 2 * r) * (s - 2 * r) - std::numbers::pi * (a + r) * (a + r)) / (s * s);
    EXPECT_NEAR(sphericalContact(p, r, 1e-7), expected, 1e-4) << r;
  }
}
