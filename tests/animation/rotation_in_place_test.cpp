// Elements that turn in place (thesis Fig. 5.16): with a preferred orientation, torsion holds
// every slice at the orientation plus the rotation the script gives it at that slice's t, so a
// penguin turned upside down at t = 0.5 stays upside down there (and reads as a giraffe).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "animation/animation_fixtures.hpp"
#include "pak/animation/animation.hpp"
#include "pak/animation/keyframes.hpp"
#include "pak/geom/verify.hpp"

namespace pak {
namespace {

// Fourteen arrows that make a full clockwise turn over the loop, from their preferred orientation.
AnimationScript turningArrows(double orientation) {
  AnimationScript script;
  script.slices = 8;
  AnimatedElementSpec spec;
  spec.id = "arrow";
  spec.svg = "arrow.svg";
  spec.count = 14;
  spec.animation.rotation = {{0.0, 0.0}, {0.25, -90.0}, {0.5, -180.0}, {0.75, -270.0}, {1.0, -360.0}};
  spec.orientation = orientation;
  script.elements = {spec};
  return script;
}

double wrapped(double radians) { return std::remainder(radians, 2.0 * std::numbers::pi); }

// How far, over elements and slices, a slice's angle is from where the script puts it: the
// preferred orientation plus the track (degrees counter-clockwise, y up).
struct TurnError { double largest, mean; };  // degrees
TurnError turnError(const AnimatedPacking& a, const AnimationScript& script) {
  const AnimatedElementSpec& spec = script.elements[0];
  double worst = 0.0, sum = 0.0;
  int n = 0;
  for (const AnimatedElement& e : a.elements)
    for (int s = 0; s < a.slices; ++s) {
      const double scripted = sampleTrack(spec.animation.rotation, e.sliceTimes[s], 0.0, true);
      const double expected = -(*spec.orientation + scripted) * std::numbers::pi / 180.0;
      worst = std::max(worst, std::abs(wrapped(test::sliceAngle(e, s) - expected)));
      sum += std::abs(wrapped(test::sliceAngle(e, s) - expected));
      ++n;
    }
  return {worst * 180.0 / std::numbers::pi, sum / n * 180.0 / std::numbers::pi};
}

TEST(RotationInPlace, TorsionHoldsEverySliceAtItsScriptedTurn) {
  AnimationOptions options = test::quickAnimationOptions();
  options.stop.maxIterations = 200;
  options.initialScale = 0.5;  // pressed against each other within the 200 iterations
  const AnimationScript script = turningArrows(30.0);
  const AnimatedPacking withTorsion = packAnimation(test::discScene(), {test::arrowElement()}, script, options);
  options.simulation.torsionStrength = 0.0;  // the same seeds, free to turn as they are pushed
  const AnimatedPacking without = packAnimation(test::discScene(), {test::arrowElement()}, script, options);
  const TurnError held = turnError(withTorsion, script), free = turnError(without, script);
  // Measured 9.9° worst and 2.1° mean with torsion, 10.4° and 2.3° without (at 300 iterations
  // and the growth rate of 0.01, 9.0°, 1.5°, 9.4° and 1.9°; at 300 and 0.015 the arrows were
  // pressed harder, 12.3° worst).
  const std::string measured = "held " + std::to_string(held.largest) + "° worst, " + std::to_string(held.mean) +
                               "° mean; free " + std::to_string(free.largest) + "°, " + std::to_string(free.mean) + "°";
  EXPECT_LT(held.largest, 12.0) << measured;
  EXPECT_LT(held.mean, 3.0) << measured;
  EXPECT_GT(free.mean, held.mean) << "torsion made no difference: " << measured;
  PackingCheckOptions tolerance;
  tolerance.areaTolerance = 1e-4 * area(withTorsion.container);
  for (double t : {0.0, 0.25, 0.5, 0.75}) {
    const PackingCheck check = verifyPacking(artOutlines(animationFrame(withTorsion, t)), withTorsion.container, tolerance);
    EXPECT_EQ(check.overlappingPairs, 0) << "t = " << t;
    EXPECT_EQ(check.elementsOutside, 0) << "t = " << t;
  }
}

}  // namespace
}  // namespace pak
