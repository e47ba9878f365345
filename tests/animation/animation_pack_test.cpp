// packAnimation end to end on a small scene, and frames (thesis 5.4–5.6).
#include "pak/animation/animation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <gtest/gtest.h>

#include "animation/animation_fixtures.hpp"
#include "pak/error.hpp"
#include "pak/geom/verify.hpp"

namespace pak {
namespace {

TEST(AnimationPack, SpinningStarsFillTheDiscWithoutOverlapsAtTheSlices) {
  const Scene scene = test::discScene();
  const AnimationScript script = test::spinningStars(8);
  AnimationOptions options = test::quickAnimationOptions();
  options.stop.maxIterations = 400;
  const AnimatedPacking a = packAnimation(scene, {test::starElement("star.svg")}, script, options);
  ASSERT_EQ(a.elements.size(), 8u);
  EXPECT_GT(a.iterations, 50);
  const double containerArea = area(scene.container);
  for (int s = 0; s < script.slices; ++s) {
    const double t = a.elements[0].sliceTimes[s];
    const Packing frame = animationFrame(a, t);
    PackingCheckOptions check;
    check.areaTolerance = 1e-4 * containerArea;
    const PackingCheck result = verifyPacking(artOutlines(frame), scene.container, check);
    EXPECT_EQ(result.overlappingPairs, 0) << "slice " << s;
    EXPECT_EQ(result.elementsOutside, 0) << "slice " << s;
    double art = 0.0;
    for (const Region& r : artOutlines(frame)) art += area(r);
    EXPECT_GT(art / containerArea, 0.15) << "slice " << s;
  }
}

TEST(AnimationPack, TheSettleGrowsNothingAndLeavesFewerSlicesPressed) {
  AnimationOptions options = test::quickAnimationOptions();
  options.stop.maxIterations = 700;  // the stars press each other by then
  options.stop.settleIterations = 0;
  const AnimatedPacking unsettled =
      packAnimation(test::discScene(), {test::starElement("star.svg")}, test::spinningStars(12), options);
  options.stop.settleIterations = 100;
  const AnimatedPacking settled =
      packAnimation(test::discScene(), {test::starElement("star.svg")}, test::spinningStars(12), options);
  EXPECT_EQ(unsettled.settleIterations, 0);
  EXPECT_EQ(settled.settleIterations, 100);
  EXPECT_EQ(settled.iterations, unsettled.iterations + 100);
  ASSERT_EQ(settled.elements.size(), unsettled.elements.size());
  for (std::size_t e = 0; e < settled.elements.size(); ++e)
    EXPECT_EQ(settled.elements[e].sliceGrowth, unsettled.elements[e].sliceGrowth) << "element " << e;
  EXPECT_GT(unsettled.overlappingSlices, 0);
  EXPECT_LT(settled.overlappingSlices, unsettled.overlappingSlices);
}

TEST(AnimationPack, FrameZeroIsTheFirstSliceAndLoopsClose) {
  const AnimatedPacking a =
      packAnimation(test::discScene(), {test::starElement("star.svg")}, test::spinningStars(5), test::quickAnimationOptions());
  const Packing first = animationFrame(a, 0.0);
  for (std::size_t e = 0; e < a.elements.size(); ++e) {
    EXPECT_EQ(a.elements[e].sliceTimes.front(), 0.0);
    EXPECT_EQ(a.elements[e].sliceTimes.back(), 1.0);
    ASSERT_EQ(first.elements[e].meshVertices, a.elements[e].slices.front());
    // The loop constraint joins each element's last slice to its own first one: the star has
    // turned by 72°, so the outline (not the vertex order) is the same.
    EXPECT_NEAR(std::abs(signedArea(Ring(a.elements[e].slices.back().begin(),
                                         a.elements[e].slices.back().begin() + a.elements[e].mesh.boundaryCount))),
                std::abs(signedArea(first.elements[e].skin)), 1e-6 * area(a.container));
    // The star's mesh has the turn's symmetry, so the two slices are the same points in the
    // container, each vertex on the one a fifth of a turn away.
    for (Vec2 p : a.elements[e].slices.back()) {
      double nearest = std::numeric_limits<double>::infinity();
      for (Vec2 q : a.elements[e].slices.front()) nearest = std::min(nearest, distance(p, q));
      EXPECT_LT(nearest, 1e-6) << "element " << e;
    }
  }
}

TEST(AnimationPack, TheThesisTouchingRuleStopsOnlyWhenAskedFor) {
  // By default a run does not stop because every slice touches something (a touching slice
  // may still grow); with --closeness it does, as in the thesis.
  AnimationOptions options = test::quickAnimationOptions();
  options.stop.maxIterations = 700;
  options.stop.settleIterations = 0;
  options.stop.stallGrowth = 0.0;  // only the touching rule or the cap may end the run
  const AnimatedPacking plain =
      packAnimation(test::discScene(), {test::starElement("star.svg")}, test::spinningStars(12), options);
  EXPECT_EQ(plain.stopReason, AnimationStop::IterationCap);
  EXPECT_EQ(plain.iterations, 700);
  options.stop.closeness = 30.0;
  const AnimatedPacking thesis =
      packAnimation(test::discScene(), {test::starElement("star.svg")}, test::spinningStars(12), options);
  EXPECT_EQ(thesis.stopReason, AnimationStop::AllTouching);
  EXPECT_LT(thesis.iterations, 700);
}

TEST(AnimationPack, DeterministicWhateverTheThreadCount) {
  AnimationOptions one = test::quickAnimationOptions(), two = one;
  two.run.threads = 2;
  const AnimatedPacking a = packAnimation(test::discScene(), {test::starElement("s")}, test::spinningStars(6), one);
  const AnimatedPacking b = packAnimation(test::discScene(), {test::starElement("s")}, test::spinningStars(6), two);
  ASSERT_EQ(a.elements.size(), b.elements.size());
  for (std::size_t e = 0; e < a.elements.size(); ++e) ASSERT_EQ(a.elements[e].slices, b.elements[e].slices);
}

TEST(AnimationPack, ResumingFromACheckpointGivesTheSameResult) {
  // Long enough for slices to stop growing and feel the pocket pressure, which depends on
  // whether they grew in the step before the checkpoint.
  AnimationOptions options = test::quickAnimationOptions();
  options.stop.maxIterations = 1000;
  AnimationState saved;
  AnimationCallbacks callbacks;
  callbacks.checkpointEvery = 25;
  callbacks.onCheckpoint = [&](const AnimationState& s) { saved = s; };  // the last one before the end
  const AnimatedPacking straight = packAnimation(test::discScene(), {test::starElement("s")}, test::spinningStars(5), options, callbacks);
  ASSERT_GT(saved.iteration, 0);
  int pressed = 0;  // slices that did not grow in the step before the checkpoint
  for (std::size_t k = 0; k < saved.growth.size(); ++k) pressed += saved.growth[k] == saved.previousGrowth[k] ? 1 : 0;
  ASSERT_GT(pressed, 0);
  const AnimatedPacking resumed = packAnimation(test::discScene(), {test::starElement("s")}, test::spinningStars(5), options, {}, &saved);
  EXPECT_EQ(resumed.iterations, straight.iterations);
  for (std::size_t e = 0; e < straight.elements.size(); ++e) ASSERT_EQ(straight.elements[e].slices, resumed.elements[e].slices);
}

TEST(AnimationPack, FixedElementsAreObstaclesAndInEveryFrame) {
  // A fixed square in the middle of the disc, where the stars would otherwise go.
  Scene scene = test::discScene();
  Shape square;
  square.subpaths = {Subpath{{{200, 200}, {300, 200}, {300, 300}, {200, 300}}, true}};
  square.fill = Color{240, 230, 200, 1.0};
  AnimationOptions options = test::quickAnimationOptions();
  options.stop.maxIterations = 600;
  const Library library{test::starElement("star.svg")};
  const AnimatedPacking open = packAnimation(scene, library, test::spinningStars(6), options);
  scene.fixed = {square};
  const AnimatedPacking around = packAnimation(scene, library, test::spinningStars(6), options);
  ASSERT_GT(area(around.fixedArt), 9999.0);
  PackingCheckOptions tolerance;
  tolerance.areaTolerance = 1e-6 * area(scene.container);
  int crossingTheSquare = 0;
  for (double t : {0.0, 0.3, 0.6, 0.9}) {
    // As the frames are drawn: between the separation's samples, a frame gets its own.
    Packing frame = animationFrame(around, t);
    separateFrame(frame, options.frameSeparation);
    EXPECT_EQ(area(frame.fixedArt), area(around.fixedArt));
    const PackingCheck check = verifyPacking(checkedOutlines(frame), frame.container, tolerance);
    EXPECT_EQ(check.overlappingPairs, 0) << "t = " << t << (check.problems.empty() ? "" : ": " + check.problems.front())
                                         << " (the square is element " << frame.elements.size() << ")";
    EXPECT_EQ(check.elementsOutside, 0) << "t = " << t;
    std::vector<Region> withSquare = artOutlines(animationFrame(open, t));
    withSquare.push_back(around.fixedArt);
    crossingTheSquare += verifyPacking(withSquare, frame.container, tolerance).overlappingPairs;
  }
  EXPECT_GT(crossingTheSquare, 0) << "without the fixed element, stars cover the square";
}

TEST(AnimationPack, GuidedElementFollowsItsTargets) {
  AnimationScript script = test::spinningStars(3);
  AnimatedElementSpec guided;
  guided.id = "runner";
  guided.svg = "star.svg";
  guided.targets = {{0.0, {150, 250}, {}, {}}, {0.5, {350, 250}, {}, {}}, {1.0, {150, 250}, {}, {}}};
  script.elements.push_back(guided);
  const AnimatedPacking a = packAnimation(test::discScene(), {test::starElement("star.svg"), test::starElement("star.svg")},
                                          script, test::quickAnimationOptions());
  const AnimatedElement* runner = nullptr;
  for (const AnimatedElement& e : a.elements)
    if (e.guided) runner = &e;
  ASSERT_NE(runner, nullptr);
  auto centreAt = [&](double t) {
    const Packing f = animationFrame(a, t);
    Vec2 c;
    const PlacedElement& e = f.elements[runner - a.elements.data()];
    for (Vec2 p : e.meshVertices) c += p;
    return c / static_cast<double>(e.meshVertices.size());
  };
  EXPECT_LT(distance(centreAt(0.0), Vec2{150, 250}), 40.0);
  EXPECT_LT(distance(centreAt(0.5), Vec2{350, 250}), 40.0);
  EXPECT_GT(distance(centreAt(0.5), centreAt(0.0)), 120.0);
}

TEST(AnimationPack, SmallestGuidedGrowthRatioIsOverTheUnguidedMedianAtEachSlice) {
  AnimatedPacking a;
  a.slices = 2;
  auto element = [](bool guided, std::vector<double> growth) {
    AnimatedElement e;
    e.guided = guided;
    e.sliceGrowth = std::move(growth);
    return e;
  };
  EXPECT_EQ(smallestGuidedGrowthRatio(a), 1.0);
  // Unguided medians: slice 0 of {1.0, 0.6, 0.8} is 0.8, slice 1 of {0.5, 0.9, 0.7} is 0.7.
  a.elements = {element(false, {1.0, 0.5}), element(false, {0.6, 0.9}), element(false, {0.8, 0.7}),
                element(true, {0.4, 0.7}), element(true, {0.8, 0.35})};
  EXPECT_DOUBLE_EQ(smallestGuidedGrowthRatio(a), 0.5);  // 0.4 / 0.8 and 0.35 / 0.7
  a.elements.pop_back();
  a.elements.pop_back();
  EXPECT_EQ(smallestGuidedGrowthRatio(a), 1.0);  // none guided
}

TEST(AnimationPack, AGuidedElementCrossingACrowdKeepsUpWithItsSize) {
  // A runner across the disc and back, through eight spinning stars.
  AnimationScript script = test::spinningStars(8);
  AnimatedElementSpec guided;
  guided.id = "runner";
  guided.svg = "star.svg";
  guided.targets = {{0.0, {100, 250}, {}, {}}, {0.5, {400, 250}, {}, {}}, {1.0, {100, 250}, {}, {}}};
  script.elements.push_back(guided);
  const Library library{test::starElement("star.svg"), test::starElement("star.svg")};
  AnimationOptions options = test::quickAnimationOptions();
  options.stop.maxIterations = 600;
  const AnimatedPacking kept = packAnimation(test::discScene(), library, script, options);
  options.spacetime.guidedGrowth = 0.0;  // the common growth rule only (thesis)
  const AnimatedPacking common = packAnimation(test::discScene(), library, script, options);
  EXPECT_GE(smallestGuidedGrowthRatio(kept), 0.8);
  EXPECT_LT(smallestGuidedGrowthRatio(common), smallestGuidedGrowthRatio(kept));
}

TEST(AnimationPack, TwoGuidedElementsSwapPlacesInAPermutationLoop) {
  // Thesis Fig. 5.11d: A runs from left to right, B from right to left; A's t = 1 slice joins
  // B's t = 0 slice and the other way round.
  AnimationScript script = test::spinningStars(2);
  AnimatedElementSpec a, b;
  a.id = "a", b.id = "b";
  a.svg = b.svg = "star.svg";
  a.targets = {{0.0, {150, 250}, {}, {}}, {1.0, {350, 250}, {}, {}}};
  b.targets = {{0.0, {350, 250}, {}, {}}, {1.0, {150, 250}, {}, {}}};
  a.loopTo = "b", b.loopTo = "a";
  script.elements.push_back(a);
  script.elements.push_back(b);
  const ElementArt star = test::starElement("star.svg");
  const AnimatedPacking result = packAnimation(test::discScene(), {star, star, star}, script, test::quickAnimationOptions());
  const AnimatedElement *ea = nullptr, *eb = nullptr;
  for (const AnimatedElement& e : result.elements) {
    if (e.id == "a") ea = &e;
    if (e.id == "b") eb = &e;
  }
  ASSERT_TRUE(ea && eb);
  auto centre = [](const std::vector<Vec2>& slice) {
    Vec2 c;
    for (Vec2 p : slice) c += p;
    return c / static_cast<double>(slice.size());
  };
  EXPECT_LT(distance(centre(ea->slices.back()), centre(eb->slices.front())), 1e-9);
  EXPECT_LT(distance(centre(eb->slices.back()), centre(ea->slices.front())), 1e-9);
  EXPECT_GT(distance(centre(ea->slices.front()), centre(eb->slices.front())), 120.0);
}

TEST(AnimationPack, BadInputIsAnInputError) {
  AnimationScript script = test::spinningStars(2);
  EXPECT_THROW(packAnimation(test::discScene(), {}, script), InputError);  // no art for the element
  AnimationOptions bad;
  bad.slices = 1;
  EXPECT_THROW(packAnimation(test::discScene(), {test::starElement("s")}, script, bad), InputError);
  script.elements[0].animation.handles = {{"tail", {{0.0, {0, 0}}, {1.0, {5, 0}}}}};
  EXPECT_THROW(packAnimation(test::discScene(), {test::starElement("s")}, script), InputError);  // no such handle
  AnimationScript unguidedLoop = test::spinningStars(2);
  AnimatedElementSpec runner;
  runner.id = "runner";
  runner.svg = "star.svg";
  runner.targets = {{0.0, {150, 250}, {}, {}}, {1.0, {150, 250}, {}, {}}};
  runner.loopTo = "star";  // an unguided element
  unguidedLoop.elements.push_back(runner);
  EXPECT_THROW(packAnimation(test::discScene(), {test::starElement("s"), test::starElement("s")}, unguidedLoop), InputError);
  Scene empty;
  EXPECT_THROW(packAnimation(empty, {test::starElement("s")}, test::spinningStars(2)), InputError);
  // The growth shares and the wall's give are distances or ratios: never negative.
  for (double SpacetimeParameters::*field :
       {&SpacetimeParameters::growthSpread, &SpacetimeParameters::guidedGrowth, &SpacetimeParameters::guidedWallGive}) {
    AnimationOptions negative;
    negative.spacetime.*field = -1.0;
    EXPECT_THROW(packAnimation(test::discScene(), {test::starElement("star.svg")}, test::spinningStars(2), negative),
                 InputError);
  }
}

TEST(AnimationPack, MeanCentroidAccelerationIsTheCentroidsSecondDifference) {
  // One element circling at radius 10 (input units) over a loop of 8 slices (t = s / 8, the
  // last equal to the first); 2 canonical units per input unit.
  AnimatedPacking a;
  a.loop = true;
  a.canonicalScale = 2.0;
  auto circling = [](bool guided) {
    AnimatedElement e;
    e.guided = guided;
    for (int s = 0; s <= 8; ++s) {
      const double angle = 2.0 * std::numbers::pi * s / 8.0;
      const Vec2 c{10.0 * std::cos(angle), 10.0 * std::sin(angle)};
      e.sliceTimes.push_back(s / 8.0);
      e.slices.push_back({c + Vec2{1, 0}, c + Vec2{-1, 0}, c + Vec2{0, 3}, c + Vec2{0, -3}});  // centred on c
    }
    return e;
  };
  a.elements = {circling(false), circling(true)};  // the guided one is left out
  // 8 frames land on the slices: |c(i-1) - 2 c(i) + c(i+1)| = 2 r (1 - cos 45°) on the circle.
  EXPECT_NEAR(meanCentroidAcceleration(a, 8), 2.0 * 2.0 * 10.0 * (1.0 - std::cos(std::numbers::pi / 4.0)), 1e-9);
  // 16 frames: every other frame lies on a chord's midpoint, whose second difference is 0;
  // at a slice it is half the above (its neighbours are the chords' midpoints).
  EXPECT_NEAR(meanCentroidAcceleration(a, 16), 0.5 * 0.5 * 2.0 * 2.0 * 10.0 * (1.0 - std::cos(std::numbers::pi / 4.0)),
              1e-9);
  // A straight, steady path does not accelerate; an open animation has no wrap-around.
  a.loop = false;
  for (AnimatedElement& e : a.elements)
    for (int s = 0; s <= 8; ++s)
      for (Vec2& p : e.slices[s]) {
        const double angle = 2.0 * std::numbers::pi * s / 8.0;
        p = p - Vec2{10.0 * std::cos(angle), 10.0 * std::sin(angle)} + Vec2{3.0 * s, 0.0};
      }
  EXPECT_NEAR(meanCentroidAcceleration(a, 17), 0.0, 1e-9);
  EXPECT_EQ(meanCentroidAcceleration(a, 2), 0.0);
}

}  // namespace
}  // namespace pak
