#include "sim/explicit_euler.hpp"

#include <gtest/gtest.h>

#include <limits>

using namespace pak;

TEST(ExplicitEuler, UndampedStepIsVelocityFromForceThenPositionFromVelocity) {
  const ExplicitEuler euler(0.1, 100.0, 0.0);
  Vec2 x{1.0, 2.0}, v{3.0, -1.0};
  euler.advance(x, v, Vec2{10.0, 20.0});
  // v = (3, -1) + 0.1 (10, 20) = (4, 1); x = (1, 2) + 0.1 (4, 1).
  EXPECT_DOUBLE_EQ(v.x, 4.0);
  EXPECT_DOUBLE_EQ(v.y, 1.0);
  EXPECT_DOUBLE_EQ(x.x, 1.4);
  EXPECT_DOUBLE_EQ(x.y, 2.1);
}

TEST(ExplicitEuler, DampingScalesTheOldVelocityOnly) {
  // v ← (1 − d) v + Δt f: d = 0.2 keeps 0.8 of (5, 0) and adds 0.5 (0, 2) in full.
  const ExplicitEuler euler(0.5, 100.0, 0.2);
  Vec2 x, v{5.0, 0.0};
  euler.advance(x, v, Vec2{0.0, 2.0});
  EXPECT_DOUBLE_EQ(v.x, 4.0);
  EXPECT_DOUBLE_EQ(v.y, 1.0);
  EXPECT_DOUBLE_EQ(x.x, 2.0);
  EXPECT_DOUBLE_EQ(x.y, 0.5);
}

TEST(ExplicitEuler, SameStepInSpacetime) {
  // AnimationPak's vertices take the same formula in (x, y, t).
  const ExplicitEuler euler(0.5, 100.0, 0.2);
  Vec3 x, v{5.0, 0.0, -10.0};
  euler.advance(x, v, Vec3{0.0, 2.0, 4.0});
  EXPECT_DOUBLE_EQ(v.x, 4.0);
  EXPECT_DOUBLE_EQ(v.y, 1.0);
  EXPECT_DOUBLE_EQ(v.t, -6.0);
  EXPECT_DOUBLE_EQ(x.t, -3.0);
}

TEST(ExplicitEuler, CapKeepsTheDirectionAndLimitsTheSpeed) {
  const ExplicitEuler euler(0.1, 2.0, 0.0);
  Vec3 x{0.0, 0.0, 10.0}, v;
  euler.advance(x, v, Vec3{300.0, 0.0, 400.0});  // Δt f = (30, 0, 40): speed 50
  EXPECT_NEAR(length(v), 2.0, 1e-12);
  EXPECT_NEAR(v.x, 1.2, 1e-12);
  EXPECT_NEAR(v.t, 1.6, 1e-12);
  EXPECT_NEAR(x.x, 0.12, 1e-12);
  EXPECT_NEAR(x.t, 10.16, 1e-12);
  // Below the cap nothing is scaled.
  Vec3 y, w;
  euler.advance(y, w, Vec3{10.0, 0.0, 0.0});
  EXPECT_DOUBLE_EQ(w.x, 1.0);
}

TEST(ExplicitEuler, FiniteChecks) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Vec2 points[] = {{0, 0}, {1, 2}, {nan, 0}};
  EXPECT_TRUE(allFinite(points, points + 2));
  EXPECT_FALSE(allFinite(points, points + 3));
  EXPECT_FALSE(isFinite(Vec3{0.0, 0.0, std::numeric_limits<double>::infinity()}));
}
