// Orientations along a vector field (thesis Fig. 5.18): an element whose orientation is
// "field" faces the direction of FLOWPAK's field (from the scene's guide strokes) at its seed,
// and torsion keeps every one of its slices so.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "animation/animation_fixtures.hpp"
#include "pak/animation/animation.hpp"
#include "pak/error.hpp"
#include "pak/flow/vector_field.hpp"

namespace pak {
namespace {

// The disc with two guides: up on the left, down on the right; the field turns between them.
Scene discWithGuides() {
  Scene scene = test::discScene();
  scene.guides = {Polyline{{140, 400}, {140, 250}, {140, 100}}, Polyline{{360, 100}, {360, 250}, {360, 400}}};
  return scene;
}

AnimationScript arrowsAlongTheField(int count) {
  AnimationScript script;
  script.slices = 6;
  AnimatedElementSpec spec;
  spec.id = "arrow";
  spec.svg = "arrow.svg";
  spec.count = count;
  spec.orientationFromField = true;
  script.elements = {spec};
  return script;
}

double degreesApart(double a, double b) { return std::abs(std::remainder(a - b, 2.0 * std::numbers::pi)) * 180.0 / std::numbers::pi; }

TEST(FieldOrientation, EveryElementFacesTheFieldWhereItIsAtEverySlice) {
  const Scene scene = discWithGuides();
  AnimationOptions options = test::quickAnimationOptions();
  options.stop.maxIterations = 300;
  options.initialScale = 0.5;  // pressed against each other within the 300 iterations
  const AnimatedPacking a = packAnimation(scene, {test::arrowElement()}, arrowsAlongTheField(8), options);
  const VectorField field = buildVectorField(scene.container, scene.guides);
  int up = 0, down = 0;
  for (const AnimatedElement& e : a.elements) {
    Vec2 centre;
    for (Vec2 p : e.slices[0]) centre += p;
    centre = centre / static_cast<double>(e.slices[0].size());
    const Vec2 along = field.at(centre);
    const double first = test::sliceAngle(e, 0);
    EXPECT_LT(degreesApart(first, std::atan2(along.y, along.x)), 20.0) << "at " << centre.x << ", " << centre.y;
    for (int s = 1; s < a.slices; ++s) EXPECT_LT(degreesApart(test::sliceAngle(e, s), first), 5.0) << "slice " << s;
    up += along.y < -0.7 ? 1 : 0;
    down += along.y > 0.7 ? 1 : 0;
  }
  // The field does turn over the disc: some arrows point up and some down.
  EXPECT_GT(up, 0);
  EXPECT_GT(down, 0);
}

TEST(FieldOrientation, NeedsGuides) {
  EXPECT_THROW(packAnimation(test::discScene(), {test::arrowElement()}, arrowsAlongTheField(3), test::quickAnimationOptions()),
               InputError);
}

}  // namespace
}  // namespace pak
