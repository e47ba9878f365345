#include "pak/geom/clipping.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "pak/error.hpp"

using namespace pak;

namespace {

Ring square(double x0, double y0, double side) {
  return {{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}};
}
Region squareRegion(double x0, double y0, double side) { return {Polygon{square(x0, y0, side), {}}}; }

void expectNormalized(const Region& r) {
  for (const Polygon& p : r) {
    EXPECT_GT(signedArea(p.outer), 0.0);
    for (const Ring& h : p.holes) EXPECT_LT(signedArea(h), 0.0);
  }
}

}  // namespace

TEST(Clipping, UnionDifferenceIntersectionOfOverlappingSquares) {
  Region a = squareRegion(0, 0, 10), b = squareRegion(5, 5, 10);
  Region u = unite(a, b);
  ASSERT_EQ(u.size(), 1u);
  EXPECT_NEAR(area(u), 175.0, 1e-9);
  EXPECT_EQ(u[0].outer.size(), 8u);
  Region d = subtract(a, b);
  EXPECT_NEAR(area(d), 75.0, 1e-9);
  Region i = intersect(a, b);
  ASSERT_EQ(i.size(), 1u);
  EXPECT_NEAR(area(i), 25.0, 1e-9);
  EXPECT_NEAR(bounds(i).min.x, 5.0, 1e-12);
  EXPECT_NEAR(bounds(i).max.y, 10.0, 1e-12);
  expectNormalized(u);
  expectNormalized(d);
  expectNormalized(i);
}

TEST(Clipping, DifferenceMakesAHole) {
  Region r = subtract(squareRegion(0, 0, 10), squareRegion(3, 3, 2));
  ASSERT_EQ(r.size(), 1u);
  ASSERT_EQ(r[0].holes.size(), 1u);
  EXPECT_NEAR(area(r), 96.0, 1e-9);
  expectNormalized(r);
  // An island inside the hole comes back as its own polygon.
  Region withIsland = unite(r, squareRegion(3.5, 3.5, 1));
  EXPECT_EQ(withIsland.size(), 2u);
  EXPECT_NEAR(area(withIsland), 97.0, 1e-9);
}

TEST(Clipping, InputOrientationDoesNotMatter) {
  Ring cw = square(0, 0, 10);
  std::reverse(cw.begin(), cw.end());
  Region a{Polygon{cw, {square(2, 2, 2)}}};  // outer clockwise, hole counter-clockwise
  EXPECT_NEAR(area(unite(a, Region{})), 96.0, 1e-9);
  EXPECT_NEAR(area(intersect(a, squareRegion(0, 0, 5))), 21.0, 1e-9);
}

TEST(Clipping, UniteMany) {
  std::vector<Region> parts;
  for (int i = 0; i < 5; ++i) parts.push_back(squareRegion(i * 1.0, 0, 2));
  Region u = unite(parts);
  ASSERT_EQ(u.size(), 1u);
  EXPECT_NEAR(area(u), 12.0, 1e-9);
  EXPECT_TRUE(unite(std::vector<Region>{}).empty());
}

TEST(Clipping, EvenOddVersusNonZeroOnNestedSameDirectionRings) {
  std::vector<Ring> rings{square(0, 0, 10), square(2, 2, 4)};  // both counter-clockwise
  Region evenOdd = regionFromRings(rings, FillRule::EvenOdd);
  ASSERT_EQ(evenOdd.size(), 1u);
  EXPECT_EQ(evenOdd[0].holes.size(), 1u);
  EXPECT_NEAR(area(evenOdd), 84.0, 1e-9);
  Region nonZero = regionFromRings(rings, FillRule::NonZero);
  ASSERT_EQ(nonZero.size(), 1u);
  EXPECT_TRUE(nonZero[0].holes.empty());
  EXPECT_NEAR(area(nonZero), 100.0, 1e-9);
  // With the inner ring reversed, non-zero makes the hole too.
  std::reverse(rings[1].begin(), rings[1].end());
  EXPECT_NEAR(area(regionFromRings(rings, FillRule::NonZero)), 84.0, 1e-9);
}

TEST(Clipping, SelfIntersectingBowTieBecomesTwoTriangles) {
  Ring bowTie{{0, 0}, {2, 2}, {2, 0}, {0, 2}};
  Region r = regionFromRings({bowTie}, FillRule::NonZero);
  EXPECT_EQ(r.size(), 2u);
  EXPECT_NEAR(area(r), 2.0, 1e-9);
  expectNormalized(r);
}

TEST(Clipping, DegenerateInputGivesEmptyRegions) {
  EXPECT_TRUE(regionFromRings({Ring{}, Ring{{0, 0}, {1, 1}}}, FillRule::NonZero).empty());
  EXPECT_TRUE(regionFromRings({Ring{{0, 0}, {1, 1}, {2, 2}}}, FillRule::NonZero).empty());
  EXPECT_TRUE(unite(Region{}, Region{}).empty());
  EXPECT_TRUE(intersect(squareRegion(0, 0, 1), squareRegion(5, 5, 1)).empty());
  EXPECT_TRUE(offset(Region{}, 1.0).empty());
  EXPECT_TRUE(offsetPolyline({}, 1.0).empty());
  EXPECT_TRUE(offsetPolyline({{0, 0}, {1, 0}}, 0.0).empty());
}

TEST(Clipping, BadInputThrows) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(regionFromRings({Ring{{0, 0}, {1, nan}, {0, 1}}}, FillRule::NonZero), InputError);
  EXPECT_THROW(unite(squareRegion(0, 0, 1e30), Region{}), InputError);
  EXPECT_THROW(unite(squareRegion(0, 0, 1), Region{}, ClipOptions{0.0}), InputError);
  EXPECT_THROW(offset(squareRegion(0, 0, 1), nan), InputError);
  OffsetOptions bad;
  bad.arcTolerance = 0.0;
  EXPECT_THROW(offset(squareRegion(0, 0, 1), 1.0, bad), InputError);
}

TEST(Clipping, OffsetOfSquareWithRoundJoins) {
  const double s = 10.0, d = 2.0;
  OffsetOptions options;
  options.arcTolerance = 0.001;
  Region grown = offset(squareRegion(0, 0, s), d, options);
  ASSERT_EQ(grown.size(), 1u);
  const double exact = s * s + 4.0 * s * d + std::numbers::pi * d * d;
  // The polygonal arcs lie inside the true arcs by at most the arc tolerance.
  EXPECT_LT(area(grown), exact + 1e-6);
  EXPECT_GT(area(grown), exact - 2.0 * std::numbers::pi * d * options.arcTolerance);
  EXPECT_NEAR(bounds(grown).min.x, -d, 1e-3);
  EXPECT_NEAR(bounds(grown).max.y, s + d, 1e-3);
  // Shrinking a square keeps its corners sharp: side s - 2d.
  Region shrunk = offset(squareRegion(0, 0, s), -d, options);
  EXPECT_NEAR(area(shrunk), (s - 2 * d) * (s - 2 * d), 1e-6);
  // Shrinking past half the side removes it.
  EXPECT_TRUE(offset(squareRegion(0, 0, s), -6.0, options).empty());
}

TEST(Clipping, OffsetGrowsHolesInward) {
  Region r{Polygon{square(0, 0, 10), {square(4, 4, 2)}}};
  Region grown = offset(r, 0.5);
  ASSERT_EQ(grown.size(), 1u);
  ASSERT_EQ(grown[0].holes.size(), 1u);
  EXPECT_NEAR(std::abs(signedArea(grown[0].holes[0])), 1.0, 1e-6);  // 2 - 2*0.5 = 1 per side
  Region closed = offset(r, 1.5);
  EXPECT_TRUE(closed[0].holes.empty());
}

TEST(Clipping, OffsetPolylineIsAStadium) {
  const double len = 10.0, d = 1.0;
  OffsetOptions options;
  options.arcTolerance = 0.0005;
  Region band = offsetPolyline({{0, 0}, {len, 0}}, d, options);
  ASSERT_EQ(band.size(), 1u);
  const double exact = 2.0 * d * len + std::numbers::pi * d * d;
  EXPECT_LT(area(band), exact + 1e-6);
  EXPECT_GT(area(band), exact - 2.0 * std::numbers::pi * d * options.arcTolerance);
  // A single point becomes a disc.
  Region disc = offsetPolyline({{3, 3}}, d, options);
  EXPECT_NEAR(area(disc), std::numbers::pi, 0.01);
}

TEST(Clipping, OffsetPolylineOfClosedLoopIsAnAnnulus) {
  const double s = 10.0, d = 1.0;
  Polyline loop = square(0, 0, s);
  loop.push_back(loop.front());
  OffsetOptions options;
  options.arcTolerance = 0.0005;
  Region band = offsetPolyline(loop, d, options);
  ASSERT_EQ(band.size(), 1u);
  ASSERT_EQ(band[0].holes.size(), 1u);
  const double exact = s * s + 4 * s * d + std::numbers::pi * d * d - (s - 2 * d) * (s - 2 * d);
  EXPECT_NEAR(area(band), exact, 0.01);
}

TEST(Clipping, PrecisionRoundsToTheGrid) {
  ClipOptions coarse{0.5};
  Region r = unite(squareRegion(0.1, 0.1, 10.0), Region{}, coarse);
  EXPECT_DOUBLE_EQ(bounds(r).min.x, 0.0);
  EXPECT_DOUBLE_EQ(bounds(r).max.x, 10.0);
}

TEST(Clipping, ManyRingsAreUnitedColumnByColumnToTheSameRegion) {
  // 100 × 50 pairs of overlapping squares: more rings than one union takes, in columns apart.
  std::vector<Ring> rings;
  for (int c = 0; c < 100; ++c)
    for (int r = 0; r < 50; ++r) {
      rings.push_back(Ring{{2.0 * c, 2.0 * r}, {2.0 * c + 1, 2.0 * r}, {2.0 * c + 1, 2.0 * r + 1}, {2.0 * c, 2.0 * r + 1}});
      rings.push_back(Ring{{2.0 * c + 0.5, 2.0 * r}, {2.0 * c + 1.5, 2.0 * r}, {2.0 * c + 1.5, 2.0 * r + 1}, {2.0 * c + 0.5, 2.0 * r + 1}});
    }
  const Region united = regionFromRings(rings, FillRule::NonZero);
  EXPECT_EQ(united.size(), 5000u);
  EXPECT_NEAR(area(united), 5000 * 1.5, 1e-6);
  // Even-odd: the overlaps cancel, each pair leaves two strips.
  const Region evenOdd = regionFromRings(rings, FillRule::EvenOdd);
  EXPECT_EQ(evenOdd.size(), 10000u);
  EXPECT_NEAR(area(evenOdd), 5000 * 1.0, 1e-6);
  // A ring spanning every column joins them into one run: one polygon.
  rings.push_back(Ring{{0, -1}, {200, -1}, {200, 101}, {0, 101}});
  EXPECT_EQ(regionFromRings(rings, FillRule::NonZero).size(), 1u);
}
