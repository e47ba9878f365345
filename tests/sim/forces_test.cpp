#include "sim/forces.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace pak;

TEST(Forces, RepulsionFollowsEquation42) {
  // u = (3, 4), |u| = 5: F = k u/|u| / (ς + 25) = 80 (0.6, 0.8) / 26.
  Vec2 f = forces::repulsion({3, 4}, {0, 0}, 80.0, 1.0);
  EXPECT_NEAR(f.x, 80.0 * 0.6 / 26.0, 1e-12);
  EXPECT_NEAR(f.y, 80.0 * 0.8 / 26.0, 1e-12);
}

TEST(Forces, RepulsionIsBoundedBySoftParameter) {
  Vec2 f = forces::repulsion({1e-9, 0}, {0, 0}, 80.0, 1.0);
  EXPECT_LE(length(f), 80.0);
  EXPECT_GT(length(f), 79.9);
  EXPECT_EQ(length(forces::repulsion({2, 2}, {2, 2}, 80.0, 1.0)), 0.0);
}

TEST(Forces, EdgeSpringIsQuadraticAndRestoring) {
  // Stretched by 2 along x: force on a is +k·4 toward b.
  Vec2 f = forces::edge({0, 0}, {12, 0}, 10.0, 40.0);
  EXPECT_NEAR(f.x, 160.0, 1e-12);
  EXPECT_NEAR(f.y, 0.0, 1e-12);
  // Compressed by 3: pushes a away from b with k·9.
  Vec2 g = forces::edge({0, 0}, {0, 7}, 10.0, 40.0);
  EXPECT_NEAR(g.y, -360.0, 1e-12);
  // At rest: nothing.
  EXPECT_EQ(length(forces::edge({1, 1}, {1, 11}, 10.0, 40.0)), 0.0);
}

TEST(Forces, OverlapPullsTowardCentroid) {
  Vec2 f = forces::overlap({1, 1}, {3, 5}, 80.0);
  EXPECT_DOUBLE_EQ(f.x, 160.0);
  EXPECT_DOUBLE_EQ(f.y, 320.0);
}

TEST(Forces, BoundaryPullsTowardClosestPoint) {
  Vec2 f = forces::boundary({10, -2}, {10, 0}, 80.0);
  EXPECT_DOUBLE_EQ(f.x, 0.0);
  EXPECT_DOUBLE_EQ(f.y, 160.0);
}

TEST(Forces, TorsionTurnsBackTowardRestDirection) {
  // Vertex at +x from the centre, rest direction +y (counter-clockwise): push along +y.
  Vec2 f = forces::torsion({2, 0}, {0, 0}, {0, 1}, 1.0);
  EXPECT_NEAR(f.x, 0.0, 1e-12);
  EXPECT_NEAR(f.y, 1.0, 1e-12);
  // Rest direction -y: push along -y. Unit magnitude k regardless of the radius.
  Vec2 g = forces::torsion({5, 0}, {0, 0}, {0, -1}, 2.0);
  EXPECT_NEAR(g.y, -2.0, 1e-12);
  // Aligned: no force.
  EXPECT_EQ(length(forces::torsion({3, 0}, {0, 0}, {1, 0}, 1.0)), 0.0);
}

namespace pak {
namespace {

// The same laws in (x, y, t): a spacetime pair at distance 5 repels as a planar one does.
TEST(Forces, SpacetimeRepulsionAndSpringsMatchThePlane) {
  const Vec3 f = forces::repulsion(Vec3{3, 0, 4}, Vec3{0, 0, 0}, 80.0, 1.0);
  const Vec2 g = forces::repulsion(Vec2{3, 4}, Vec2{0, 0}, 80.0, 1.0);
  EXPECT_NEAR(length(f), length(g), 1e-12);
  EXPECT_NEAR(f.t / f.x, 4.0 / 3.0, 1e-12);
  const Vec3 e = forces::edge(Vec3{0, 0, 0}, Vec3{0, 0, 12}, 10.0, 40.0);
  EXPECT_NEAR(e.t, 40.0 * 4.0, 1e-9);  // stretched by 2: k·2² toward the other end
  EXPECT_EQ(e.x, 0.0);
}

}  // namespace
}  // namespace pak
