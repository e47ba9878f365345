#include "pak/geom/polygon.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace pak;

namespace {

Ring square(double x0, double y0, double side) {
  return {{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}};
}

Ring reversed(Ring r) {
  std::reverse(r.begin(), r.end());
  return r;
}

}  // namespace

TEST(Polygon, SignedAreaOfSquareAndTriangle) {
  EXPECT_DOUBLE_EQ(signedArea(square(0, 0, 10)), 100.0);
  EXPECT_DOUBLE_EQ(signedArea(reversed(square(0, 0, 10))), -100.0);
  EXPECT_DOUBLE_EQ(signedArea(Ring{{0, 0}, {4, 0}, {0, 3}}), 6.0);
  // Far from the origin the shoelace must not lose the area to cancellation.
  EXPECT_DOUBLE_EQ(signedArea(square(1e9, 1e9, 2)), 4.0);
}

TEST(Polygon, DegenerateRingsHaveZeroArea) {
  EXPECT_EQ(signedArea(Ring{}), 0.0);
  EXPECT_EQ(signedArea(Ring{{1, 1}, {2, 2}}), 0.0);
  EXPECT_EQ(signedArea(Ring{{0, 0}, {1, 1}, {2, 2}}), 0.0);
  EXPECT_FALSE(isCounterClockwise(Ring{{0, 0}, {1, 1}, {2, 2}}));
}

TEST(Polygon, Orientation) {
  EXPECT_TRUE(isCounterClockwise(square(0, 0, 1)));
  EXPECT_FALSE(isCounterClockwise(reversed(square(0, 0, 1))));
  Polygon p{reversed(square(0, 0, 10)), {square(2, 2, 2)}};
  normalizeOrientation(p);
  EXPECT_GT(signedArea(p.outer), 0.0);
  EXPECT_LT(signedArea(p.holes[0]), 0.0);
  EXPECT_DOUBLE_EQ(area(p), 96.0);
}

TEST(Polygon, AreaWithHolesIsOrientationIndependent) {
  Polygon p{square(0, 0, 10), {square(1, 1, 2), reversed(square(5, 5, 3))}};
  EXPECT_DOUBLE_EQ(area(p), 100.0 - 4.0 - 9.0);
  Region r{p, Polygon{square(20, 0, 1), {}}};
  EXPECT_DOUBLE_EQ(area(r), 88.0);
}

TEST(Polygon, PointInPolygonWithHole) {
  Polygon p{square(0, 0, 10), {square(4, 4, 2)}};
  EXPECT_TRUE(pointInPolygon({1, 1}, p));
  EXPECT_TRUE(pointInPolygon({9.5, 5}, p));
  EXPECT_FALSE(pointInPolygon({5, 5}, p));    // in the hole
  EXPECT_FALSE(pointInPolygon({11, 5}, p));   // outside
  EXPECT_FALSE(pointInPolygon({-1, -1}, p));
  EXPECT_TRUE(pointInRing({5, 5}, p.outer));
  Region r{p, Polygon{square(20, 0, 1), {}}};
  EXPECT_TRUE(pointInRegion({20.5, 0.5}, r));
  EXPECT_FALSE(pointInRegion({15, 0.5}, r));
  EXPECT_FALSE(pointInRing({0, 0}, Ring{{0, 0}, {1, 1}}));
}

TEST(Polygon, PointInConcaveRing) {
  // An L-shape: the notch at the top right is outside.
  Ring l{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  EXPECT_TRUE(pointInRing({0.5, 1.5}, l));
  EXPECT_TRUE(pointInRing({1.5, 0.5}, l));
  EXPECT_FALSE(pointInRing({1.5, 1.5}, l));
  // A ray through a vertex must not double count.
  EXPECT_TRUE(pointInRing({0.5, 1.0}, l));
}

TEST(Polygon, PerimeterAndLength) {
  EXPECT_DOUBLE_EQ(perimeter(square(0, 0, 10)), 40.0);
  EXPECT_DOUBLE_EQ(polylineLength(Polyline{{0, 0}, {3, 4}, {3, 0}}), 9.0);
  EXPECT_EQ(perimeter(Ring{{1, 1}}), 0.0);
  EXPECT_EQ(polylineLength(Polyline{}), 0.0);
}

TEST(Polygon, Bounds) {
  Region r{Polygon{square(0, 0, 10), {}}, Polygon{square(-5, 20, 1), {}}};
  Box b = bounds(r);
  EXPECT_EQ(b.min, (Vec2{-5, 0}));
  EXPECT_EQ(b.max, (Vec2{10, 21}));
  EXPECT_TRUE(bounds(Region{}).empty());
}

TEST(Polygon, Centroid) {
  Vec2 c = centroid(square(2, 4, 2));
  EXPECT_DOUBLE_EQ(c.x, 3.0);
  EXPECT_DOUBLE_EQ(c.y, 5.0);
  Vec2 t = centroid(Ring{{0, 0}, {3, 0}, {0, 3}});
  EXPECT_DOUBLE_EQ(t.x, 1.0);
  EXPECT_DOUBLE_EQ(t.y, 1.0);
  // A 4x4 square minus its left 2x4 half (as a hole touching nothing) -> shifted right.
  // Square [0,4]^2 with hole [0.5,1.5]x[0.5,3.5] (area 3): centroid x = (16*2 - 3*1)/13.
  Region r{Polygon{square(0, 0, 4), {Ring{{0.5, 0.5}, {1.5, 0.5}, {1.5, 3.5}, {0.5, 3.5}}}}};
  Vec2 rc = centroid(r);
  EXPECT_NEAR(rc.x, (32.0 - 3.0) / 13.0, 1e-12);
  EXPECT_NEAR(rc.y, 2.0, 1e-12);
  // Two equal squares: midpoint.
  Region two{Polygon{square(0, 0, 1), {}}, Polygon{reversed(square(10, 0, 1)), {}}};
  EXPECT_NEAR(centroid(two).x, 5.5, 1e-12);
  // Zero area falls back to the vertex average.
  Vec2 d = centroid(Ring{{0, 0}, {2, 0}, {4, 0}});
  EXPECT_DOUBLE_EQ(d.x, 2.0);
  EXPECT_EQ(centroid(Ring{}), (Vec2{}));
}

TEST(Polygon, CleanRing) {
  Ring r{{0, 0}, {0, 0}, {1, 0}, {1, 1}, {1, 1}, {0, 0}};
  Ring c = cleanRing(r);
  ASSERT_EQ(c.size(), 3u);
  EXPECT_EQ(c[0], (Vec2{0, 0}));
  EXPECT_EQ(c[1], (Vec2{1, 0}));
  EXPECT_EQ(c[2], (Vec2{1, 1}));
  Ring near{{0, 0}, {0.001, 0}, {1, 0}, {1, 1}, {0.0005, 0.0005}};
  EXPECT_EQ(cleanRing(near, 0.01).size(), 3u);
  EXPECT_TRUE(cleanRing(Ring{}).empty());
}

TEST(Polygon, FillHolesAndTransform) {
  Region r{Polygon{square(0, 0, 10), {square(1, 1, 2)}}};
  Region filled = fillHoles(r);
  ASSERT_EQ(filled.size(), 1u);
  EXPECT_TRUE(filled[0].holes.empty());
  EXPECT_DOUBLE_EQ(area(filled), 100.0);
  Region t = transformed(r, 2.0, {1, -1});
  EXPECT_DOUBLE_EQ(area(t), 4.0 * 96.0);
  EXPECT_EQ(t[0].outer[2], (Vec2{21, 19}));
  EXPECT_EQ(t[0].holes[0][0], (Vec2{3, 1}));
}
