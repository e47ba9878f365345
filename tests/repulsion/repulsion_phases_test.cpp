// RepulsionPak's phases one by one (src/repulsion/repulsion_phases.hpp): what each promises,
// and that running them in order is packRepulsion.
#include "repulsion/repulsion_phases.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>

#include "pak/geom/clipping.hpp"
#include "pak/geom/verify.hpp"
#include "pak/io/scene_loader.hpp"

namespace pak {
namespace {

const std::string kExamples = std::string(PAK_SOURCE_DIR) + "/examples";

RepulsionOptions quickOptions() {
  RepulsionOptions o;
  o.count = 8;
  o.stop.maxIterations = 200;
  o.run.seed = 4;
  o.run.threads = 2;
  return o;
}

bool samePacking(const Packing& a, const Packing& b) {
  if (a.elements.size() != b.elements.size() || a.iterations != b.iterations) return false;
  for (std::size_t e = 0; e < a.elements.size(); ++e)
    if (a.elements[e].meshVertices != b.elements[e].meshVertices) return false;
  return true;
}

class RepulsionPhases : public ::testing::Test {
 protected:
  Scene scene = loadScene(kExamples + "/scene.svg").scene;
  Library library = loadLibrary({kExamples + "/elements"});
};

TEST_F(RepulsionPhases, PrepareSetsUpTheFrameTheContainerAndTheTypes) {
  const RepulsionRun run = prepareRepulsion(scene, library, quickOptions());
  EXPECT_EQ(run.count, 8);
  EXPECT_EQ(run.types.size(), library.size());
  // The container's bounding square is 1000 canonical units wide.
  const Box box = bounds(run.setup.container);
  EXPECT_NEAR(std::max(box.width(), box.height()), kCanonicalSide, 1e-6);
  EXPECT_NEAR(run.setup.containerArea, area(scene.container) * run.setup.frame.scale * run.setup.frame.scale,
              1e-6 * run.setup.containerArea);
  EXPECT_DOUBLE_EQ(run.nominalSkinArea, run.setup.containerArea / 8);
  EXPECT_GT(run.parameters.cellSize, 0.0);  // resolved from the mesh spacing
}

TEST_F(RepulsionPhases, ShrunkSeedsAreInsideAndApart) {
  const RepulsionRun run = prepareRepulsion(scene, library, quickOptions());
  Seeding seeding = seedPrimaries(run);
  ASSERT_EQ(seeding.seeds.size(), 8u);
  shrinkSeeds(run, seeding);
  EXPECT_GT(seeding.growth, 0.0);
  std::vector<Region> skins;
  for (const Seed& s : seeding.seeds) {
    const ElementMesh& mesh = run.types[s.type].mesh;
    Ring ring;
    for (int k = 0; k < mesh.boundaryCount; ++k)
      ring.push_back(s.position + rotated(mesh.mesh.vertices[k] - mesh.restCentroid, s.angle) * seeding.growth);
    skins.push_back(Region{Polygon{ring, {}}});
  }
  const PackingCheck check = verifyPacking(skins, run.setup.container);
  EXPECT_EQ(check.overlappingPairs, 0);
  EXPECT_EQ(check.elementsOutside, 0);
}

TEST_F(RepulsionPhases, InOrderTheyArePackRepulsion) {
  const RepulsionOptions options = quickOptions();
  const RepulsionRun run = prepareRepulsion(scene, library, options);
  Seeding seeding = seedPrimaries(run);
  shrinkSeeds(run, seeding);
  ThreadPool pool(options.run.threads);
  PackingSimulation sim = primarySimulation(run, seeding, pool);
  EXPECT_EQ(sim.meshes().size(), 8u);
  EXPECT_EQ(sim.iteration(), 0);
  const StopReason reason = simulate(sim, run, options.stop, options.stop.targetFill, 0, {}, {});
  EXPECT_EQ(reason, StopReason::IterationCap);
  EXPECT_EQ(sim.iteration(), options.stop.maxIterations);
  const int settled = settle(sim, run, options.stop, run.types);
  EXPECT_GE(settled, 0);
  EXPECT_LE(settled, options.stop.settleIterations);
  EXPECT_EQ(sim.iteration(), options.stop.maxIterations + settled);
  const Packing byPhases = collectPrimary(run, sim, seeding, reason);
  EXPECT_TRUE(samePacking(byPhases, packRepulsion(scene, library, options)));
  EXPECT_TRUE(artIsClean(byPhases));
}

TEST_F(RepulsionPhases, SettleUnfoldsAnElementFoldedOverItself) {
  constexpr double kFoldLength = 1.0;  // beyond the second neighbour, in skin segments
  // Folds one element, settles, and says whether its art still crosses itself.
  auto foldedAfterSettle = [&](double unfoldStrength) {
    RepulsionOptions options = quickOptions();
    options.count = 1;
    options.simulation.unfoldStrength = unfoldStrength;
    const RepulsionRun run = prepareRepulsion(scene, library, options);
    Seeding seeding = seedPrimaries(run);
    shrinkSeeds(run, seeding);
    ThreadPool pool(options.run.threads);
    PackingSimulation sim = primarySimulation(run, seeding, pool);
    // One skin vertex dragged along the skin past its next two neighbours: the skin and the
    // art bound to it zigzag back over themselves.
    std::vector<Vec2>& x = sim.positions();
    const int v = sim.meshes()[0].vertexBegin;
    x[v] = x[v + 2] + (x[v + 2] - x[v + 1]) * kFoldLength;
    EXPECT_FALSE(foldedMeshes(sim, run.types).empty());
    EXPECT_LE(settle(sim, run, options.stop, run.types), options.stop.settleIterations);
    return !foldedMeshes(sim, run.types).empty();
  };
  EXPECT_FALSE(foldedAfterSettle(RepulsionOptions{}.simulation.unfoldStrength));
  EXPECT_TRUE(foldedAfterSettle(0.0));  // the springs alone leave it folded
}

TEST_F(RepulsionPhases, TheTimeLimitStopsTheRun) {
  RepulsionOptions options = quickOptions();
  options.stop.timeLimit = 1e-9;
  const Packing packing = packRepulsion(scene, library, options);
  EXPECT_EQ(packing.stopReason, StopReason::TimeLimit);
  EXPECT_EQ(packing.iterations, 1);
}

TEST_F(RepulsionPhases, AStopRequestStopsTheRunAsTheTimeLimitDoes) {
  RepulsionOptions options = quickOptions();
  const std::atomic<bool> stop{true};
  options.run.stopRequest = &stop;
  const Packing packing = packRepulsion(scene, library, options);
  EXPECT_EQ(packing.stopReason, StopReason::Interrupted);
  EXPECT_STREQ(toString(packing.stopReason), "interrupted");
  EXPECT_EQ(packing.iterations, 1);
}

TEST_F(RepulsionPhases, TheSecondaryPassAddsElementsAndAPass) {
  RepulsionOptions options = quickOptions();
  options.secondary.minDistance = 60.0;  // a few large pockets: quick
  const Library secondary = loadLibrary({kExamples + "/elements/star.svg"});
  const RepulsionRun run = prepareRepulsion(scene, library, options);
  Seeding seeding = seedPrimaries(run);
  shrinkSeeds(run, seeding);
  ThreadPool pool(options.run.threads);
  PackingSimulation sim = primarySimulation(run, seeding, pool);
  Packing packing = collectPrimary(run, sim, seeding, simulate(sim, run, options.stop, 0.5, 0, {}, {}));
  secondaryPass(run, sim, secondary, pool, {}, packing);
  ASSERT_EQ(packing.passes.size(), 2u);
  int secondaries = 0;
  for (const PlacedElement& e : packing.elements) secondaries += e.secondary ? 1 : 0;
  EXPECT_EQ(secondaries, packing.passes[1].elements);
  EXPECT_GT(secondaries, 0);
  EXPECT_EQ(packing.iterations, packing.passes[0].iterations + packing.passes[1].iterations);
}

}  // namespace
}  // namespace pak
