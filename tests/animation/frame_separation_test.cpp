// Frame separation: sliver overlaps between slices shrunk away, eased over t.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "animation/animation_fixtures.hpp"
#include "animation/frame_separation.hpp"
#include "pak/animation/animation.hpp"
#include "pak/geom/verify.hpp"

namespace pak {
namespace {

PlacedElement square(double x0, double y0, double side) {
  PlacedElement e;
  const Ring ring{{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}};
  e.skin = ring;
  e.meshVertices = ring;
  Shape shape;
  shape.fill = Color{0, 0, 0};
  shape.subpaths.push_back(Subpath{ring, true});
  e.art = {shape};
  return e;
}

Packing threeSquares() {
  Packing frame;
  frame.container = {Polygon{{{0, 0}, {100, 0}, {100, 100}, {0, 100}}, {}}};
  frame.elements = {square(10, 10, 20), square(29, 12, 20), square(70, 70, 20)};  // the first two overlap by 1
  return frame;
}

PackingCheck checked(const Packing& frame) {
  PackingCheckOptions options;
  options.areaTolerance = 1e-6 * area(frame.container);
  return verifyPacking(artOutlines(frame), frame.container, options);
}

// Separates the frame with the defaults, expecting it clean with no element shrunk: the shifts.
std::vector<Vec2> separatedByMovesAlone(Packing& frame) {
  std::vector<double> scales;
  std::vector<Vec2> shifts;
  EXPECT_EQ(separateFrame(frame, {}, &scales, nullptr, &shifts), 1.0);
  EXPECT_EQ(checked(frame).overlappingPairs, 0);
  EXPECT_EQ(scales, std::vector<double>(frame.elements.size(), 1.0));
  return shifts;
}

// By default two unguided elements that overlap move apart, each away from their overlap by
// 1 % of its radius a round, and neither shrinks.
TEST(FrameSeparation, TwoUnguidedElementsMoveApartAndKeepTheirSize) {
  Packing frame = threeSquares();
  const std::vector<Vec2> shifts = separatedByMovesAlone(frame);
  ASSERT_EQ(shifts.size(), 3u);
  // The overlap is the strip x ∈ [29, 30]: the first goes left, the second right, until the
  // strip is gone, and neither much further than a round past that.
  EXPECT_LT(shifts[0].x, 0.0);
  EXPECT_GT(shifts[1].x, 0.0);
  const double opened = shifts[1].x - shifts[0].x, round = 0.01 * std::sqrt(200.0);
  EXPECT_GE(opened, 1.0);
  EXPECT_LT(opened, 1.0 + 2.0 * round);
  EXPECT_EQ(shifts[2], Vec2{});
  EXPECT_EQ(frame.elements[2].skin, threeSquares().elements[2].skin);  // the bystander is untouched
}

TEST(FrameSeparation, ShrinksOnlyTheOverlappingPairUntilTheFrameIsClean) {
  Packing frame = threeSquares();
  ASSERT_EQ(checked(frame).overlappingPairs, 1);
  std::vector<double> scales;
  FrameSeparationOptions shrinkPairs;
  shrinkPairs.shrinkPairs = true;
  const double smallest = separateFrame(frame, shrinkPairs, &scales);
  EXPECT_EQ(checked(frame).overlappingPairs, 0);
  ASSERT_EQ(scales.size(), 3u);
  // 1 of 20 overlaps: each square must lose 5 % of its width, six rounds of 1 %.
  EXPECT_NEAR(scales[0], std::pow(0.99, 6), 1e-12);
  EXPECT_NEAR(scales[1], std::pow(0.99, 6), 1e-12);
  EXPECT_EQ(scales[2], 1.0);
  EXPECT_EQ(smallest, std::min(scales[0], scales[1]));
  EXPECT_EQ(frame.elements[2].skin, threeSquares().elements[2].skin);  // the bystander is untouched
}

TEST(FrameSeparation, ShrinksAboutTheCentreAndKeepsStrokesInProportion) {
  PlacedElement e = square(10, 10, 20);
  e.art[0].strokeWidth = 2.0;
  scaleAboutCentre(e, 0.5);
  EXPECT_EQ(e.skin, (Ring{{15, 15}, {25, 15}, {25, 25}, {15, 25}}));
  EXPECT_EQ(e.art[0].subpaths[0].points, e.skin);
  EXPECT_EQ(e.meshVertices, e.skin);
  EXPECT_DOUBLE_EQ(e.art[0].strokeWidth, 1.0);
}

TEST(FrameSeparation, NoRoundsChangeNothing) {
  Packing frame = threeSquares();
  FrameSeparationOptions none;
  none.rounds = 0;
  EXPECT_EQ(separateFrame(frame, none), 1.0);
  EXPECT_EQ(frame.elements[0].skin, threeSquares().elements[0].skin);
}

// A guided element is held on its path: the element in its way moves off it, away from where
// they overlap, and neither shrinks; with shrinkOnly both shrink, as any other pair.
TEST(FrameSeparation, AnElementInAGuidedOnesWayMovesOffItAndTheGuidedOneKeepsItsSize) {
  Packing frame = threeSquares();
  frame.elements[0].guided = true;
  std::vector<Vec2> shifts = separatedByMovesAlone(frame);
  ASSERT_EQ(shifts.size(), 3u);
  EXPECT_EQ(shifts[0], Vec2{});
  EXPECT_EQ(shifts[2], Vec2{});
  // The overlap is the strip x ∈ [29, 30]: the second square goes right (and a little up, away
  // from the strip's centroid), 1 % of its radius √200 a round, until it is clear of the first.
  EXPECT_GE(shifts[1].x, 1.0);
  EXPECT_LT(shifts[1].x, 1.0 + 0.01 * std::sqrt(200.0));
  EXPECT_GT(shifts[1].y, 0.0);
  EXPECT_LT(shifts[1].y, 0.2);
  const Vec2 moved = threeSquares().elements[1].skin[0] + shifts[1];
  EXPECT_NEAR(frame.elements[1].skin[0].x, moved.x, 1e-12);
  EXPECT_NEAR(frame.elements[1].skin[0].y, moved.y, 1e-12);

  Packing evenly = threeSquares();
  evenly.elements[0].guided = true;
  FrameSeparationOptions shrinkOnly;
  shrinkOnly.shrinkOnly = true;
  std::vector<double> scales;
  separateFrame(evenly, shrinkOnly, &scales, nullptr, &shifts);
  EXPECT_NEAR(scales[0], std::pow(0.99, 6), 1e-12);
  EXPECT_NEAR(scales[1], std::pow(0.99, 6), 1e-12);
  EXPECT_EQ(shifts[1], Vec2{});
}

TEST(FrameSeparation, ScaleBetweenSamplesIsInterpolatedAndALoopWrapsToTheFirst) {
  AnimatedPacking a;
  a.elements.resize(1);
  a.separationTimes = {0.0, 0.5};
  a.elements[0].separationScale = {1.0, 0.9};
  EXPECT_DOUBLE_EQ(separationScaleAt(a, 0, 0.25), 0.95);
  EXPECT_DOUBLE_EQ(separationScaleAt(a, 0, 0.75), 0.9);  // no loop: the last sample holds
  a.loop = true;
  EXPECT_DOUBLE_EQ(separationScaleAt(a, 0, 0.75), 0.95);  // a loop comes back to t = 0's
  a.elements[0].separationShift = {{0.0, 0.0}, {2.0, 4.0}};
  EXPECT_EQ(separationShiftAt(a, 0, 0.25), (Vec2{1.0, 2.0}));  // shifts the same way
  a.elements[0].separationScale.clear();
  a.elements[0].separationShift.clear();
  EXPECT_EQ(separationScaleAt(a, 0, 0.3), 1.0);
  EXPECT_EQ(separationShiftAt(a, 0, 0.3), Vec2{});
}

TEST(FrameSeparation, PackedFramesAtTheSamplesAreCleanAndTheShrinkingIsEased) {
  AnimationOptions options = test::quickAnimationOptions();
  options.stop.maxIterations = 700;  // long enough for the stars to press each other
  options.stop.settleIterations = 0;  // the slivers the separation is for; the settle mends some
  options.frameSeparation.samples = 40;
  options.frameSeparation.shrinkPairs = true;  // the shrinking's easing; the moves below
  AnimationOptions unseparated = options;
  unseparated.frameSeparation.rounds = 0;
  const AnimatedPacking raw =
      packAnimation(test::discScene(), {test::starElement("star.svg")}, test::spinningStars(12), unseparated);
  EXPECT_TRUE(raw.separationTimes.empty());
  int overlapping = 0;  // the frames between slices, as interpolated, have slivers
  for (int k = 0; k < 40; ++k) overlapping += checked(animationFrame(raw, k / 40.0)).overlappingPairs > 0 ? 1 : 0;
  EXPECT_GT(overlapping, 0);

  const AnimatedPacking a = packAnimation(test::discScene(), {test::starElement("star.svg")}, test::spinningStars(12), options);
  ASSERT_EQ(a.separationTimes.size(), 40u);
  for (double t : a.separationTimes) {
    const PackingCheck check = checked(animationFrame(a, t));
    EXPECT_EQ(check.overlappingPairs, 0) << "t = " << t;
    EXPECT_EQ(check.elementsOutside, 0) << "t = " << t;
  }
  // Between neighbouring samples no element's scale changes faster than the ramp allows: its
  // deepest shrinking over `ramp` of t.
  const double dt = a.separationTimes[1] - a.separationTimes[0];
  int shrunk = 0;
  for (const AnimatedElement& e : a.elements) {
    ASSERT_EQ(e.separationScale.size(), a.separationTimes.size());
    const double deepest = 1.0 - *std::min_element(e.separationScale.begin(), e.separationScale.end());
    shrunk += deepest > 0.0 ? 1 : 0;
    for (std::size_t k = 1; k < e.separationScale.size(); ++k)
      EXPECT_LE(std::abs(e.separationScale[k] - e.separationScale[k - 1]), deepest / options.frameSeparation.ramp * dt + 1e-12);
  }
  EXPECT_GT(shrunk, 0);

  // The same on two threads, to the bit.
  options.run.threads = 2;
  const AnimatedPacking b = packAnimation(test::discScene(), {test::starElement("star.svg")}, test::spinningStars(12), options);
  for (std::size_t e = 0; e < a.elements.size(); ++e) EXPECT_EQ(a.elements[e].separationScale, b.elements[e].separationScale);

  // By default the pairs move apart first: clean at every sample again, some elements shifted,
  // and the same on one thread and two.
  options.frameSeparation.shrinkPairs = false;
  const AnimatedPacking moved = packAnimation(test::discScene(), {test::starElement("star.svg")}, test::spinningStars(12), options);
  int shifted = 0;
  for (const AnimatedElement& e : moved.elements) shifted += e.separationShift.empty() ? 0 : 1;
  EXPECT_GT(shifted, 0);
  for (double t : moved.separationTimes) {
    const PackingCheck check = checked(animationFrame(moved, t));
    EXPECT_EQ(check.overlappingPairs, 0) << "t = " << t;
    EXPECT_EQ(check.elementsOutside, 0) << "t = " << t;
  }
  options.run.threads = 1;
  const AnimatedPacking movedAlone = packAnimation(test::discScene(), {test::starElement("star.svg")}, test::spinningStars(12), options);
  for (std::size_t e = 0; e < moved.elements.size(); ++e) {
    EXPECT_EQ(moved.elements[e].separationShift, movedAlone.elements[e].separationShift);
    EXPECT_EQ(moved.elements[e].separationScale, movedAlone.elements[e].separationScale);
  }
}

}  // namespace
}  // namespace pak
