// The guide-driven vector field (thesis 3.3.3): constraints reproduced at the guides, smooth
// between them, and a straight guide gives a uniform field.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "pak/error.hpp"
#include "pak/flow/vector_field.hpp"

namespace pak {
namespace {

Region square(double side) { return Region{Polygon{Ring{{0, 0}, {side, 0}, {side, side}, {0, side}}, {}}}; }

double angleBetween(Vec2 a, Vec2 b) { return std::acos(std::clamp(dot(normalized(a), normalized(b)), -1.0, 1.0)); }

TEST(VectorField, AStraightGuideGivesAUniformField) {
  VectorFieldOptions o;
  o.sampleSpacing = 2.0;
  o.resolution = 64;
  VectorField f = buildVectorField(square(100), {{{10, 30}, {90, 70}}}, o);
  const Vec2 expected = normalized(Vec2{80, 40});
  for (double y = 0; y <= 100; y += 7)
    for (double x = 0; x <= 100; x += 7) {
      Vec2 v = f.at({x, y});
      EXPECT_NEAR(v.x, expected.x, 1e-6) << x << "," << y;
      EXPECT_NEAR(v.y, expected.y, 1e-6) << x << "," << y;
    }
}

TEST(VectorField, TwoGuidesAreFollowedAndTheFieldTurnsSmoothlyBetweenThem) {
  VectorFieldOptions o;
  o.sampleSpacing = 1.0;
  o.resolution = 100;
  // Two parallel guides are both reproduced.
  VectorField f = buildVectorField(square(100), {{{0, 5}, {100, 5}}, {{0, 95}, {100, 95}}}, o);
  for (double x = 10; x <= 90; x += 10) {
    EXPECT_LT(angleBetween(f.at({x, 5}), {1, 0}), 0.05) << x;
    EXPECT_LT(angleBetween(f.at({x, 95}), {1, 0}), 0.05) << x;
  }
  VectorField g = buildVectorField(square(100), {{{0, 5}, {100, 5}}, {{95, 0}, {95, 100}}}, o);
  EXPECT_LT(angleBetween(g.at({50, 5}), {1, 0}), 0.05);
  EXPECT_LT(angleBetween(g.at({95, 50}), {0, 1}), 0.05);
  // Going up the middle, from the bottom guide toward the corner where the right one runs,
  // the angle never jumps.
  double previous = std::atan2(g.at({5, 5}).y, g.at({5, 5}).x);
  for (double t = 6; t <= 95; t += 1) {
    Vec2 w = g.at({50, t});
    double a = std::atan2(w.y, w.x);
    EXPECT_LT(std::abs(a - previous), 0.1) << t;
    previous = a;
  }
}

TEST(VectorField, ACircularGuideGivesAFieldTangentAlongIt) {
  VectorFieldOptions o;
  o.sampleSpacing = 1.0;
  o.resolution = 128;
  Polyline circle;
  for (int k = 0; k <= 200; ++k) {
    double a = 2.0 * M_PI * k / 200.0;
    circle.push_back(Vec2{50, 50} + Vec2{std::cos(a), std::sin(a)} * 35.0);
  }
  VectorField f = buildVectorField(square(100), {circle}, o);
  for (int k = 0; k < 24; ++k) {
    double a = 2.0 * M_PI * k / 24.0;
    Vec2 p = Vec2{50, 50} + Vec2{std::cos(a), std::sin(a)} * 35.0;
    EXPECT_LT(angleBetween(f.at(p), {-std::sin(a), std::cos(a)}), 0.08) << k;
  }
}

TEST(VectorField, AdvanceFollowsTheFieldWithRungeKutta) {
  VectorFieldOptions o;
  o.sampleSpacing = 2.0;
  o.resolution = 32;
  VectorField f = buildVectorField(square(100), {{{0, 50}, {100, 50}}}, o);
  Vec2 p = f.advance({20, 30}, 5.0);
  EXPECT_NEAR(p.x, 25.0, 1e-9);
  EXPECT_NEAR(p.y, 30.0, 1e-9);
  Vec2 back = f.advance(p, -5.0);
  EXPECT_NEAR(back.x, 20.0, 1e-9);
}

TEST(VectorField, NoUsableGuideIsAnInputError) {
  EXPECT_THROW(buildVectorField(square(10), {}, {}), InputError);
  EXPECT_THROW(buildVectorField(square(10), {{{1, 1}, {1, 1}}}, {}), InputError);
}

}  // namespace
}  // namespace pak
