// The evenness measure's grid machinery: nearest occupied cells against brute force, small
// holes, and a medial axis with no raster-noise branches.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "metrics/medial_axis.hpp"
#include "metrics/nearest_occupied.hpp"
#include "metrics/small_holes.hpp"
#include "metrics_fixtures.hpp"
#include "pak/metrics/evenness.hpp"

namespace pak {
namespace {

using namespace metrics_internal;

TEST(NearestOccupied, MatchesBruteForceOnARandomGrid) {
  const int nx = 41, ny = 29;
  std::mt19937 random(7);
  std::vector<std::uint8_t> occupied(nx * ny);
  for (auto& o : occupied) o = random() % 11 == 0;
  const std::vector<int> nearest = nearestOccupiedCells(occupied, nx, ny);
  ASSERT_EQ(nearest.size(), occupied.size());
  for (int k = 0; k < nx * ny; ++k) {
    int best = -1;
    for (int m = 0; m < nx * ny; ++m) {
      if (!occupied[m]) continue;
      auto d2 = [&](int c) { return (c % nx - k % nx) * (c % nx - k % nx) + (c / nx - k / nx) * (c / nx - k / nx); };
      if (best < 0 || d2(m) < d2(best)) best = m;
    }
    ASSERT_GE(nearest[k], 0);
    ASSERT_TRUE(occupied[nearest[k]]);
    auto d2 = [&](int c) { return (c % nx - k % nx) * (c % nx - k % nx) + (c / nx - k / nx) * (c / nx - k / nx); };
    EXPECT_EQ(d2(nearest[k]), d2(best)) << "cell " << k;  // ties may pick another cell
  }
  EXPECT_EQ(nearestOccupiedCells(std::vector<std::uint8_t>(12, 0), 4, 3), std::vector<int>(12, -1));
}

TEST(SmallHoles, FillsOnlyEnclosedComponentsUnderTheLimit) {
  // A 10 × 10 ring of shape around a 2 × 2 hole, a 3 × 3 hole, and the border's background.
  const int n = 12;
  std::vector<std::uint8_t> mask(n * n, 0);
  for (int j = 1; j <= 10; ++j)
    for (int i = 1; i <= 10; ++i) mask[j * n + i] = 1;
  for (int j = 2; j < 4; ++j)
    for (int i = 2; i < 4; ++i) mask[j * n + i] = 0;
  for (int j = 5; j < 8; ++j)
    for (int i = 5; i < 8; ++i) mask[j * n + i] = 0;
  EXPECT_EQ(fillSmallHoles(mask, n, 5.0, 2), 4);  // 4 < 5 cells filled; 9 and the outside stay
  EXPECT_EQ(mask[2 * n + 2], 2);
  EXPECT_EQ(mask[6 * n + 6], 0);
  EXPECT_EQ(mask[0], 0);
}

// The medial axis of a square frame around a disc: parabolas between each wall and the disc,
// whose empty discs have radius at least (side / 2 - disc radius) / 2; the right-angle corner
// branches are pruned. A raster-noise branch along the disc or a wall would show as a
// crossing of radius of a few cells.
TEST(MedialAxis, NoNoiseBranchesAlongSmoothOrStraightBoundaries) {
  const double side = 600.0, radius = 170.0;
  PackingGeometry p;
  p.container = test::rect(0, 0, side, side);
  p.elements.push_back(test::disc({side / 2 + 0.37, side / 2 - 0.61}, radius));
  EvennessOptions options;
  options.resolution = 600;
  const EvennessMap map = evennessMap(p, options);
  const double narrowest = (side / 2 - radius) / 2;  // 65 cells
  int axisCells = 0;
  for (std::size_t k = 0; k < map.axis.size(); ++k) {
    if (!map.axis[k]) continue;
    ++axisCells;
    EXPECT_GT(map.distance[k], narrowest - 1.5) << "axis cell " << k % map.columns << "," << k / map.columns;
  }
  EXPECT_GT(axisCells, 500);
  // Channels of half-width 65 (at the walls' middles) widening to ~90 before the corners.
  EXPECT_GT(map.evenness.halfWidth, narrowest);
  EXPECT_LT(map.evenness.halfWidth, 95.0);
}

// A straight channel of width g at 17° to the grid, through a square container: a staircase
// on both sides. Its axis is one straight segment with h = g/2 and length ≈ the channel's
// length, whatever the angle (the crossings' weights).
TEST(MedialAxis, TiltedChannelHasTheRightWidthAndLength) {
  const double side = 1000.0, g = 24.0, angle = 17.0 * std::numbers::pi / 180.0;
  const Vec2 c{side / 2, side / 2}, along{std::cos(angle), std::sin(angle)}, across{-along.y, along.x};
  auto band = [&](double from, double to) {
    Ring r;
    for (Vec2 corner : {Vec2{-side, from}, Vec2{side, from}, Vec2{side, to}, Vec2{-side, to}})
      r.push_back(c + along * corner.x + across * corner.y);
    return Region{Polygon{r, {}}};
  };
  PackingGeometry p;
  p.container = test::rect(0, 0, side, side);
  p.elements.push_back(band(-side, -g / 2));
  p.elements.push_back(band(g / 2, side));
  const Evenness e = measureEvenness(p);  // cell = 1
  EXPECT_NEAR(e.halfWidth, g / 2, 0.5);
  // The channel's midline crosses the square over side / cos(17°); its ends lose about g/2.
  const double length = side / std::cos(angle);
  EXPECT_NEAR(e.axisLength, length, 0.02 * length);
  EXPECT_LT(e.widthSpread, 1.0 / e.halfWidth);
  EXPECT_DOUBLE_EQ(e.pocketShare[1], 0.0);
}

}  // namespace
}  // namespace pak
