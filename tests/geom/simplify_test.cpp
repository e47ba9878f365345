#include <gtest/gtest.h>

#include <cmath>

#include "pak/geom/closest_point.hpp"
#include "pak/geom/simplify.hpp"

namespace pak {
namespace {

double distanceToRing(Vec2 p, const Ring& ring) {
  double best = INFINITY;
  for (std::size_t k = 0; k < ring.size(); ++k)
    best = std::min(best, length(p - closestPointOnSegment(p, ring[k], ring[(k + 1) % ring.size()])));
  return best;
}

TEST(SimplifyRing, DropsCollinearVerticesOfASquare) {
  Ring square;
  for (int k = 0; k < 10; ++k) square.push_back({k * 1.0, 0.0});
  for (int k = 0; k < 10; ++k) square.push_back({10.0, k * 1.0});
  for (int k = 0; k < 10; ++k) square.push_back({10.0 - k, 10.0});
  for (int k = 0; k < 10; ++k) square.push_back({0.0, 10.0 - k});
  const Ring simple = simplifyRing(square, 1e-9);
  ASSERT_EQ(simple.size(), 4u);
  EXPECT_DOUBLE_EQ(std::abs(signedArea(simple)), 100.0);
}

TEST(SimplifyRing, StaysWithinToleranceOfACircle) {
  Ring circle;
  const int n = 2000;
  for (int k = 0; k < n; ++k) circle.push_back({100.0 * std::cos(2 * M_PI * k / n), 100.0 * std::sin(2 * M_PI * k / n)});
  const double tolerance = 0.05;
  const Ring simple = simplifyRing(circle, tolerance);
  // A chord of sagitta 0.05 on radius 100 spans about 2·√(2·100·0.05) ≈ 6.3: ~100 vertices.
  EXPECT_LT(simple.size(), 160u);
  EXPECT_GT(simple.size(), 60u);
  for (Vec2 p : circle) EXPECT_LE(distanceToRing(p, simple), tolerance + 1e-12);
}

TEST(SimplifyRing, KeepsTinyRingsAndZeroTolerance) {
  const Ring triangle{{0, 0}, {1, 0}, {0, 1}};
  EXPECT_EQ(simplifyRing(triangle, 10.0).size(), 3u);
  Ring square{{0, 0}, {0.5, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_EQ(simplifyRing(square, 0.0).size(), 5u);
}

}  // namespace
}  // namespace pak
