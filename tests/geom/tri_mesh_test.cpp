#include "pak/geom/tri_mesh.hpp"

#include <gtest/gtest.h>

using namespace pak;

TEST(TriMesh, SignedArea) {
  EXPECT_DOUBLE_EQ(triangleSignedArea({0, 0}, {4, 0}, {0, 3}), 6.0);
  EXPECT_DOUBLE_EQ(triangleSignedArea({0, 0}, {0, 3}, {4, 0}), -6.0);
  EXPECT_EQ(triangleSignedArea({0, 0}, {1, 1}, {2, 2}), 0.0);
}

TEST(TriMesh, Barycentric) {
  const Vec2 a{0, 0}, b{4, 0}, c{0, 4};
  auto w = barycentric({1, 1}, a, b, c);
  EXPECT_DOUBLE_EQ(w[0], 0.5);
  EXPECT_DOUBLE_EQ(w[1], 0.25);
  EXPECT_DOUBLE_EQ(w[2], 0.25);
  auto atB = barycentric(b, a, b, c);
  EXPECT_DOUBLE_EQ(atB[1], 1.0);
  EXPECT_DOUBLE_EQ(atB[0], 0.0);
  // Outside: a negative weight, and the weights still reproduce the point.
  const Vec2 p{5, 1};
  auto o = barycentric(p, a, b, c);
  EXPECT_LT(o[0], 0.0);
  Vec2 back = a * o[0] + b * o[1] + c * o[2];
  EXPECT_NEAR(back.x, p.x, 1e-12);
  EXPECT_NEAR(back.y, p.y, 1e-12);
  // Orientation of the triangle does not change the weights.
  auto r = barycentric({1, 1}, a, c, b);
  EXPECT_DOUBLE_EQ(r[1], 0.25);
  // Degenerate triangle: a finite answer that sums to one.
  auto d = barycentric({1, 1}, a, a, a);
  EXPECT_DOUBLE_EQ(d[0] + d[1] + d[2], 1.0);
}
