// Preferred orientations (thesis 4.5, eq. 4.6, Figure 4.11): elements end near the angle of
// the field at their position, measured from their art against the library's.
#include "pak/repulsion/orientation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "pak/error.hpp"
#include "pak/geom/verify.hpp"
#include "pak/io/scene_loader.hpp"
#include "pak/repulsion/repulsion.hpp"

using namespace pak;

namespace {

const std::string kExamples = std::string(PAK_SOURCE_DIR) + "/examples";
constexpr double kDegrees = 180.0 / std::numbers::pi;

// The least-squares rotation (radians) that takes the library's art points to the placed
// ones, both about their own mean: atan2(Σ r × u, Σ r · u).
double rotationOf(const PlacedElement& placed, const ElementArt& rest, Vec2* centre = nullptr) {
  std::vector<Vec2> from, to;
  for (const Shape& s : rest.shapes)
    for (const Subpath& sub : s.subpaths) from.insert(from.end(), sub.points.begin(), sub.points.end());
  for (const Shape& s : placed.art)
    for (const Subpath& sub : s.subpaths) to.insert(to.end(), sub.points.begin(), sub.points.end());
  EXPECT_EQ(from.size(), to.size());
  Vec2 a, b;
  for (std::size_t i = 0; i < from.size(); ++i) { a += from[i]; b += to[i]; }
  a = a / static_cast<double>(from.size());
  b = b / static_cast<double>(to.size());
  double c = 0.0, d = 0.0;
  for (std::size_t i = 0; i < from.size(); ++i) {
    c += cross(from[i] - a, to[i] - b);
    d += dot(from[i] - a, to[i] - b);
  }
  if (centre) *centre = b;
  return std::atan2(c, d);
}

double wrapped(double radians) { return std::remainder(radians, 2.0 * std::numbers::pi); }

RepulsionOptions quick() {
  RepulsionOptions o;
  o.gap = 14.0;
  o.count = 8;
  o.stop.targetFill = 0.45;
  o.stop.maxIterations = 2500;
  o.run.seed = 2;
  return o;
}

}  // namespace

TEST(Orientation, ParsesModesAndFields) {
  EXPECT_EQ(parseOrientationMode("upright"), OrientationMode::Upright);
  EXPECT_EQ(parseOrientationMode("field"), OrientationMode::Field);
  EXPECT_EQ(parseOrientationMode("random"), OrientationMode::Random);
  EXPECT_THROW(parseOrientationMode("sideways"), InputError);
  OrientationField f = parseOrientationField("y:-45:90.5");
  EXPECT_EQ(f.axis, 'y');
  EXPECT_DOUBLE_EQ(f.fromDegrees, -45.0);
  EXPECT_DOUBLE_EQ(f.toDegrees, 90.5);
  for (const char* bad : {"", "x", "x:0", "z:0:1", "x:0:1:2", "x:a:1", "x:0:nan", "x::1"})
    EXPECT_THROW(parseOrientationField(bad), InputError) << bad;
}

TEST(Orientation, RampIsLinearAcrossTheBoxAndClamped) {
  OrientationRamp ramp = OrientationRamp::over({'x', 0.0, 180.0}, {100, 0}, {300, 50});
  EXPECT_NEAR(ramp.angleAt({100, 10}), 0.0, 1e-12);
  EXPECT_NEAR(ramp.angleAt({200, 40}), std::numbers::pi / 2, 1e-12);
  EXPECT_NEAR(ramp.angleAt({300, 0}), std::numbers::pi, 1e-12);
  EXPECT_NEAR(ramp.angleAt({900, 0}), std::numbers::pi, 1e-12);
  EXPECT_NEAR(ramp.angleAt({-5, 0}), 0.0, 1e-12);
  OrientationRamp vertical = OrientationRamp::over({'y', 90.0, 0.0}, {0, 0}, {10, 100});
  EXPECT_NEAR(vertical.angleAt({5, 25}), 0.75 * std::numbers::pi / 2, 1e-12);
}

TEST(Orientation, ElementsFollowTheFieldAcrossTheBand) {
  Scene scene = loadScene(kExamples + "/band.svg").scene;
  Library library = loadLibrary({kExamples + "/elements/bird.svg"});
  RepulsionOptions options = quick();
  options.orientation.mode = OrientationMode::Field;
  options.orientation.field = {'x', 0.0, 180.0};
  Packing packing = packRepulsion(scene, library, options);
  ASSERT_EQ(packing.elements.size(), 8u);
  Box box = bounds(scene.container);
  double worst = 0.0;
  for (const PlacedElement& e : packing.elements) {
    Vec2 centre;
    double angle = rotationOf(e, library[0], &centre);
    double expected = std::numbers::pi * std::clamp((centre.x - box.min.x) / box.width(), 0.0, 1.0);
    worst = std::max(worst, std::abs(wrapped(angle - expected)));
  }
  EXPECT_LT(worst * kDegrees, 8.0);
  PackingCheck check = verifyPacking(artOutlines(packing), packing.container, {1e-5 * area(packing.container)});
  EXPECT_EQ(check.overlappingPairs, 0);
  EXPECT_EQ(check.elementsOutside, 0);
}

TEST(Orientation, UprightHoldsTheDrawnAngleAndRandomDoesNot) {
  Scene scene = loadScene(kExamples + "/band.svg").scene;
  Library library = loadLibrary({kExamples + "/elements/bird.svg"});
  RepulsionOptions options = quick();
  options.orientation.mode = OrientationMode::Upright;
  double worst = 0.0;
  for (const PlacedElement& e : packRepulsion(scene, library, options).elements)
    worst = std::max(worst, std::abs(wrapped(rotationOf(e, library[0]))));
  EXPECT_LT(worst * kDegrees, 8.0);
  options.orientation.mode = OrientationMode::Random;
  options.stop.maxIterations = 10;
  worst = 0.0;
  for (const PlacedElement& e : packRepulsion(scene, library, options).elements)
    worst = std::max(worst, std::abs(wrapped(rotationOf(e, library[0]))));
  EXPECT_GT(worst * kDegrees, 30.0);
}
