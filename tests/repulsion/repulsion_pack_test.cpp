#include "pak/repulsion/repulsion.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "pak/error.hpp"
#include "pak/geom/clipping.hpp"
#include "pak/geom/verify.hpp"
#include "pak/io/packing_drawing.hpp"
#include "pak/io/scene_loader.hpp"
#include "pak/io/svg_writer.hpp"

using namespace pak;
namespace fs = std::filesystem;

namespace {

const std::string kExamples = std::string(PAK_SOURCE_DIR) + "/examples";
const std::string kData = PAK_SHARED_DATA_DIR;

void expectValidPacking(const Packing& packing) {
  PackingCheckOptions options;
  options.areaTolerance = 1e-5 * area(packing.container);
  PackingCheck check = verifyPacking(artOutlines(packing), packing.container, options);
  EXPECT_TRUE(check.ok) << (check.problems.empty() ? "" : check.problems.front());
  EXPECT_EQ(check.overlappingPairs, 0);
  EXPECT_EQ(check.elementsOutside, 0);
}

// A small, quick version of the bundled example (coarse meshes, few elements).
RepulsionOptions quickOptions() {
  RepulsionOptions o;
  o.gap = 16.0;
  o.count = 10;
  o.stop.targetFill = 0.45;
  o.stop.maxIterations = 6000;
  o.run.seed = 3;
  return o;
}

}  // namespace

TEST(RepulsionPack, BundledExampleReachesTargetWithoutOverlaps) {
  Scene scene = loadScene(kExamples + "/scene.svg").scene;
  Library library = loadLibrary({kExamples + "/elements"});
  RepulsionOptions options = quickOptions();
  Packing packing = packRepulsion(scene, library, options);
  EXPECT_EQ(packing.stopReason, StopReason::TargetFill);
  // The clean-up after the stop shrinks what was pressed too deep into a neighbour, so the
  // final fill may sit a little under the target that stopped the growth.
  EXPECT_GE(packing.skinFill, options.stop.targetFill - 0.01);
  EXPECT_GT(packing.passes.front().settleIterations, 0);
  EXPECT_EQ(packing.elements.size(), 10u);
  expectValidPacking(packing);
  for (const PlacedElement& e : packing.elements) EXPECT_GT(e.growth, 0.0);
}

TEST(RepulsionPack, SameSeedSameBytesWhateverTheThreadCount) {
  LoadedScene input = loadScene(kExamples + "/scene.svg");
  Scene& scene = input.scene;
  Library library = loadLibrary({kExamples + "/elements"});
  RepulsionOptions options = quickOptions();
  options.stop.maxIterations = 400;  // determinism shows early; keep it quick
  std::string reference;
  for (int threads : {1, 2, 4}) {
    options.run.threads = threads;
    std::string svg = toSvgString(packingDrawing(input.layout, packRepulsion(scene, library, options)));
    if (reference.empty()) reference = svg;
    EXPECT_EQ(svg, reference) << "threads = " << threads;
  }
  options.run.seed = 4;
  EXPECT_NE(toSvgString(packingDrawing(input.layout, packRepulsion(scene, library, options))), reference);
}

TEST(RepulsionPack, RejectsBadOptionsAndEmptyLibrary) {
  Scene scene = loadScene(kExamples + "/scene.svg").scene;
  Library library = loadLibrary({kExamples + "/elements"});
  RepulsionOptions bad;
  bad.gap = -1.0;
  EXPECT_THROW(packRepulsion(scene, library, bad), InputError);
  EXPECT_THROW(packRepulsion(scene, Library{}, RepulsionOptions{}), InputError);
}

TEST(RepulsionPack, SharedAnimalsInHeart) {
  if (!fs::exists(kData + "/repulsionpak")) GTEST_SKIP() << "shared data not found at " << kData;
  Scene scene = loadScene(kData + "/repulsionpak/containers/heart.path").scene;
  Library library = loadLibrary({kData + "/repulsionpak/animals"});
  RepulsionOptions options;
  options.count = 27;
  Packing packing = packRepulsion(scene, library, options);
  expectValidPacking(packing);
  EXPECT_GE(artFill(packing), 0.50);
}

TEST(RepulsionPack, SharedMdiAnimalsInMdiHeart) {
  if (!fs::exists(kData + "/mdi")) GTEST_SKIP() << "shared data not found at " << kData;
  Scene scene = loadScene(kData + "/mdi/heart.svg").scene;
  std::vector<std::string> files;
  for (const char* name : {"cat", "dog", "rabbit", "bird", "fish", "penguin", "turtle", "snail"})
    files.push_back(kData + "/mdi/" + name + ".svg");
  Library library = loadLibrary(files);
  Packing packing = packRepulsion(scene, library, RepulsionOptions{});
  expectValidPacking(packing);
  EXPECT_GE(artFill(packing), 0.50);
}
