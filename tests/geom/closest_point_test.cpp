#include "pak/geom/closest_point.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace pak;

TEST(ClosestPoint, OnSegment) {
  double t = -1.0;
  Vec2 q = closestPointOnSegment({5, 3}, {0, 0}, {10, 0}, &t);
  EXPECT_EQ(q, (Vec2{5, 0}));
  EXPECT_DOUBLE_EQ(t, 0.5);
  q = closestPointOnSegment({-3, 4}, {0, 0}, {10, 0}, &t);
  EXPECT_EQ(q, (Vec2{0, 0}));
  EXPECT_EQ(t, 0.0);
  q = closestPointOnSegment({12, -1}, {0, 0}, {10, 0}, &t);
  EXPECT_EQ(q, (Vec2{10, 0}));
  EXPECT_EQ(t, 1.0);
  // Diagonal segment: the foot of the perpendicular.
  q = closestPointOnSegment({0, 2}, {0, 0}, {2, 2});
  EXPECT_DOUBLE_EQ(q.x, 1.0);
  EXPECT_DOUBLE_EQ(q.y, 1.0);
  // Degenerate segment.
  q = closestPointOnSegment({3, 4}, {1, 1}, {1, 1}, &t);
  EXPECT_EQ(q, (Vec2{1, 1}));
  EXPECT_EQ(t, 0.0);
}

TEST(ClosestPoint, OnPolyline) {
  Polyline line{{0, 0}, {10, 0}, {10, 10}};
  ClosestPoint c = closestPointOnPolyline({12, 7}, line);
  EXPECT_EQ(c.point, (Vec2{10, 7}));
  EXPECT_DOUBLE_EQ(c.distance, 2.0);
  EXPECT_EQ(c.segment, 1u);
  EXPECT_DOUBLE_EQ(c.t, 0.7);
  // A polyline is open: the point near the missing closing edge goes to a vertex.
  c = closestPointOnPolyline({3, 5}, line);
  EXPECT_DOUBLE_EQ(c.distance, 5.0);
  EXPECT_EQ(c.segment, 0u);
  ClosestPoint single = closestPointOnPolyline({3, 4}, {{0, 0}});
  EXPECT_DOUBLE_EQ(single.distance, 5.0);
  EXPECT_TRUE(std::isinf(closestPointOnPolyline({0, 0}, {}).distance));
}

TEST(ClosestPoint, OnRingIncludesClosingEdge) {
  Ring square{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  ClosestPoint c = closestPointOnRing({-2, 4}, square);
  EXPECT_EQ(c.point, (Vec2{0, 4}));
  EXPECT_DOUBLE_EQ(c.distance, 2.0);
  EXPECT_EQ(c.segment, 3u);
  EXPECT_DOUBLE_EQ(c.t, 0.6);
  c = closestPointOnRing({5, 4}, square);  // inside: nearest side is the bottom
  EXPECT_DOUBLE_EQ(c.distance, 4.0);
  EXPECT_EQ(c.segment, 0u);
  EXPECT_TRUE(std::isinf(closestPointOnRing({0, 0}, {}).distance));
}

TEST(ClosestPoint, OnRegionBoundaryIncludesHoles) {
  Region r{Polygon{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{{4, 4}, {4, 6}, {6, 6}, {6, 4}}}},
           Polygon{{{20, 0}, {30, 0}, {30, 10}}, {}}};
  ClosestPoint c = closestPointOnBoundary({5, 3}, r);
  EXPECT_DOUBLE_EQ(c.distance, 1.0);
  EXPECT_EQ(c.point, (Vec2{5, 4}));
  EXPECT_EQ(c.segment, 4u + 3u);  // the hole's last edge (6,4)->(4,4)
  c = closestPointOnBoundary({31, 5}, r);
  EXPECT_DOUBLE_EQ(c.distance, 1.0);
  EXPECT_EQ(c.segment, 8u + 1u);
  EXPECT_TRUE(std::isinf(closestPointOnBoundary({0, 0}, Region{}).distance));
}
