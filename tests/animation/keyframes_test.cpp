// Keyframe tracks: Catmull–Rom (finite-difference tangents) through keys at uneven times.
#include "pak/animation/keyframes.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace pak {
namespace {

const std::vector<ScalarKey> kWave{{0.0, 0.0}, {0.2, 3.0}, {0.7, -1.0}, {1.0, 2.0}};

TEST(Keyframes, PassesThroughEveryKey) {
  for (bool periodic : {false, true})
    for (const ScalarKey& key : kWave) EXPECT_NEAR(sampleTrack(kWave, key.t, 99.0, periodic), key.value, 1e-12);
  const std::vector<PointKey> points{{0.1, {1, 2}}, {0.4, {-3, 5}}, {0.9, {4, 4}}};
  for (const PointKey& key : points) {
    const Vec2 p = sampleTrack(points, key.t, Vec2{}, false);
    EXPECT_NEAR(p.x, key.value.x, 1e-12);
    EXPECT_NEAR(p.y, key.value.y, 1e-12);
  }
}

TEST(Keyframes, ConstantOutsideTheKeys) {
  const std::vector<ScalarKey> keys{{0.25, 4.0}, {0.5, 6.0}, {0.75, 1.0}};
  EXPECT_EQ(sampleTrack(keys, 0.0, 0.0), 4.0);
  EXPECT_EQ(sampleTrack(keys, 0.1, 0.0), 4.0);
  EXPECT_EQ(sampleTrack(keys, 0.9, 0.0), 1.0);
  EXPECT_EQ(sampleTrack(keys, 1.0, 0.0), 1.0);
  EXPECT_EQ(sampleTrack(keys, -3.0, 0.0), 4.0);
}

TEST(Keyframes, KeysOnALineGiveTheLine) {
  // Uneven spacing on purpose: the tangents are slopes per unit t, so the line is exact.
  const std::vector<ScalarKey> keys{{0.0, 1.0}, {0.1, 1.5}, {0.45, 3.25}, {1.0, 6.0}};
  for (double t = 0.0; t <= 1.0; t += 0.01) EXPECT_NEAR(sampleTrack(keys, t, 0.0), 1.0 + 5.0 * t, 1e-12) << t;
  const std::vector<PointKey> points{{0.0, {0, 0}}, {0.3, {3, -6}}, {1.0, {10, -20}}};
  for (double t = 0.0; t <= 1.0; t += 0.05) {
    const Vec2 p = sampleTrack(points, t, Vec2{});
    EXPECT_NEAR(p.x, 10 * t, 1e-12);
    EXPECT_NEAR(p.y, -20 * t, 1e-12);
  }
  // Periodic with keys at both ends: a steady rotation 0° → 72° keeps its slope over the seam.
  const std::vector<ScalarKey> turn{{0.0, 0.0}, {1.0, 72.0}};
  for (double t = 0.0; t <= 1.0; t += 0.1) EXPECT_NEAR(sampleTrack(turn, t, 0.0, true), 72.0 * t, 1e-12);
}

TEST(Keyframes, SingleKeyAndEmpty) {
  EXPECT_EQ(sampleTrack(std::vector<ScalarKey>{{0.3, 7.0}}, 0.9, 1.0), 7.0);
  EXPECT_EQ(sampleTrack(std::vector<ScalarKey>{{0.3, 7.0}}, 0.1, 1.0, true), 7.0);
  EXPECT_EQ(sampleTrack(std::vector<ScalarKey>{}, 0.5, 1.25), 1.25);
  EXPECT_EQ(sampleTrack(std::vector<PointKey>{}, 0.5, Vec2{2, 3}), (Vec2{2, 3}));
}

TEST(Keyframes, MidpointOfAnEvenSegment) {
  // Keys 0, 1, 0 at t = 0, 0.5, 1: tangents 2, 0, −2; the Hermite midpoint of [0, 0.5] is
  // 0.5·0 + 0.5·1 + h/8·(m₀ − m₁) = 0.5 + 0.5/8·2 = 0.625.
  const std::vector<ScalarKey> bump{{0.0, 0.0}, {0.5, 1.0}, {1.0, 0.0}};
  EXPECT_NEAR(sampleTrack(bump, 0.25, 0.0), 0.625, 1e-12);
  // Periodic: the tangent at t = 0 is taken across the seam, (1 − 1)/(0.5 + 0.5) = 0, so the
  // midpoint is 0.5 + 0.5/8·(0 − 0) = 0.5.
  EXPECT_NEAR(sampleTrack(bump, 0.25, 0.0, true), 0.5, 1e-12);
}

double derivative(const std::vector<ScalarKey>& keys, double t, bool periodic, double h) {
  return (sampleTrack(keys, t + h, 0.0, periodic) - sampleTrack(keys, t - h, 0.0, periodic)) / (2 * h);
}

TEST(Keyframes, PeriodicIsC1AtTheSeam) {
  const double h = 1e-6;
  // Slope just after t = 0 equals the slope just before t = 1.
  const double start = (sampleTrack(kWave, h, 0.0, true) - sampleTrack(kWave, 0.0, 0.0, true)) / h;
  const double end = (sampleTrack(kWave, 1.0, 0.0, true) - sampleTrack(kWave, 1.0 - h, 0.0, true)) / h;
  EXPECT_NEAR(start, end, 1e-3);
  // Open, the same keys have a kink there.
  const double openStart = (sampleTrack(kWave, h, 0.0) - sampleTrack(kWave, 0.0, 0.0)) / h;
  const double openEnd = (sampleTrack(kWave, 1.0, 0.0) - sampleTrack(kWave, 1.0 - h, 0.0)) / h;
  EXPECT_GT(std::abs(openStart - openEnd), 1.0);

  // A closed loop (last value = first value), its keys away from the ends: it wraps, and is
  // continuous and C1 everywhere, the seam included.
  const std::vector<ScalarKey> inner{{0.2, 1.0}, {0.5, 4.0}, {0.8, 2.0}};
  EXPECT_NEAR(sampleTrack(inner, 0.0, 0.0, true), sampleTrack(inner, 1.0, 0.0, true), 1e-12);
  EXPECT_NE(sampleTrack(inner, 0.9, 0.0, true), 2.0);  // not held constant after the last key
  for (double t : {0.2, 0.5, 0.8})
    EXPECT_NEAR(derivative(inner, t - 1e-4, true, h), derivative(inner, t + 1e-4, true, h), 0.05) << t;
  const double wrapStart = (sampleTrack(inner, h, 0.0, true) - sampleTrack(inner, 0.0, 0.0, true)) / h;
  const double wrapEnd = (sampleTrack(inner, 1.0, 0.0, true) - sampleTrack(inner, 1.0 - h, 0.0, true)) / h;
  EXPECT_NEAR(wrapStart, wrapEnd, 1e-3);
}

TEST(Keyframes, PeriodicPointTrack) {
  const std::vector<PointKey> loop{{0.0, {0, 0}}, {0.3, {10, 0}}, {0.6, {10, 10}}, {1.0, {0, 0}}};
  const double h = 1e-6;
  const Vec2 start = (sampleTrack(loop, h, Vec2{}, true) - sampleTrack(loop, 0.0, Vec2{}, true)) / h;
  const Vec2 end = (sampleTrack(loop, 1.0, Vec2{}, true) - sampleTrack(loop, 1.0 - h, Vec2{}, true)) / h;
  EXPECT_NEAR(start.x, end.x, 1e-3);
  EXPECT_NEAR(start.y, end.y, 1e-3);
  // Across the seam: (p₁ − p₂)/(t₁ + 1 − t₂) = ((10, 0) − (10, 10)) / 0.7.
  EXPECT_NEAR(start.x, 0.0, 1e-3);
  EXPECT_NEAR(start.y, -10.0 / 0.7, 1e-3);
}

}  // namespace
}  // namespace pak
