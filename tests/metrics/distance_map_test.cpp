// The discrete distance transform against the exact distance of a disc in a square.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "metrics_fixtures.hpp"
#include "pak/error.hpp"

namespace pak {
namespace {

TEST(DistanceMap, DiscInSquareMatchesExactDistanceWithinACell) {
  const double s = 100.0, a = 20.0;
  const Vec2 c{40.0, 55.0};
  PackingGeometry p;
  p.container = test::rect(0, 0, s, s);
  p.elements.push_back(test::disc(c, a));
  const DistanceMap map = distanceMap(p, 200);
  ASSERT_EQ(map.columns, 200);
  ASSERT_EQ(map.rows, 200);
  EXPECT_DOUBLE_EQ(map.cell, 0.5);
  double largest = 0.0, worst = 0.0;
  int free = 0;
  for (int j = 0; j < map.rows; ++j)
    for (int i = 0; i < map.columns; ++i) {
      const Vec2 q = map.origin + Vec2{(i + 0.5) * map.cell, (j + 0.5) * map.cell};
      const double exact = std::min({q.x, q.y, s - q.x, s - q.y, length(q - c) - a});
      const double d = map.distance[static_cast<std::size_t>(j) * map.columns + i];
      if (exact < 0.0) {
        EXPECT_LT(d, 0.0) << "cell inside the disc " << i << "," << j;
        continue;
      }
      if (d < 0.0) {  // only cells whose centre is within a hair of the boundary may be lost
        EXPECT_LT(exact, 1e-3) << i << "," << j;
        continue;
      }
      ++free;
      worst = std::max(worst, std::abs(d - exact));
      largest = std::max(largest, exact);
    }
  EXPECT_LE(worst, map.cell) << "grid distance off by more than a cell";
  EXPECT_NEAR(map.largest, largest, map.cell);
  EXPECT_NEAR(free * map.cell * map.cell, s * s - M_PI * a * a, 2.0 * 4.0 * s * map.cell);
}

TEST(DistanceMap, RejectsBadResolution) {
  PackingGeometry p;
  p.container = test::rect(0, 0, 10, 10);
  p.elements.push_back(test::rect(2, 2, 4, 4));
  EXPECT_THROW(distanceMap(p, 1), InputError);
}

}  // namespace
}  // namespace pak
