#include <gtest/gtest.h>

#include <cmath>

#include "metrics_fixtures.hpp"
#include "pak/error.hpp"

using namespace pak;
using namespace pak::test;

TEST(Calibration, TwoPackingsReachTheSameNegativeRatio) {
  const PackingGeometry a = squareGrid(4, 2, 0.5);  // negative ratio 0.36
  PackingGeometry b;
  b.container = rect(0, 0, 10, 10);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) b.elements.push_back(disc({1.7 + 3.2 * i, 1.7 + 3.1 * j}, 1.2, 256));
  const double target = 0.3;
  const Calibration ca = calibrateNegativeSpace(a, target, 1e-6);
  const Calibration cb = calibrateNegativeSpace(b, target, 1e-6);
  EXPECT_GT(ca.offset, 0.0);  // the squares grow
  EXPECT_GT(cb.offset, 0.0);
  EXPECT_NEAR(ca.negativeRatio, target, 1e-6);
  EXPECT_NEAR(cb.negativeRatio, target, 1e-6);
  // Measured afresh, both calibrated packings agree within 1e-4.
  EXPECT_NEAR(sphericalContact(ca.calibrated, 0.0), sphericalContact(cb.calibrated, 0.0), 1e-4);
  EXPECT_NEAR(sphericalContact(ca.calibrated, 0.0), target, 1e-4);
  // Shrinking works too.
  const Calibration shrunk = calibrateNegativeSpace(a, 0.5, 1e-6);
  EXPECT_LT(shrunk.offset, 0.0);
  EXPECT_NEAR(sphericalContact(shrunk.calibrated, 0.0), 0.5, 1e-4);
  EXPECT_THROW(calibrateNegativeSpace(a, 1.5), InputError);
}
