// AnimationPak's phases one by one (src/animation/animation_phases.hpp): what each promises,
// and that running them in order is packAnimation.
#include "animation/animation_phases.hpp"

#include <gtest/gtest.h>

#include <atomic>

#include "animation/animation_fixtures.hpp"
#include "sim/fold_relaxation.hpp"

namespace pak {
namespace {

TEST(AnimationPhases, SeedingPlacesEveryCopyShrunkAndApart) {
  const Scene scene = test::discScene();
  const Library library{test::starElement("star.svg")};
  const AnimationScript script = test::spinningStars(6);
  const AnimationRun run = prepareAnimation(scene, library, script, test::quickAnimationOptions());
  ASSERT_EQ(run.types.size(), 1u);
  EXPECT_EQ(run.meshes.size(), 1u);
  EXPECT_EQ(run.types[0].shapes.size(), static_cast<std::size_t>(script.slices));
  const AnimationSeeding seeding = seedAnimation(run);
  ASSERT_EQ(seeding.instances.size(), 6u);
  EXPECT_GT(seeding.growth, 0.0);
  EXPECT_LE(seeding.growth, run.options.initialScale);
  // Seeds r apart hold shrunken elements of radius ≤ 0.45 r: the centres keep apart.
  for (std::size_t a = 0; a < seeding.instances.size(); ++a)
    for (std::size_t b = a + 1; b < seeding.instances.size(); ++b)
      EXPECT_GT(distance(seeding.instances[a].centre[0], seeding.instances[b].centre[0]),
                2.0 * run.types[0].radius * seeding.growth);
}

// `count` spinning stars in the disc, taken through the phases up to the end of the simulation.
struct SimulatedStars {
  explicit SimulatedStars(int count) : script(test::spinningStars(count)) {}
  const Scene scene = test::discScene();
  const Library library{test::starElement("star.svg")};
  const AnimationScript script;
  // Without the settle: the fold below is made by hand on the positions these options give.
  const AnimationOptions options = [] {
    AnimationOptions o = test::quickAnimationOptions();
    o.stop.settleIterations = 0;
    return o;
  }();
  const AnimationRun run = prepareAnimation(scene, library, script, options);
  const AnimationSeeding seeding = seedAnimation(run);
  ThreadPool pool{options.run.threads};
  SpacetimeSimulation sim = spacetimeSimulation(run, seeding, pool, nullptr);
  const AnimationStop stop = simulateAnimation(sim, run, {}, nullptr);
};

TEST(AnimationPhases, InOrderTheyArePackAnimation) {
  SimulatedStars stars(5);
  auto& [scene, library, script, options, run, seeding, pool, sim, stop] = stars;
  EXPECT_EQ(sim.elementCount(), 5);
  EXPECT_EQ(sim.slices(), script.slices);
  const AnimatedPacking byPhases = collectAnimation(run, seeding, sim, stop, pool);
  const AnimatedPacking packed = packAnimation(scene, library, script, options);
  EXPECT_EQ(byPhases.iterations, packed.iterations);
  EXPECT_EQ(byPhases.stopReason, packed.stopReason);
  ASSERT_EQ(byPhases.elements.size(), packed.elements.size());
  for (std::size_t e = 0; e < packed.elements.size(); ++e) EXPECT_EQ(byPhases.elements[e].slices, packed.elements[e].slices);
}

TEST(AnimationPhases, CollectingUnfoldsASliceFoldedOverItself) {
  SimulatedStars stars(3);
  auto& [scene, library, script, options, run, seeding, pool, sim, stop] = stars;
  const PreparedElement& element = run.meshes[run.types[0].mesh];
  std::vector<Vec2> folds, artPoints, slice;
  Ring ring;
  auto foldsOf = [&](const std::vector<Vec2>& vertices) {
    folds.clear();
    appendArtFolds(element, vertices.data(), folds, artPoints, ring);
    return folds.size();
  };
  EXPECT_EQ(collectAnimation(run, seeding, sim, stop, pool).unfoldedSlices, 0);

  // The skin vertex nearest a tip of element 1's star in slice 2 pulled across the body, far past
  // the centre: the tip bound to its triangles is dragged over the rest of the star.
  constexpr int kElement = 1, kSlice = 2;
  std::vector<Vec3> x = sim.positions();
  const int n = sim.verticesPerSlice(kElement), first = sim.vertexBegin(kElement) + kSlice * n;
  for (int k = 0; k < n; ++k) slice.push_back(spatial(x[first + k]));
  replayArt(element.mesh, slice.data(), artPoints);
  int v = first;
  for (int k = 0; k < element.mesh.boundaryCount; ++k)
    if (distance(slice[k], artPoints[0]) < distance(slice[v - first], artPoints[0])) v = first + k;
  Vec2 centre;
  for (Vec2 p : slice) centre += p / static_cast<double>(n);
  const Vec2 across = centre + (centre - spatial(x[v])) * 3.0;
  x[v].x = across.x;
  x[v].y = across.y;
  slice[v - first] = across;
  ASSERT_GT(foldsOf(slice), 0u);
  sim.restoreState(sim.iteration(), x, sim.velocities(), sim.growth(), sim.previousGrowth(), sim.neighbourOrigin());

  const AnimatedPacking collected = collectAnimation(run, seeding, sim, stop, pool);
  EXPECT_EQ(collected.unfoldedSlices, 1);
  EXPECT_EQ(foldsOf(collected.elements[kElement].slices[kSlice]), 0u);
  // Only the folded slice moved: its neighbour in time is as simulated.
  const std::vector<Vec2>& before = collected.elements[kElement].slices[kSlice - 1];
  for (int k = 0; k < n; ++k)
    EXPECT_EQ(before[k], run.setup.frame.toInput(spatial(x[first - n + k])));
}

TEST(AnimationPhases, TheTimeLimitStopsTheRun) {
  AnimationOptions options = test::quickAnimationOptions();
  options.stop.timeLimit = 1e-9;
  const AnimatedPacking a =
      packAnimation(test::discScene(), {test::starElement("star.svg")}, test::spinningStars(4), options);
  EXPECT_EQ(a.stopReason, AnimationStop::TimeLimit);
  EXPECT_EQ(a.iterations, 1);  // and no settle after it
  EXPECT_EQ(a.settleIterations, 0);
}

TEST(AnimationPhases, AStopRequestStopsTheRunAsTheTimeLimitDoes) {
  AnimationOptions options = test::quickAnimationOptions();
  const std::atomic<bool> stop{true};
  options.run.stopRequest = &stop;
  const AnimatedPacking a =
      packAnimation(test::discScene(), {test::starElement("star.svg")}, test::spinningStars(4), options);
  EXPECT_EQ(a.stopReason, AnimationStop::Interrupted);
  EXPECT_STREQ(toString(a.stopReason), "interrupted");
  EXPECT_EQ(a.iterations, 1);
  EXPECT_EQ(a.settleIterations, 0);
}

TEST(AnimationPhases, AStopRequestEndsTheSettle) {
  AnimationOptions options = test::quickAnimationOptions();
  std::atomic<bool> stop{false};
  options.run.stopRequest = &stop;
  AnimationCallbacks callbacks;
  callbacks.progressEvery = 10;
  callbacks.onProgress = [&](const AnimationProgress& p) {
    if (p.settleLeft >= 0) stop = true;  // the settle's first report, after its 10th step
  };
  const AnimatedPacking a =
      packAnimation(test::discScene(), {test::starElement("star.svg")}, test::spinningStars(4), options, callbacks);
  EXPECT_EQ(a.stopReason, AnimationStop::IterationCap);  // what ended the growth
  EXPECT_EQ(a.settleIterations, 10);
  EXPECT_EQ(a.iterations, options.stop.maxIterations + 10);
}

}  // namespace
}  // namespace pak
