// Mirror symmetry (thesis Fig. 5.18): the packing is simulated left of a vertical line and
// every frame shows it reflected across the line too, checked as one packing.
#include <gtest/gtest.h>

#include <algorithm>

#include "animation/animation_fixtures.hpp"
#include "pak/animation/animation.hpp"
#include "pak/error.hpp"
#include "pak/geom/verify.hpp"

namespace pak {
namespace {

constexpr double kLine = 250.0;  // through the disc's centre

TEST(MirrorSymmetry, FramesAreSymmetricAndCleanOverBothHalves) {
  AnimationOptions options = test::quickAnimationOptions();
  options.stop.maxIterations = 300;
  options.initialScale = 0.5;  // in contact, with the line too, within the 300 iterations
  options.mirrorX = kLine;
  const Scene scene = test::discScene();
  const AnimatedPacking a = packAnimation(scene, {test::starElement("star.svg")}, test::spinningStars(5), options);
  ASSERT_EQ(a.elements.size(), 5u);
  EXPECT_EQ(area(a.container), area(scene.container)) << "the frames are of the whole container";
  PackingCheckOptions tolerance;
  tolerance.areaTolerance = 1e-4 * area(a.container);
  // The frames as simulated, without the frame separation's moves (which may take a skin a
  // little past the line: docs/animationpak.md, Known limits).
  AnimatedPacking simulated = a;
  for (AnimatedElement& e : simulated.elements) e.separationScale.clear(), e.separationShift.clear();
  for (int k = 0; k < 8; ++k) {
    const double t = k / 8.0;
    const Packing frame = animationFrame(a, t);
    ASSERT_EQ(frame.elements.size(), 10u) << "each element and its reflection";
    const Packing unseparated = animationFrame(simulated, t);
    double left = 0.0, right = 0.0;
    for (std::size_t e = 0; e < 5; ++e) {
      const PlacedElement &packed = frame.elements[e], &twin = frame.elements[5 + e];
      for (Vec2 p : unseparated.elements[e].skin)
        EXPECT_LE(p.x, kLine + 1e-6) << "simulated on the left; t = " << t << ", element " << e;
      ASSERT_EQ(packed.skin.size(), twin.skin.size());
      const std::size_t n = packed.skin.size();
      for (std::size_t i = 0; i < n; ++i) {  // reflected, in reverse order
        EXPECT_DOUBLE_EQ(twin.skin[n - 1 - i].x, 2.0 * kLine - packed.skin[i].x);
        EXPECT_DOUBLE_EQ(twin.skin[n - 1 - i].y, packed.skin[i].y);
      }
      left += std::abs(signedArea(packed.skin));
      right += std::abs(signedArea(twin.skin));
    }
    EXPECT_NEAR(left, right, 1e-9 * left);
    const PackingCheck check = verifyPacking(checkedOutlines(frame), a.container, tolerance);
    EXPECT_EQ(check.overlappingPairs, 0) << "t = " << t;  // twins across the line included
    EXPECT_EQ(check.elementsOutside, 0) << "t = " << t;
    EXPECT_NEAR(frame.skinFill, (left + right) / area(a.container), 1e-9) << "the fill counts both halves";
  }
}

TEST(MirrorSymmetry, ALineThatMissesTheContainerIsAnInputError) {
  AnimationOptions options = test::quickAnimationOptions();
  options.mirrorX = 20.0;  // the disc spans x ∈ [50, 450]
  EXPECT_THROW(packAnimation(test::discScene(), {test::starElement("star.svg")}, test::spinningStars(3), options), InputError);
}

}  // namespace
}  // namespace pak
