// Every file of ../shared/data (real inputs nobody on this project drew) reads correctly.
// A fresh clone has no shared data: these tests then skip and say why.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "pak/io/path_reader.hpp"
#include "pak/io/scene_loader.hpp"
#include "pak/io/svg_reader.hpp"

namespace pak {
namespace {

namespace fs = std::filesystem;

const fs::path kSharedData = PAK_SHARED_DATA_DIR;

#define SKIP_WITHOUT_SHARED_DATA()                                                               \
  if (!fs::is_directory(kSharedData / "mdi") || !fs::is_directory(kSharedData / "repulsionpak")) \
  GTEST_SKIP() << "shared data not found at " << kSharedData.string()

std::vector<fs::path> filesIn(const fs::path& folder, const std::string& extension) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(folder))
    if (entry.path().extension() == extension) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

std::size_t holeCount(const Region& region) {
  std::size_t holes = 0;
  for (const Polygon& polygon : region) holes += polygon.holes.size();
  return holes;
}

TEST(SharedData, EveryMdiIconReadsWithArea) {
  SKIP_WITHOUT_SHARED_DATA();
  const auto files = filesIn(kSharedData / "mdi", ".svg");
  EXPECT_GE(files.size(), 30u);
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.string());
    SvgDocument document = readSvgFile(file.string());
    ASSERT_GE(document.shapes.size(), 1u);
    EXPECT_TRUE(document.warnings.empty());
    // Every subpath of an icon encloses something, with or without its closing "Z".
    for (const SvgShape& shape : document.shapes)
      for (const Subpath& subpath : shape.subpaths) EXPECT_TRUE(subpath.closed);
    EXPECT_DOUBLE_EQ(document.viewBox.width(), 24.0);
    EXPECT_DOUBLE_EQ(document.viewBox.height(), 24.0);
    ElementArt element = elementFromDocument(document).element;
    const double painted = area(element.outline);
    EXPECT_GT(painted, 1.0);
    EXPECT_LT(painted, 24.0 * 24.0);
  }
}

TEST(SharedData, MdiCatHasItsEyesAsHoles) {
  SKIP_WITHOUT_SHARED_DATA();
  SvgDocument document = readSvgFile((kSharedData / "mdi" / "cat.svg").string());
  ASSERT_EQ(document.shapes.size(), 1u);
  const SvgShape& cat = document.shapes[0];
  // Head outline, two eyes, and the nose-and-mouth.
  EXPECT_EQ(cat.subpaths.size(), 4u);
  for (const Subpath& subpath : cat.subpaths) EXPECT_TRUE(subpath.closed);
  const Region region = filledRegion(cat);
  ASSERT_EQ(region.size(), 1u);
  EXPECT_GE(holeCount(region), 3u);  // two eyes and the mouth
  // The eyes are discs of radius 1.
  int eyes = 0;
  for (const Ring& hole : region[0].holes)
    if (std::abs(std::abs(signedArea(hole)) - 3.14159) < 0.01) ++eyes;
  EXPECT_EQ(eyes, 2);
}

TEST(SharedData, RepulsionPakFilesHaveTheirPathCounts) {
  SKIP_WITHOUT_SHARED_DATA();
  // Path lines in each file (counted in the files themselves).
  const std::map<std::string, std::size_t> expected = {
      {"animals/bear.path", 5},  {"animals/bird.path", 2},    {"animals/bunny.path", 3},
      {"animals/cat.path", 3},   {"animals/dog.path", 5},     {"animals/fox.path", 4},
      {"animals/mouse.path", 3}, {"animals/penguin.path", 2}, {"animals/snake.path", 3},
      {"containers/heart.path", 1}, {"small_cat/cat.path", 3}};
  const auto files = filesIn(kSharedData / "repulsionpak", ".path");
  EXPECT_EQ(files.size(), expected.size());
  for (const fs::path& file : files) {
    const std::string key = fs::relative(file, kSharedData / "repulsionpak").generic_string();
    SCOPED_TRACE(key);
    SvgDocument document = readPathFile(file.string());
    ASSERT_TRUE(expected.count(key));
    EXPECT_EQ(document.shapes.size(), expected.at(key));
    EXPECT_TRUE(document.warnings.empty());
    for (const SvgShape& shape : document.shapes) {
      ASSERT_EQ(shape.subpaths.size(), 1u);
      EXPECT_TRUE(shape.subpaths[0].closed);
      EXPECT_GT(area(filledRegion(shape)), 0.0);
    }
    if (key.rfind("animals/", 0) == 0 || key.rfind("small_cat/", 0) == 0) {
      // The silhouette (last in the file, drawn first) covers the details.
      ElementArt element = elementFromDocument(document).element;
      EXPECT_NEAR(area(element.outline), area(filledRegion(document.shapes.front())),
                  1e-6 * area(element.outline));
    }
  }
}

TEST(SharedData, AnimalsAreRedSilhouettesWithWhiteDetails) {
  SKIP_WITHOUT_SHARED_DATA();
  SvgDocument document = readPathFile((kSharedData / "repulsionpak" / "animals" / "cat.path").string());
  ASSERT_EQ(document.shapes.size(), 3u);
  // The file lists white, white, red; the red silhouette is drawn first, under the details.
  EXPECT_EQ(*document.shapes[0].fill, (Color{240, 100, 101, 1.0}));
  EXPECT_EQ(document.shapes[0].subpaths[0].points.size(), 160u);
  EXPECT_EQ(*document.shapes[1].fill, (Color{255, 255, 255, 1.0}));
  EXPECT_EQ(*document.shapes[2].fill, (Color{255, 255, 255, 1.0}));
}

TEST(SharedData, SnakeSilhouetteComesOutClosedAndFilled) {
  SKIP_WITHOUT_SHARED_DATA();
  SvgDocument document = readPathFile((kSharedData / "repulsionpak" / "animals" / "snake.path").string());
  ASSERT_EQ(document.shapes.size(), 3u);
  const SvgShape& silhouette = document.shapes.front();
  EXPECT_TRUE(silhouette.subpaths[0].closed);
  EXPECT_EQ(silhouette.subpaths[0].points.size(), 552u);  // 553 stored, the first repeated
  EXPECT_TRUE(silhouette.fill);
  EXPECT_GT(area(filledRegion(silhouette)), 1000.0);
}

TEST(SharedData, HeartContainerArea) {
  SKIP_WITHOUT_SHARED_DATA();
  const LoadedScene heart = loadScene((kSharedData / "repulsionpak" / "containers" / "heart.path").string());
  ASSERT_EQ(heart.layout.containerShapes.size(), 1u);
  EXPECT_EQ(heart.layout.containerShapes[0].shape.subpaths[0].points.size(), 56u);  // 57 stored, first repeated
  EXPECT_FALSE(heart.layout.containerShapes[0].keepsPaint);  // a container by itself: drawn as an outline
  EXPECT_NEAR(area(heart.scene.container), 122440.0, 0.01 * 122440.0);
  EXPECT_EQ(heart.scene.container.size(), 1u);
  EXPECT_DOUBLE_EQ(heart.layout.viewBox.width(), 500.0);
}

TEST(SharedData, MdiHeartIsAContainerByItself) {
  SKIP_WITHOUT_SHARED_DATA();
  Scene scene = loadScene((kSharedData / "mdi" / "heart.svg").string()).scene;
  EXPECT_GT(area(scene.container), 100.0);
}

TEST(SharedData, LibraryOfTheAnimals) {
  SKIP_WITHOUT_SHARED_DATA();
  Library library = loadLibrary({(kSharedData / "repulsionpak" / "animals").string()});
  ASSERT_EQ(library.size(), 9u);
  EXPECT_EQ(library.front().name, "bear");
  EXPECT_EQ(library.back().name, "snake");
}

}  // namespace
}  // namespace pak
