// Tileable packings (thesis 4.8): periodic geometry, the periodic simulation, and the
// seamlessness of the result (the 2 × 2 repetition of a tile passes verifyPacking).
#include "pak/repulsion/tiling.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "pak/error.hpp"
#include "pak/geom/verify.hpp"
#include "pak/io/packing_drawing.hpp"
#include "pak/io/scene_loader.hpp"
#include "pak/io/svg_writer.hpp"
#include "pak/io/tile_drawing.hpp"
#include "pak/repulsion/repulsion.hpp"
#include "repulsion/mesh_fixtures.hpp"
#include "repulsion/packing_simulation.hpp"
#include "repulsion/thesis_parameters.hpp"

using namespace pak;

namespace {

const std::string kExamples = std::string(PAK_SOURCE_DIR) + "/examples";

Region square(Vec2 min, double side) {
  return {Polygon{{min, {min.x + side, min.y}, {min.x + side, min.y + side}, {min.x, min.y + side}}, {}}};
}

using test::squareMesh;

Vec2 meshCentre(const PackingSimulation& sim, int m) {
  const MeshInstance& mesh = sim.meshes()[m];
  Vec2 c;
  for (int v = mesh.vertexBegin; v < mesh.vertexBegin + mesh.vertexCount; ++v) c += sim.positions()[v];
  return c / static_cast<double>(mesh.vertexCount);
}

// Two squares 2 units apart across the left/right seam of a 100 × 40 tile (centres at x = 94
// and x = 6), far apart (88 units) without the seam.
struct SeamScene {
  Region tile = Region{Polygon{{{0, 0}, {100, 0}, {100, 40}, {0, 40}}, {}}};
  RegionIndex index{tile, 5.0};
  ThreadPool pool{1};
  PackingSimulation sim;
  SeamScene(bool periodic, double gapAcrossSeam, double dy = 0.0)
      : sim(index, 4000.0, parameters(), pool, domain(periodic)) {
    sim.addMesh(squareMesh(), 0, {95.0 - gapAcrossSeam / 2, 20}, 0.0, 1.0);
    sim.addMesh(squareMesh(), 0, {5.0 + gapAcrossSeam / 2, 20 + dy}, 0.0, 1.0);
    Box area;
    area.add(Vec2{-20, -20});
    area.add(Vec2{120, 60});
    sim.finalize(area);
  }
  static SimulationParameters parameters() {
    SimulationParameters p = test::thesisParameters();
    p.cellSize = 20.0;
    p.growthRate = 0.0;
    return p;
  }
  static PackingDomain domain(bool periodic) {
    PackingDomain d;
    if (periodic) d.period = {100, 40};
    return d;
  }
};

RepulsionOptions tileOptions() {
  RepulsionOptions o;
  o.tiling.size = {400, 300};
  o.gap = 16.0;
  o.count = 8;
  o.stop.targetFill = 0.55;
  o.stop.maxIterations = 5000;
  o.run.seed = 2;
  return o;
}

}  // namespace

TEST(Tiling, PeriodicDistanceTakesTheNearestClone) {
  EXPECT_DOUBLE_EQ(periodicDistance({1, 1}, {9, 1}, {10, 10}), 2.0);
  EXPECT_DOUBLE_EQ(periodicDistance({1, 1}, {9, 9}, {10, 10}), std::sqrt(8.0));
  EXPECT_DOUBLE_EQ(periodicDistance({2, 3}, {5, 3}, {10, 10}), 3.0);
  auto offsets = periodicOffsets({10, 20});
  EXPECT_EQ(offsets[0], (Vec2{0, 0}));
  EXPECT_EQ(offsets[1], (Vec2{-10, -20}));
  EXPECT_EQ(offsets[8], (Vec2{10, 20}));
}

TEST(Tiling, RepetitionCutsAnElementAcrossTheCornerIntoFourPieces) {
  // A 4 × 4 square centred on the tile's corner: a quarter in each corner of the tile.
  std::vector<Region> pieces = periodicRepetition({square({-2, -2}, 4)}, {10, 10}, 1, 1);
  ASSERT_EQ(pieces.size(), 4u);
  for (const Region& p : pieces) EXPECT_NEAR(area(p), 4.0, 1e-6);
  // In the 2 × 2 repetition: one whole square at the centre, halves on the edges, quarters in the corners.
  std::vector<Region> block = periodicRepetition({square({-2, -2}, 4)}, {10, 10}, 2, 2);
  double total = 0.0;
  for (const Region& p : block) total += area(p);
  EXPECT_NEAR(total, 4 * 16.0, 1e-6);
  EXPECT_EQ(block.size(), 9u);
}

TEST(Tiling, ClonesOverlapSeesAcrossTheSeam) {
  Vec2 period{10, 10};
  EXPECT_FALSE(clonesOverlap({square({2, 2}, 3), square({6, 6}, 3)}, period));
  EXPECT_TRUE(clonesOverlap({square({8, 2}, 3), square({0, 3}, 3)}, period));   // 8..11 wraps onto 0..1
  EXPECT_TRUE(clonesOverlap({square({-1, -1}, 12)}, period));                     // wider than the tile: its own clone
}

TEST(Tiling, MeshesPushEachOtherAcrossTheSeam) {
  SeamScene periodic(true, 2.0), bounded(false, 2.0);
  for (int i = 0; i < 200; ++i) {
    periodic.sim.step();
    bounded.sim.step();
  }
  // Periodic: the pair repelled each other across the seam, so they are now further apart on
  // the torus; bounded: 88 units apart, out of reach, they stay (up to the walls' pull).
  double before = 12.0;
  double after = periodicDistance(meshCentre(periodic.sim, 0), meshCentre(periodic.sim, 1), {100, 40});
  EXPECT_GT(after, before + 2.0);
  EXPECT_GT(meshCentre(periodic.sim, 1).x, 5.0 + 1.0);  // pushed right, away from the seam
  EXPECT_NEAR(distance(meshCentre(bounded.sim, 0), meshCentre(bounded.sim, 1)), 88.0, 1.0);
}

TEST(Tiling, OverlapAcrossTheSeamIsDetectedAndMeshesWrapWhole) {
  // Squares overlapping by 4 × 7 units across the seam: inside-other vertices on both.
  SeamScene scene(true, -4.0, 3.0);
  scene.sim.step();
  EXPECT_TRUE(scene.sim.meshes()[0].overlapping);
  EXPECT_TRUE(scene.sim.meshes()[1].overlapping);
  for (int i = 0; i < 300; ++i) scene.sim.step();
  EXPECT_FALSE(scene.sim.meshes()[0].overlapping);
  // Every mesh stays whole (its springs at rest length) with its centre in the tile.
  for (int m = 0; m < 2; ++m) {
    Vec2 c = meshCentre(scene.sim, m);
    EXPECT_GE(c.x, -1.0);
    EXPECT_LE(c.x, 101.0);
    const MeshInstance& mesh = scene.sim.meshes()[m];
    EXPECT_NEAR(distance(scene.sim.positions()[mesh.vertexBegin], scene.sim.positions()[mesh.vertexBegin + 1]), 10.0, 1.0);
  }
}

TEST(Tiling, TwoByTwoRepetitionOfATileIsOverlapFree) {
  Library library = loadLibrary({kExamples + "/elements"});
  RepulsionOptions options = tileOptions();
  Packing packing = packRepulsion(Scene{}, library, options);  // the scene is ignored in tile mode
  ASSERT_EQ(packing.elements.size(), 8u);
  EXPECT_EQ(packing.tile, options.tiling.size);
  EXPECT_EQ(packing.stopReason, StopReason::TargetFill);
  // The clean-up after the stop may let a pressed skin relax a little.
  EXPECT_GE(packing.skinFill, options.stop.targetFill - 0.005);
  EXPECT_NEAR(area(packing.container), 400.0 * 300.0, 1e-6);

  std::vector<Region> outlines = artOutlines(packing);
  // The seam check means something only if elements cross the tile's edge.
  int crossing = 0;
  for (const Region& r : outlines) {
    Box b = bounds(r);
    crossing += (b.min.x < 0 || b.max.x > 400 || b.min.y < 0 || b.max.y > 300) ? 1 : 0;
  }
  EXPECT_GE(crossing, 1);

  const Vec2 W{400, 300};
  std::vector<Region> repetition = periodicRepetition(outlines, W, 2, 2);
  PackingCheckOptions check;
  check.areaTolerance = 1e-5 * 4 * 400 * 300;
  Region block{Polygon{{{0, 0}, {800, 0}, {800, 600}, {0, 600}}, {}}};
  PackingCheck result = verifyPacking(repetition, block, check);
  EXPECT_TRUE(result.ok) << (result.problems.empty() ? "" : result.problems.front());
  EXPECT_EQ(result.overlappingPairs, 0);
  EXPECT_EQ(result.elementsOutside, 0);
  // The repetition holds 4 copies of all the art: fill over the block equals the tile's.
  double art = 0.0, tileArt = 0.0;
  for (const Region& r : repetition) art += area(r);
  for (const Region& r : outlines) tileArt += area(r);
  EXPECT_NEAR(art, 4.0 * tileArt, 1e-3 * art);
  EXPECT_GT(artFill(packing), 0.3);
  // Every element's centre stays in the tile (meshes wrap whole).
  for (const PlacedElement& e : packing.elements) {
    Vec2 c;
    for (Vec2 v : e.meshVertices) c += v;
    c = c / static_cast<double>(e.meshVertices.size());
    EXPECT_TRUE(c.x > -2 && c.x < 402 && c.y > -2 && c.y < 302) << c.x << "," << c.y;
  }
}

TEST(Tiling, SameSeedSameTileWhateverTheThreadCount) {
  Library library = loadLibrary({kExamples + "/elements"});
  RepulsionOptions options = tileOptions();
  options.stop.maxIterations = 300;
  std::string reference;
  for (int threads : {1, 2, 4}) {
    options.run.threads = threads;
    Packing packing = packRepulsion(Scene{}, library, options);
    std::string svg = toSvgString(packingDrawing(tileLayout(options.tiling.size), packing));
    if (reference.empty()) reference = svg;
    EXPECT_EQ(svg, reference) << "threads = " << threads;
  }
}

TEST(Tiling, TileDrawingClipsElementsAndDrawsTheirClones) {
  Library library = loadLibrary({kExamples + "/elements"});
  RepulsionOptions options = tileOptions();
  options.stop.maxIterations = 1500;
  Packing packing = packRepulsion(Scene{}, library, options);
  Drawing drawing = packingDrawing(tileLayout(options.tiling.size), packing);
  const DrawingGroup* elements = nullptr;
  for (const DrawingGroup& g : drawing.groups)
    if (g.id == "elements") elements = &g;
  ASSERT_NE(elements, nullptr);
  ASSERT_TRUE(elements->clip.has_value());
  EXPECT_EQ(elements->clip->min, (Vec2{0, 0}));
  EXPECT_EQ(elements->clip->max, (Vec2{400, 300}));
  ASSERT_EQ(elements->children.size(), packing.elements.size());
  // An element crossing the edge is drawn once more per neighbouring cell it reaches into.
  std::size_t extra = 0;
  for (std::size_t i = 0; i < packing.elements.size(); ++i) {
    EXPECT_EQ(elements->children[i].shapes.size() % packing.elements[i].art.size(), 0u);
    extra += elements->children[i].shapes.size() / packing.elements[i].art.size() - 1;
  }
  EXPECT_GE(extra, 1u);
  std::string svg = toSvgString(drawing);
  EXPECT_NE(svg.find("<clipPath id=\"pak-clip-1\"><rect x=\"0\" y=\"0\" width=\"400\" height=\"300\"/></clipPath>"),
            std::string::npos);
  EXPECT_NE(svg.find("clip-path=\"url(#pak-clip-1)\""), std::string::npos);
  // The 3 × 3 preview: 9 copies, each clipped to its own cell.
  Drawing preview = tileRepetition(drawing, options.tiling.size, 3, 3);
  EXPECT_EQ(preview.viewBox.max, (Vec2{1200, 900}));
  int clipped = 0;
  for (const DrawingGroup& g : preview.groups) clipped += g.clip ? 1 : 0;
  EXPECT_EQ(clipped, 9);
}

TEST(Tiling, RejectsBadTileSizes) {
  Library library = loadLibrary({kExamples + "/elements"});
  RepulsionOptions options = tileOptions();
  options.tiling.size = {-400, 300};
  EXPECT_THROW(packRepulsion(Scene{}, library, options), InputError);
  EXPECT_THROW(tileScene({400, std::nan("")}), InputError);
  EXPECT_THROW(tileScene({0, 300}), InputError);
  EXPECT_THROW(tileLayout({0, 300}), InputError);
}
