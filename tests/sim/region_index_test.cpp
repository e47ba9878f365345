#include "sim/region_index.hpp"

#include <gtest/gtest.h>

#include "pak/geom/rng.hpp"

using namespace pak;

namespace {
Region squareWithHole() {
  Polygon p;
  p.outer = {{0, 0}, {100, 0}, {100, 100}, {0, 100}};
  p.holes = {{{40, 40}, {40, 60}, {60, 60}, {60, 40}}};
  return {p};
}
}  // namespace

TEST(RegionIndex, InsideOutsideAndHole) {
  RegionIndex index(squareWithHole(), 7.0);
  EXPECT_TRUE(index.query({10, 10}, false).inside);
  EXPECT_FALSE(index.query({50, 50}, false).inside);   // in the hole
  EXPECT_FALSE(index.query({-5, 50}, false).inside);
  EXPECT_FALSE(index.query({500, 500}, false).inside); // far outside the grid
}

TEST(RegionIndex, ClosestBoundaryPointIsExact) {
  RegionIndex index(squareWithHole(), 7.0);
  auto q = index.query({-3, 20}, true);
  ASSERT_TRUE(q.computed);
  EXPECT_NEAR(q.closest.x, 0.0, 1e-12);
  EXPECT_NEAR(q.closest.y, 20.0, 1e-12);
  EXPECT_NEAR(q.distance, 3.0, 1e-12);
  auto h = index.query({50, 52}, true);  // in the hole; the nearest hole edge is y = 60
  EXPECT_NEAR(h.distance, 8.0, 1e-12);
  EXPECT_FALSE(h.inside);
  auto corner = index.query({105, 110}, true);  // nearest is the corner (100, 100)
  EXPECT_NEAR(corner.closest.x, 100.0, 1e-12);
  EXPECT_NEAR(corner.closest.y, 100.0, 1e-12);
  EXPECT_FALSE(corner.inside);
}

TEST(RegionIndex, AgreesWithPointInRegionEverywhere) {
  Region region = squareWithHole();
  RegionIndex index(region, 3.0);
  Rng rng(7);
  for (int i = 0; i < 5000; ++i) {
    Vec2 p{rng.uniform(-20, 120), rng.uniform(-20, 120)};
    EXPECT_EQ(index.query(p, false).inside, pointInRegion(p, region)) << p.x << "," << p.y;
    EXPECT_EQ(index.query(p, true).inside, pointInRegion(p, region)) << p.x << "," << p.y;
  }
}
