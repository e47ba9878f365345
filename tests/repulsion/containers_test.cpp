// Several containers, holes, per-container libraries and a previous packing's elements as
// containers (issue 5 items 3 and 6b; thesis Figures 4.10 and 4.12b).
#include "repulsion/container_seeding.hpp"
#include "sim/scene_containers.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "pak/error.hpp"
#include "pak/geom/clipping.hpp"
#include "pak/geom/verify.hpp"
#include "pak/io/packing_drawing.hpp"
#include "pak/io/scene_loader.hpp"
#include "pak/io/svg_reader.hpp"
#include "pak/io/svg_writer.hpp"
#include "pak/repulsion/repulsion.hpp"

using namespace pak;
namespace fs = std::filesystem;

namespace {

const std::string kExamples = std::string(PAK_SOURCE_DIR) + "/examples";

std::string fileName(const std::string& path) { return fs::path(path).filename().string(); }

// Area of what `art` paints outside `region`.
double outsideArea(const Region& art, const Region& region) { return area(subtract(art, region)); }

// Every element's art lies inside the container it was seeded in (and so out of its holes)
// and out of every other container; none overlap.
void expectEachInItsOwnContainer(const Packing& packing) {
  ASSERT_FALSE(packing.containers.empty());
  const double tolerance = 1e-5 * area(packing.container);
  std::vector<Region> outlines = artOutlines(packing);
  for (std::size_t i = 0; i < outlines.size(); ++i) {
    const int own = packing.elements[i].container;
    ASSERT_GE(own, 0);
    ASSERT_LT(own, static_cast<int>(packing.containers.size()));
    EXPECT_LE(outsideArea(outlines[i], packing.containers[own]), tolerance) << "element " << i;
    for (std::size_t c = 0; c < packing.containers.size(); ++c)
      if (static_cast<int>(c) != own) {
        EXPECT_LE(area(intersect(outlines[i], packing.containers[c])), tolerance) << "element " << i << " in " << c;
      }
  }
  PackingCheckOptions options;
  options.areaTolerance = tolerance;
  PackingCheck check = verifyPacking(outlines, packing.container, options);
  EXPECT_EQ(check.overlappingPairs, 0);
  EXPECT_EQ(check.elementsOutside, 0);
}

RepulsionOptions quick(int count) {
  RepulsionOptions o;
  o.gap = 14.0;
  o.count = count;
  o.stop.targetFill = 0.40;
  o.stop.maxIterations = 1500;
  o.run.seed = 5;
  return o;
}

// The container of `packing` whose bounds contain `p`.
int containerAt(const Packing& packing, Vec2 p) {
  for (std::size_t c = 0; c < packing.containers.size(); ++c)
    if (bounds(packing.containers[c]).contains(p)) return static_cast<int>(c);
  return -1;
}

}  // namespace

TEST(Containers, SeedsAreSharedByAreaWithOneForEveryRoomyContainer) {
  EXPECT_EQ(seedsPerContainer({1.0, 1.0, 2.0}, 8, 0.1), (std::vector<int>{2, 2, 4}));
  EXPECT_EQ(seedsPerContainer({3.0}, 7, 0.1), (std::vector<int>{7}));
  // 10 seeds over 3:3:4 → 3, 3, 4; the largest remainders take what rounding leaves.
  EXPECT_EQ(seedsPerContainer({1.0, 1.0, 1.0}, 10, 0.1), (std::vector<int>{4, 3, 3}));
  // A small container still gets one if it is at least the minimum, else none.
  EXPECT_EQ(seedsPerContainer({100.0, 1.0}, 10, 0.5), (std::vector<int>{10, 1}));
  EXPECT_EQ(seedsPerContainer({100.0, 0.2}, 10, 0.5), (std::vector<int>{10, 0}));
}

TEST(Containers, SceneLoaderSplitsDisjointPartsAndResolvesTheirLibraries) {
  Scene scene = loadScene(kExamples + "/rooms.svg", SceneOptions{}).scene;
  ASSERT_EQ(scene.containers.size(), 3u);
  int withHole = 0, ownLibraries = 0;
  for (const ContainerPart& part : scene.containers) {
    ASSERT_EQ(part.region.size(), 1u);
    withHole += part.region.front().holes.size() == 1 ? 1 : 0;
    Box box = bounds(part.region);
    if (box.min.x < 100) {  // left square: data-elements on the shape
      ASSERT_EQ(part.library.size(), 1u);
      EXPECT_EQ(fileName(part.library[0].source), "star.svg");
    } else if (box.min.x < 500) {  // right square: the run's library
      EXPECT_TRUE(part.library.empty());
      EXPECT_TRUE(part.elementFiles.empty());
    } else {  // ring: data-elements on the enclosing group
      ASSERT_EQ(part.library.size(), 2u);
      EXPECT_EQ(fileName(part.library[0].source), "leaf.svg");
      EXPECT_EQ(fileName(part.library[1].source), "moon.svg");
    }
    ownLibraries += part.library.empty() ? 0 : 1;
  }
  EXPECT_EQ(withHole, 1);
  EXPECT_EQ(ownLibraries, 2);
  // Without the scene options nothing is loaded, but the parts are still there.
  EXPECT_EQ(loadScene(kExamples + "/rooms.svg").scene.containers.size(), 3u);
}

TEST(Containers, ElementsStayInTheirContainerOutOfHolesWithTheirOwnLibrary) {
  Scene scene = loadScene(kExamples + "/rooms.svg", SceneOptions{}).scene;
  Library run = loadLibrary({kExamples + "/elements/cat.svg", kExamples + "/elements/mushroom.svg"});
  Packing packing = packRepulsion(scene, run, quick(13));
  ASSERT_EQ(packing.containers.size(), 3u);
  expectEachInItsOwnContainer(packing);

  const int left = containerAt(packing, {100, 100}), right = containerAt(packing, {600, 100}),
            ring = containerAt(packing, {1000, 50});
  ASSERT_TRUE(left >= 0 && right >= 0 && ring >= 0);
  std::vector<int> perContainer(3, 0);
  const Region hole = Region{Polygon{packing.containers[ring].front().holes.front(), {}}};
  for (const PlacedElement& e : packing.elements) {
    ++perContainer[e.container];
    const std::string name = fileName(e.source);
    if (e.container == left) {
      EXPECT_EQ(name, "star.svg");
    } else if (e.container == right) {
      EXPECT_TRUE(name == "cat.svg" || name == "mushroom.svg") << name;
    } else {
      EXPECT_EQ(e.container, ring);
      EXPECT_TRUE(name == "leaf.svg" || name == "moon.svg") << name;
    }
  }
  for (const Region& art : artOutlines(packing)) EXPECT_LE(area(intersect(art, hole)), 1e-6 * area(packing.container));
  // 13 seeds by area: the squares are 122,500 each and the ring π(180² − 80²) ≈ 81,681, so
  // shares of 4.875, 4.875 and 3.25.
  EXPECT_EQ(perContainer[left], 5);
  EXPECT_EQ(perContainer[right], 5);
  EXPECT_EQ(perContainer[ring], 3);
}

TEST(Containers, PreviousPackingElementsBecomeContainers) {
  // A small "previous packing" in Pak's output layout: three placed elements, one of them a
  // ring drawn as a thick stroke (its silhouette is the whole disc).
  const std::string previous = R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 900 400">
    <g id="container"><rect x="0" y="0" width="900" height="400" fill="none" stroke="#000"/></g>
    <g id="elements">
      <g class="element" data-source="blob.svg"><path fill="#c44" d="M 40 200 C 40 60, 260 60, 260 200 C 260 340, 40 340, 40 200 Z"/></g>
      <g class="element" data-source="box.svg"><rect x="320" y="60" width="260" height="280" fill="#4c4"/>
        <circle cx="450" cy="200" r="30" fill="#fff"/></g>
      <g class="element" data-source="ring.svg"><circle cx="750" cy="200" r="110" fill="none" stroke="#44c" stroke-width="20"/></g>
    </g></svg>)";
  Scene scene = sceneFromDocument(readSvgString(previous, "previous.svg"), SceneOptions{"elements"}).scene;
  ASSERT_EQ(scene.containers.size(), 3u);
  // The ring's silhouette fills its middle: a disc of radius 120.
  const int ringPart = bounds(scene.containers[2].region).min.x > 600 ? 2 : (bounds(scene.containers[0].region).min.x > 600 ? 0 : 1);
  EXPECT_NEAR(area(scene.containers[ringPart].region), 3.14159265 * 120 * 120, 0.01 * 3.14159265 * 120 * 120);
  // The old container layer is not a container now.
  EXPECT_LT(area(scene.container), 0.5 * 900 * 400);

  Library circles = loadLibrary({kExamples + "/elements/moon.svg"});
  Packing packing = packRepulsion(scene, circles, quick(9));
  expectEachInItsOwnContainer(packing);
  std::set<int> used;
  for (const PlacedElement& e : packing.elements) used.insert(e.container);
  EXPECT_EQ(used.size(), 3u);
}

TEST(Containers, SingleContainerRunIsUnchangedByTheContainerList) {
  // A scene with its part list and the same scene without it give the same bytes.
  LoadedScene input = loadScene(kExamples + "/scene.svg");
  Scene& scene = input.scene;
  Library library = loadLibrary({kExamples + "/elements"});
  RepulsionOptions options = quick(6);
  options.stop.maxIterations = 200;
  std::string with = toSvgString(packingDrawing(input.layout, packRepulsion(scene, library, options)));
  ASSERT_EQ(scene.containers.size(), 1u);
  scene.containers.clear();
  EXPECT_EQ(toSvgString(packingDrawing(input.layout, packRepulsion(scene, library, options))), with);
}

TEST(Containers, BadContainerLayerAndLibraryAreInputErrors) {
  EXPECT_THROW(loadScene(kExamples + "/rooms.svg", SceneOptions{"nosuchlayer"}), InputError);
  EXPECT_THROW(loadScene(kExamples + "/rooms.svg", SceneOptions{"fixed"}), InputError);
  const std::string missing = R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">
    <g id="container"><rect width="100" height="100" data-elements="  ,  "/></g></svg>)";
  EXPECT_THROW(sceneFromDocument(readSvgString(missing, "m.svg"), SceneOptions{}), InputError);
}

TEST(Containers, SeveralContainersWithAFieldAreDeterministicWhateverTheThreadCount) {
  LoadedScene input = loadScene(kExamples + "/rooms.svg", SceneOptions{});
  Scene& scene = input.scene;
  Library run = loadLibrary({kExamples + "/elements/cat.svg"});
  RepulsionOptions options = quick(9);
  options.stop.maxIterations = 150;
  options.orientation.mode = OrientationMode::Field;
  options.orientation.field = {'y', -30.0, 60.0};
  std::string reference;
  for (int threads : {1, 2, 3}) {
    options.run.threads = threads;
    std::string svg = toSvgString(packingDrawing(input.layout, packRepulsion(scene, run, options)));
    if (reference.empty()) reference = svg;
    EXPECT_EQ(svg, reference) << "threads = " << threads;
  }
}
