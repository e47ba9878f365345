#include "sim/region_index.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "pak/geom/closest_point.hpp"
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

TEST(RegionIndex, FarOutsidePointsFindTheirClosestBoundaryPoint) {
  // The search starts at the grid cell nearest the point, so distance costs nothing.
  RegionIndex index(squareWithHole(), 0.5);
  auto far = index.query({1e9, 30}, true);
  ASSERT_TRUE(far.computed);
  EXPECT_NEAR(far.closest.x, 100.0, 1e-6);
  EXPECT_NEAR(far.closest.y, 30.0, 1e-6);
  EXPECT_FALSE(far.inside);
  auto diagonal = index.query({-1e7, -1e7}, true);
  EXPECT_NEAR(diagonal.closest.x, 0.0, 1e-6);
  EXPECT_NEAR(diagonal.closest.y, 0.0, 1e-6);
  Rng rng(11);
  for (int i = 0; i < 2000; ++i) {
    Vec2 p{rng.uniform(-300, 400), rng.uniform(-300, 400)};
    auto q = index.query(p, true);
    EXPECT_NEAR(q.distance, closestPointOnBoundary(p, squareWithHole()).distance, 1e-9)
        << p.x << "," << p.y;
  }
}

TEST(RegionIndex, FarPointsAroundAStarFindTheExactNearestBoundary) {
  // A non-convex ring: far off, many of its points are almost equally near, and the search
  // off the grid (a band along the grid's near side) must still find the nearest exactly.
  Polygon star;
  for (int k = 0; k < 14; ++k) {
    const double angle = k * 3.14159265358979 / 7, radius = k % 2 ? 20.0 : 50.0;
    star.outer.push_back({50 + radius * std::cos(angle), 50 + radius * std::sin(angle)});
  }
  const Region region{star};
  RegionIndex index(region, 1.5);
  Rng rng(3);
  for (int i = 0; i < 3000; ++i) {
    const double angle = rng.uniform(0, 6.283185307179586), distance = std::pow(10.0, rng.uniform(1, 7));  // some inside
    const Vec2 p{50 + distance * std::cos(angle), 50 + distance * std::sin(angle)};
    const RegionIndex::Query q = index.query(p, true);
    ASSERT_TRUE(q.computed);
    const double exact = closestPointOnBoundary(p, region).distance;
    EXPECT_NEAR(q.distance, exact, 1e-12 * exact) << p.x << "," << p.y;
    EXPECT_EQ(q.inside, pointInRegion(p, region)) << p.x << "," << p.y;
  }
}

TEST(RegionIndex, PointsNearTheBoundaryFindTheExactNearestSegment) {
  // With near-segment lists, cells within a few rings of the boundary answer from a short list
  // of segments: every point there, inside or out, must still get the nearest boundary point
  // of all, the very one the ring search finds.
  Polygon wavy;
  for (int k = 0; k < 360; ++k) {
    const double angle = k * 3.14159265358979 / 180, radius = 40.0 + 6.0 * std::sin(7 * angle);
    wavy.outer.push_back({50 + radius * std::cos(angle), 50 + radius * std::sin(angle)});
  }
  wavy.holes = {{{45, 45}, {45, 55}, {55, 55}, {55, 45}}};
  const Region region{wavy};
  const RegionIndex searched(region, 1.25);
  RegionIndex index(region, 1.25);
  index.listNearSegments();
  Rng rng(11);
  for (int i = 0; i < 4000; ++i) {
    const double angle = rng.uniform(0, 6.283185307179586);
    const double radius = 40.0 + 6.0 * std::sin(7 * angle) + rng.uniform(-8.0, 8.0);
    const Vec2 p = i % 8 ? Vec2{50 + radius * std::cos(angle), 50 + radius * std::sin(angle)}
                         : Vec2{rng.uniform(42, 58), rng.uniform(42, 58)};  // around the hole
    const RegionIndex::Query q = index.query(p, true);
    ASSERT_TRUE(q.computed);
    const auto exact = closestPointOnBoundary(p, region);
    EXPECT_NEAR(q.distance, exact.distance, 1e-12) << p.x << "," << p.y;
    EXPECT_NEAR(lengthSquared(q.closest - p), exact.distance * exact.distance, 1e-9) << p.x << "," << p.y;
    EXPECT_EQ(q.inside, pointInRegion(p, region)) << p.x << "," << p.y;
    const RegionIndex::Query s = searched.query(p, true);  // the ring search: the same bits
    EXPECT_EQ(q.closest, s.closest) << p.x << "," << p.y;
    EXPECT_EQ(q.distance, s.distance) << p.x << "," << p.y;
  }
}

TEST(RegionIndex, NonFinitePointHasNoClosestBoundary) {
  RegionIndex index(squareWithHole(), 7.0);
  EXPECT_FALSE(index.query({std::nan(""), 3}, true).computed);
  EXPECT_FALSE(index.query({3, std::numeric_limits<double>::infinity()}, true).computed);
}

TEST(RegionIndex, InsideDistanceBoundNeverExceedsTheDistance) {
  RegionIndex index(squareWithHole(), 7.0);
  Rng rng(5);
  int positive = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec2 p{rng.uniform(-30, 130), rng.uniform(-30, 130)};
    const double bound = index.insideDistanceBound(p);
    const RegionIndex::Query q = index.query(p, true);
    if (!q.inside) {
      EXPECT_EQ(bound, 0.0) << p.x << ", " << p.y;  // outside or in the hole: no bound
      continue;
    }
    EXPECT_LE(bound, q.distance + 1e-12) << p.x << ", " << p.y;
    positive += bound > 0.0 ? 1 : 0;
  }
  EXPECT_GT(positive, 100);  // it does skip queries far from the walls
  // Deep inside (20 from the walls and the hole), a cell or so short of the distance.
  EXPECT_GE(index.insideDistanceBound({20, 20}), 20.0 - 3 * 7.0);
  EXPECT_EQ(index.insideDistanceBound({std::nan(""), 20}), 0.0);
}
