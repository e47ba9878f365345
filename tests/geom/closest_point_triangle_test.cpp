// closestPointOnTriangle against known answers and a dense sampling of the triangle.
#include <gtest/gtest.h>

#include "pak/geom/closest_point_triangle.hpp"
#include "pak/geom/rng.hpp"
#include "pak/geom/vec3.hpp"

namespace pak {
namespace {

const Vec3 kA{0, 0, 0}, kB{4, 0, 0}, kC{0, 4, 0};

TEST(ClosestPointOnTriangle, FaceVertexAndEdgeRegions) {
  EXPECT_EQ(closestPointOnTriangle({1, 1, 5}, kA, kB, kC), (Vec3{1, 1, 0}));    // above the face
  EXPECT_EQ(closestPointOnTriangle({-2, -3, 1}, kA, kB, kC), kA);              // beyond vertex A
  EXPECT_EQ(closestPointOnTriangle({9, -1, 0}, kA, kB, kC), kB);               // beyond vertex B
  EXPECT_EQ(closestPointOnTriangle({2, -5, 2}, kA, kB, kC), (Vec3{2, 0, 0}));  // edge AB
  const Vec3 onBC = closestPointOnTriangle({4, 4, 0}, kA, kB, kC);            // edge BC
  EXPECT_NEAR(onBC.x, 2.0, 1e-12);
  EXPECT_NEAR(onBC.y, 2.0, 1e-12);
}

TEST(ClosestPointOnTriangle, NoSampleOfTheTriangleIsCloser) {
  Rng rng(5);
  const Vec3 a{1, 2, 3}, b{7, -1, 2}, c{2, 5, 9};
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 p{rng.uniform(-10, 15), rng.uniform(-10, 15), rng.uniform(-10, 15)};
    const double d = distance(p, closestPointOnTriangle(p, a, b, c));
    for (int i = 0; i <= 40; ++i)
      for (int j = 0; i + j <= 40; ++j) {
        const Vec3 q = a + (b - a) * (i / 40.0) + (c - a) * (j / 40.0);
        ASSERT_LE(d, distance(p, q) + 1e-9);
      }
  }
}

}  // namespace
}  // namespace pak
