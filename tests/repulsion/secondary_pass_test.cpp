// Secondary elements (thesis 4.6): seeds from the distance transform of the negative space,
// then a second pass with the primaries frozen.
#include <gtest/gtest.h>

#include <cmath>

#include "pak/geom/clipping.hpp"
#include "pak/geom/verify.hpp"
#include "pak/io/packing_drawing.hpp"
#include "pak/io/scene_loader.hpp"
#include "pak/io/svg_writer.hpp"
#include "pak/repulsion/repulsion.hpp"
#include "repulsion/secondary_seeding.hpp"

using namespace pak;

namespace {

const std::string kExamples = std::string(PAK_SOURCE_DIR) + "/examples";

Region rectangle(double x0, double y0, double x1, double y1) {
  return Region{Polygon{Ring{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}}};
}

// Exact distance from p to the region's boundary.
double boundaryDistance(Vec2 p, const Region& region) {
  double best = 1e300;
  auto ring = [&](const Ring& r) {
    for (std::size_t k = 0; k < r.size(); ++k) {
      Vec2 a = r[k], b = r[(k + 1) % r.size()], ab = b - a;
      double t = std::clamp(dot(p - a, ab) / lengthSquared(ab), 0.0, 1.0);
      best = std::min(best, distance(p, a + ab * t));
    }
  };
  for (const Polygon& poly : region) {
    ring(poly.outer);
    for (const Ring& h : poly.holes) ring(h);
  }
  return best;
}

std::vector<Vec2> artPoints(const PlacedElement& e) {
  std::vector<Vec2> points;
  for (const Shape& shape : e.art)
    for (const Subpath& sub : shape.subpaths) points.insert(points.end(), sub.points.begin(), sub.points.end());
  return points;
}

RepulsionOptions quickOptions() {
  RepulsionOptions o;
  o.gap = 16.0;
  o.count = 8;
  o.stop.targetFill = 0.45;
  o.stop.maxIterations = 3000;
  o.run.seed = 5;
  return o;
}

// The bundled scene with three primaries and two secondaries, passes kept short; the
// secondary pass as the thesis's (the primaries frozen, no press).
struct TwoPassScene {
  LoadedScene input = loadScene(kExamples + "/scene.svg");
  Library primaries = loadLibrary({kExamples + "/elements/cat.svg", kExamples + "/elements/fish.svg",
                                   kExamples + "/elements/bird.svg"});
  Library secondaries = loadLibrary({kExamples + "/elements/star.svg", kExamples + "/elements/moon.svg"});
  RepulsionOptions options = [] {
    RepulsionOptions o = quickOptions();
    o.stop.maxIterations = 450;  // per pass
    o.secondary.pressIterations = 0;
    return o;
  }();
  Packing pack() const { return packRepulsion(input.scene, primaries, secondaries, options); }
};

// No overlapping pair and nothing outside, the art checked at 1e-5 of the container's area.
PackingCheck expectCleanArt(const Packing& packing) {
  PackingCheckOptions check;
  check.areaTolerance = 1e-5 * area(packing.container);
  PackingCheck result = verifyPacking(artOutlines(packing), packing.container, check);
  EXPECT_TRUE(result.ok) << (result.problems.empty() ? "" : result.problems.front());
  EXPECT_EQ(result.overlappingPairs, 0);
  EXPECT_EQ(result.elementsOutside, 0);
  return result;
}

}  // namespace

TEST(SecondarySeeding, DeepestPocketFirstAndOnlyAboveMinDistance) {
  // A 100 × 100 room joined to a 12-wide corridor: only the room has points 10 from walls.
  Region free = unite(rectangle(0, 0, 100, 100), rectangle(100, 44, 400, 56));
  SecondarySeedingOptions options;
  options.minDistance = 10.0;
  options.separation = 30.0;
  options.resolution = 400;  // 1-unit cells over the 400-wide frame
  std::vector<SecondarySeed> seeds = secondarySeeds(free, bounds(free), options);
  ASSERT_FALSE(seeds.empty());
  // The room's centre is the deepest point (distance 50).
  EXPECT_NEAR(seeds.front().position.x, 50.0, 1.0);
  EXPECT_NEAR(seeds.front().position.y, 50.0, 1.0);
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    const Vec2 p = seeds[i].position;
    EXPECT_GE(boundaryDistance(p, free), options.minDistance - 1e-9) << i;
    EXPECT_LE(p.x, 100.0) << "no seed in the 12-wide corridor";
    EXPECT_LE(seeds[i].radius, boundaryDistance(p, free) + 1e-9);
    for (std::size_t j = 0; j < i; ++j) {
      EXPECT_GE(distance(p, seeds[j].position), options.separation) << i << " " << j;
      // Empty discs of two seeds do not overlap.
      EXPECT_LE(seeds[i].radius + seeds[j].radius, distance(p, seeds[j].position) + 1e-9);
    }
  }
  // Too narrow everywhere: no seed.
  options.minDistance = 51.0;
  EXPECT_TRUE(secondarySeeds(free, bounds(free), options).empty());
}

TEST(SecondaryPass, FillsPocketsWithoutMovingPrimariesOrOverlapping) {
  const TwoPassScene two;
  const Library& secondary = two.secondaries;
  Packing primaryOnly = packRepulsion(two.input.scene, two.primaries, two.options);
  Packing packing = two.pack();

  ASSERT_EQ(packing.passes.size(), 2u);
  const PackingPass& first = packing.passes[0];
  const PackingPass& second = packing.passes[1];
  EXPECT_EQ(first.iterations, primaryOnly.iterations);
  EXPECT_EQ(packing.iterations, first.iterations + second.iterations);
  ASSERT_GT(second.elements, 0);
  EXPECT_GT(second.iterations, 0);
  // The secondary pass raises both fills.
  EXPECT_GT(second.skinFill, first.skinFill + 0.01);
  EXPECT_GT(second.artFill, first.artFill + 0.005);
  EXPECT_NEAR(second.artFill, artFill(packing), 1e-12);

  // Primaries are frozen: bit for bit where the primary pass left them.
  int secondaries = 0;
  ASSERT_EQ(packing.elements.size(), primaryOnly.elements.size() + static_cast<std::size_t>(second.elements));
  for (std::size_t i = 0; i < packing.elements.size(); ++i) {
    const PlacedElement& e = packing.elements[i];
    if (e.secondary) {
      ++secondaries;
      EXPECT_LT(e.libraryIndex, static_cast<int>(secondary.size()));
      EXPECT_EQ(e.source, secondary[e.libraryIndex].source);
      continue;
    }
    ASSERT_LT(i, primaryOnly.elements.size());
    EXPECT_EQ(e.meshVertices, primaryOnly.elements[i].meshVertices) << i;
    EXPECT_EQ(artPoints(e), artPoints(primaryOnly.elements[i])) << i;
  }
  EXPECT_EQ(secondaries, second.elements);

  // The whole result: no overlaps, everything inside.
  expectCleanArt(packing);

  // Secondaries are drawn as elements with their own class.
  std::string svg = toSvgString(packingDrawing(two.input.layout, packing));
  std::size_t marked = 0;
  for (std::size_t at = svg.find("class=\"element secondary\""); at != std::string::npos;
       at = svg.find("class=\"element secondary\"", at + 1))
    ++marked;
  EXPECT_EQ(marked, static_cast<std::size_t>(secondaries));
}

TEST(SecondaryPass, PressingFreesThePrimariesAndLeavesTheResultClean) {
  TwoPassScene two;
  const Packing frozen = two.pack();
  two.options.secondary.pressIterations = 200;
  const Packing pressed = two.pack();

  // The same pockets get the same secondaries; the press and the clean-up come after.
  ASSERT_EQ(pressed.passes.size(), 2u);
  EXPECT_EQ(pressed.passes[1].elements, frozen.passes[1].elements);
  EXPECT_GE(pressed.passes[1].iterations, 200 + pressed.passes[1].settleIterations);
  // Some primary moved, and none is gone.
  ASSERT_EQ(pressed.elements.size(), frozen.elements.size());
  int moved = 0;
  for (std::size_t i = 0; i < pressed.elements.size(); ++i)
    if (!pressed.elements[i].secondary && artPoints(pressed.elements[i]) != artPoints(frozen.elements[i])) ++moved;
  EXPECT_GT(moved, 0);
  PackingCheck result = expectCleanArt(pressed);
  checkSelfIntersections(artRings(pressed), result);
  EXPECT_EQ(result.selfIntersecting, 0);
}

TEST(SecondaryPass, NoPocketDeepEnoughMeansNoSecondaries) {
  Scene scene = loadScene(kExamples + "/scene.svg").scene;
  Library library = loadLibrary({kExamples + "/elements/cat.svg"});
  Library secondary = loadLibrary({kExamples + "/elements/star.svg"});
  RepulsionOptions options = quickOptions();
  options.stop.maxIterations = 300;
  options.secondary.minDistance = 2000.0;  // farther than anything in a 1000-wide frame
  Packing packing = packRepulsion(scene, library, secondary, options);
  ASSERT_EQ(packing.passes.size(), 2u);
  EXPECT_EQ(packing.passes[1].elements, 0);
  EXPECT_EQ(packing.passes[1].iterations, 0);
  for (const PlacedElement& e : packing.elements) EXPECT_FALSE(e.secondary);
}

TEST(SecondaryPass, SameSeedSameBytesWhateverTheThreadCount) {
  LoadedScene input = loadScene(kExamples + "/scene.svg");
  Scene& scene = input.scene;
  Library library = loadLibrary({kExamples + "/elements/cat.svg"});
  Library secondary = loadLibrary({kExamples + "/elements/star.svg", kExamples + "/elements/moon.svg"});
  RepulsionOptions options = quickOptions();
  options.count = 5;
  options.stop.maxIterations = 150;  // per pass
  std::string reference;
  for (int threads : {1, 2}) {
    options.run.threads = threads;
    Packing packing = packRepulsion(scene, library, secondary, options);
    ASSERT_GT(packing.passes.back().elements, 0);
    std::string svg = toSvgString(packingDrawing(input.layout, packing));
    if (reference.empty()) reference = svg;
    EXPECT_EQ(svg, reference) << "threads = " << threads;
  }
}
