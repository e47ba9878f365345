// Fixed elements (thesis 1.1, "fixed elements"): copied to the output unchanged, obstacles
// that no element overlaps, counted as occupied in the fill ratios.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "pak/error.hpp"
#include "pak/geom/clipping.hpp"
#include "pak/geom/verify.hpp"
#include "pak/io/packing_drawing.hpp"
#include "pak/io/scene_loader.hpp"
#include "pak/io/svg_writer.hpp"
#include "pak/repulsion/repulsion.hpp"
#include "pak/repulsion/repulsion_presets.hpp"

using namespace pak;

namespace {

const std::string kExamples = std::string(PAK_SOURCE_DIR) + "/examples";

// The text of the output's <g id="fixed"> layer (it holds shapes only, no nested groups).
std::string fixedLayer(const std::string& svg) {
  std::size_t begin = svg.find("<g id=\"fixed\"");
  if (begin == std::string::npos) return {};
  std::size_t end = svg.find("</g>", begin);
  return svg.substr(begin, end - begin);
}

RepulsionOptions quickOptions() {
  RepulsionOptions o;
  o.gap = 16.0;
  o.count = 8;
  o.stop.targetFill = 0.45;
  o.stop.maxIterations = 3000;
  o.run.seed = 2;
  return o;
}

void expectNoOverlapsWithFixed(const Packing& packing) {
  ASSERT_FALSE(packing.fixedArt.empty());
  std::vector<Region> outlines = artOutlines(packing);
  outlines.push_back(packing.fixedArt);  // one more, immovable element
  PackingCheckOptions check;
  check.areaTolerance = 1e-5 * area(packing.container);
  PackingCheck result = verifyPacking(outlines, packing.container, check);
  EXPECT_TRUE(result.ok) << (result.problems.empty() ? "" : result.problems.front());
  EXPECT_EQ(result.overlappingPairs, 0);
  EXPECT_EQ(result.elementsOutside, 0);
}

}  // namespace

TEST(FixedElements, AreObstaclesCopiedUnchangedAndCountedInFill) {
  LoadedScene input = loadScene(kExamples + "/fixed-scene.svg");
  Scene& scene = input.scene;
  ASSERT_EQ(scene.fixed.size(), 3u);  // eye, pupil, gill (a stroke with no fill)
  Library library = loadLibrary({kExamples + "/elements"});
  Packing packing = packRepulsion(scene, library, quickOptions());
  expectNoOverlapsWithFixed(packing);

  // Nothing comes within gap/2 of a fixed element's paint (in canonical units, less a little
  // for the boundary springs' give).
  const double margin = 0.3 * quickOptions().gap / packing.canonicalScale;
  const Region keepOut = offset(packing.fixedArt, margin);
  for (const Region& outline : artOutlines(packing)) EXPECT_LT(area(intersect(outline, keepOut)), 1e-6 * area(keepOut));

  // The fill ratios count the fixed art: artFill minus the elements' own art is its area.
  double elementsArt = 0.0;
  for (const Region& r : artOutlines(packing)) elementsArt += area(r);
  const double fixedRatio = area(packing.fixedArt) / area(packing.container);
  EXPECT_GT(fixedRatio, 0.01);
  EXPECT_NEAR(artFill(packing), elementsArt / area(packing.container) + fixedRatio, 1e-12);
  double skins = 0.0;
  for (const PlacedElement& e : packing.elements) skins += area(Region{Polygon{e.skin, {}}});
  EXPECT_GT(packing.skinFill, skins / area(packing.container) + fixedRatio);

  // The output's fixed layer is the input's, untouched: the same bytes as a drawing of the
  // scene with no elements at all, and the same geometry and paint when read back.
  std::string svg = toSvgString(packingDrawing(input.layout, packing));
  Packing empty;
  empty.container = packing.container;
  empty.canonicalScale = packing.canonicalScale;
  EXPECT_EQ(fixedLayer(svg), fixedLayer(toSvgString(packingDrawing(input.layout, empty))));
  EXPECT_FALSE(fixedLayer(svg).empty());
}

TEST(FixedElements, SecondaryPassKeepsOffThemToo) {
  Scene scene = loadScene(kExamples + "/fixed-scene.svg").scene;
  Library library = loadLibrary({kExamples + "/elements/cat.svg", kExamples + "/elements/fish.svg"});
  Library secondary = loadLibrary({kExamples + "/elements/star.svg"});
  RepulsionOptions options = quickOptions();
  options.stop.maxIterations = 600;
  Packing packing = packRepulsion(scene, library, secondary, options);
  ASSERT_EQ(packing.passes.size(), 2u);
  EXPECT_GT(packing.passes[1].elements, 0);
  expectNoOverlapsWithFixed(packing);
}

TEST(FixedElements, FocalPathsOfPathFilesAreFixedElements) {
  // A .path scene: a square container and a focal path (type 2), a square in the middle.
  const auto file = std::filesystem::temp_directory_path() / ("pak-focal-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + ".path");
  std::ofstream(file) << "1\nforeground_color_rgb 0 0,0,0 0,0,0\nbackground_color_rgb 0 -1,-1,-1 200,30,30\n"
                         "0 1 0 0 0 1000 0 1000 1000 0 1000\n0 1 2 400 400 600 400 600 600 400 600\n";
  Scene scene = loadScene(file.string()).scene;
  std::filesystem::remove(file);
  ASSERT_EQ(scene.fixed.size(), 1u);
  RepulsionOptions options = quickOptions();
  options.count = 6;
  options.stop.maxIterations = 400;
  Packing packing = packRepulsion(scene, loadLibrary({kExamples + "/elements/cat.svg"}), options);
  expectNoOverlapsWithFixed(packing);
  // The focal square (and its 1-unit stroke) is occupied: 201² of the 1000² container.
  EXPECT_NEAR(area(packing.fixedArt), 201.0 * 201.0, 1.0);
}

TEST(RigidPreset, KeepsShapesNearlyUndeformedAndOverlapFree) {
  Scene scene = loadScene(kExamples + "/scene.svg").scene;
  Library library = loadLibrary({kExamples + "/elements"});
  RepulsionOptions soft = quickOptions();
  RepulsionOptions rigid = quickOptions();
  applyRepulsionPreset("rigid", rigid);
  EXPECT_EQ(rigid.simulation.edgeStrength, 1000.0);
  EXPECT_EQ(rigid.gap, soft.gap);  // a preset sets strengths and the stepping only
  // Eq. 4.7 in simulated time: window × Δt and ε / Δt as the defaults'.
  const RepulsionOptions defaults;
  EXPECT_NEAR(rigid.stop.stallWindow * rigid.simulation.timeStep,
              defaults.stop.stallWindow * defaults.simulation.timeStep, 1e-9);
  EXPECT_NEAR(rigid.stop.stallEpsilon / rigid.simulation.timeStep,
              defaults.stop.stallEpsilon / defaults.simulation.timeStep, 1e-12);
  rigid.stop.maxIterations = 3000;
  applyRepulsionPreset("soft", soft);
  auto maxStrain = [](const Packing& p) {
    double s = 0.0;
    for (const PlacedElement& e : p.elements) s = std::max(s, e.maxEdgeStrain);
    return s;
  };
  auto meanStrain = [](const Packing& p) {
    double s = 0.0;
    for (const PlacedElement& e : p.elements) s += e.meanEdgeStrain / p.elements.size();
    return s;
  };
  Packing rigidPacking = packRepulsion(scene, library, rigid);
  Packing softPacking = packRepulsion(scene, library, soft);
  // Measured at k_edg 1000 / 40 / 5: max 0.072 / 0.33 / 0.98, mean 0.0048 / 0.016 / 0.044
  // before the anti-inversion term and self-repulsion, which cap the soft preset's worst
  // folds: now rigid 0.064 / 0.0053 against soft (k_edg 10) 0.29 / 0.019.
  EXPECT_LT(maxStrain(rigidPacking), 0.1);
  EXPECT_LT(meanStrain(rigidPacking), 0.01);
  EXPECT_GT(maxStrain(softPacking), 3.0 * maxStrain(rigidPacking));
  EXPECT_GT(meanStrain(softPacking), 3.0 * meanStrain(rigidPacking));
  PackingCheckOptions check;
  check.areaTolerance = 1e-5 * area(rigidPacking.container);
  PackingCheck result = verifyPacking(artOutlines(rigidPacking), rigidPacking.container, check);
  EXPECT_TRUE(result.ok) << (result.problems.empty() ? "" : result.problems.front());
  EXPECT_THROW(applyRepulsionPreset("wobbly", rigid), InputError);
}
