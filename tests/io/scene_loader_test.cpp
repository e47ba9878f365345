// Scenes and element libraries from documents (the input conventions of DESIGN.md), and
// the drawing `pak render` shows.
#include "pak/io/scene_loader.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "pak/error.hpp"
#include "pak/io/drawing.hpp"
#include "pak/io/path_reader.hpp"

namespace pak {
namespace {

namespace fs = std::filesystem;

SvgDocument svgDocument(const std::string& body, const std::string& name = "scene.svg") {
  return readSvgString(R"~(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">)~" + body + "</svg>", name);
}

template <class F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const InputError& error) {
    return error.what();
  }
  return "(no error)";
}

bool hasWarning(const std::vector<Warning>& warnings, const std::string& text) {
  for (const Warning& warning : warnings)
    if ((warning.where + ": " + warning.message).find(text) != std::string::npos) return true;
  return false;
}

// A temporary folder removed at the end of the test.
class TempFolder {
 public:
  TempFolder() {
    // Unique per process and test: several builds may run their tests at once.
    path_ = fs::temp_directory_path() / ("pak-io-test-" + std::to_string(::getpid()) + "-" +
                                         ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  std::string write(const std::string& name, const std::string& text) const {
    const fs::path file = path_ / name;
    std::ofstream(file) << text;
    return file.string();
  }
  std::string path() const { return path_.string(); }

 private:
  fs::path path_;
};

const std::string kSquare = R"~(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10"><rect width="4" height="5"/></svg>)~";

// ---- scenes ------------------------------------------------------------------------------

TEST(SceneLoader, LayersBecomeContainerFixedGuidesSpines) {
  const LoadedScene loaded = sceneFromDocument(svgDocument(R"~(
      <g id="container"><path d="M0 0 H100 V100 H0 Z M20 20 V40 H40 V20 Z" fill="none" stroke="black"/></g>
      <g inkscape:label="Fixed" xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape">
        <circle cx="70" cy="70" r="5" fill="red"/></g>
      <g id="guides"><path d="M10 90 L90 90" stroke="blue"/></g>
      <g id="spines"><path d="M50 10 L50 30" stroke="blue"/></g>)~"));
  const Scene& scene = loaded.scene;
  ASSERT_EQ(loaded.layout.containerShapes.size(), 1u);
  EXPECT_TRUE(loaded.layout.containerShapes[0].keepsPaint);  // on a container layer: drawn as styled
  EXPECT_NEAR(area(scene.container), 100 * 100 - 20 * 20, 1e-6);
  ASSERT_EQ(scene.container.size(), 1u);
  EXPECT_EQ(scene.container[0].holes.size(), 1u);
  EXPECT_EQ(scene.fixed.size(), 1u);
  EXPECT_EQ(loaded.layout.fixedShapes.size(), 1u);
  ASSERT_EQ(scene.guides.size(), 1u);
  EXPECT_EQ(scene.guides[0].size(), 2u);
  EXPECT_EQ(scene.spines.size(), 1u);
  EXPECT_DOUBLE_EQ(loaded.layout.viewBox.width(), 100.0);
}

TEST(SceneLoader, SeveralDisjointContainerShapes) {
  const Scene scene = sceneFromDocument(svgDocument(R"~(<g id="container">
      <rect x="0" y="0" width="10" height="10"/><rect x="50" y="50" width="20" height="10"/></g>)~")).scene;
  EXPECT_EQ(scene.container.size(), 2u);
  EXPECT_NEAR(area(scene.container), 300.0, 1e-6);
}

TEST(SceneLoader, AFileWithoutLayersIsAContainerByItself) {
  const LoadedScene loaded = sceneFromDocument(svgDocument(R"~(<circle id="icon" cx="50" cy="50" r="40"/>)~"));
  EXPECT_NEAR(area(loaded.scene.container), 3.14159265 * 1600, 3.14159265 * 1600 * 2e-3);
  ASSERT_EQ(loaded.layout.containerShapes.size(), 1u);
  EXPECT_EQ(loaded.layout.containerShapes[0].shape.id, "icon");
  EXPECT_FALSE(loaded.layout.containerShapes[0].keepsPaint);  // drawn as an outline
}

TEST(SceneLoader, PathFileContainerIsBoundaryMinusHoles) {
  SvgDocument document = readPathString(
      "1\n0 1 0 0 0 100 0 100 100 0 100\n0 1 7 10 10 30 10 30 30 10 30\n0 1 2 60 60 70 60 70 70\n", "holes.path");
  const Scene scene = sceneFromDocument(document).scene;
  EXPECT_NEAR(area(scene.container), 10000 - 400, 1e-6);
  EXPECT_EQ(scene.fixed.size(), 1u);
}

TEST(SceneLoaderErrors, UnclosedContainerPath) {
  const std::string message = errorOf([] {
    sceneFromDocument(
        svgDocument(R"~(<g id="container"><path id="outline" d="M0 0 L50 0 L50 50" fill="none" stroke="red"/></g>)~", "open.svg"));
  });
  EXPECT_NE(message.find("open.svg:1: container path 'outline' is not closed and not filled"), std::string::npos) << message;
}

// Tabler's icons start with an invisible bounding square: it is not the container.
TEST(SceneLoader, AShapeThatPaintsNothingIsNotPartOfAContainerFile) {
  const LoadedScene loaded = sceneFromDocument(svgDocument(
      R"~(<path stroke="none" d="M0 0h100v100H0z" fill="none"/><circle cx="50" cy="50" r="30" fill="none" stroke="#000" stroke-width="2"/>)~"));
  EXPECT_NEAR(area(loaded.scene.container), 3.14159265 * 900, 3.14159265 * 900 * 2e-3);
  ASSERT_EQ(loaded.layout.containerShapes.size(), 1u);
  ASSERT_EQ(loaded.warnings.size(), 1u);
  EXPECT_NE(loaded.warnings[0].message.find("paints nothing"), std::string::npos);
}

// Every editor and browser fills an open subpath as if closed, so a filled one encloses that.
TEST(SceneLoader, AFilledContainerPathWithoutZEnclosesWhatItFills) {
  const LoadedScene loaded = sceneFromDocument(svgDocument(
      R"~(<g id="container"><path d="M0 0 L100 0 L100 100 L0 100 Z M20 20 L80 20 L80 80 L20 80" fill="#ccc" fill-rule="evenodd"/></g>)~"));
  EXPECT_NEAR(area(loaded.scene.container), 10000 - 3600, 1e-6);
}

TEST(SceneLoaderErrors, BadContainerAttributesNameTheShapesLine) {
  const std::string message = errorOf([] {
    sceneFromDocument(svgDocument("<g id=\"container\">\n  <rect width=\"10\" height=\"10\" data-gap=\"dense\"/></g>"));
  });
  EXPECT_NE(message.find("scene.svg:2: data-gap=\"dense\" must be a positive number"), std::string::npos) << message;
}

TEST(SceneLoaderErrors, NoUsableContainer) {
  const std::string empty = errorOf([] { sceneFromDocument(svgDocument("", "empty.svg")); });
  EXPECT_NE(empty.find("empty.svg: no usable container"), std::string::npos) << empty;
  const std::string flat = errorOf([] {
    sceneFromDocument(svgDocument(R"~(<g id="container"><path d="M0 0 L10 0 L20 0 Z"/></g>)~", "flat.svg"));
  });
  EXPECT_NE(flat.find("flat.svg: no usable container"), std::string::npos) << flat;
  const std::string onlyGuides = errorOf([] {
    sceneFromDocument(svgDocument(R"~(<g id="guides"><path d="M0 0 L10 0"/></g>)~", "guides.svg"));
  });
  EXPECT_NE(onlyGuides.find("guides.svg: no usable container"), std::string::npos) << onlyGuides;
}

// ---- elements ----------------------------------------------------------------------------

TEST(ElementLoader, OutlineIsTheUnionOfEverythingPaintedWithHoles) {
  const LoadedElement loaded = elementFromDocument(svgDocument(R"~(
      <path d="M0 0 H10 V10 H0 Z M3 3 H7 V7 H3 Z" fill-rule="evenodd" fill="green"/>
      <path d="M20 0 L30 0" stroke="black" stroke-width="2" fill="none"/>
      <path id="spine" d="M0 5 L30 5" stroke="red"/>)~", "leaf.svg"));
  const ElementArt& element = loaded.element;
  EXPECT_EQ(element.name, "leaf");
  EXPECT_EQ(element.source, "leaf.svg");
  EXPECT_EQ(element.shapes.size(), 2u);  // the spine is not art
  ASSERT_EQ(loaded.shapes.size(), 2u);   // the same shapes with their SVG attributes
  EXPECT_EQ(loaded.shapes[0].tag, "path");
  ASSERT_TRUE(element.spine);
  EXPECT_EQ((*element.spine)[0], (Vec2{0, 5}));
  EXPECT_EQ((*element.spine)[1], (Vec2{30, 5}));
  // 84 for the holed square; the stroke band is 10 × 2 with butt caps (SVG's default).
  EXPECT_NEAR(area(element.outline), 84 + 20, 0.05);
  std::size_t holes = 0;
  for (const Polygon& polygon : element.outline) holes += polygon.holes.size();
  EXPECT_EQ(holes, 1u);
}

TEST(ElementLoader, WarnsAboutZeroAreaPathsAndOpenFills) {
  const LoadedElement element = elementFromDocument(svgDocument(R"~(
      <path id="body" d="M0 0 H10 V10 H0 Z"/>
      <path id="flat" d="M0 20 L10 20 L20 20 Z"/>
      <path id="open" d="M20 0 L30 0 L30 10"/>)~"));
  EXPECT_TRUE(hasWarning(element.warnings, "flat: path paints no area")) << element.warnings.size();
  EXPECT_TRUE(hasWarning(element.warnings, "open: open path used as a fill"));
  EXPECT_NEAR(area(element.element.outline), 100 + 50, 1e-3);
}

// A shape with neither fill nor stroke (the invisible frame of outline icon sets) is not art
// and no mistake: no warning.
TEST(ElementLoader, InvisibleShapesAreSkippedSilently) {
  const LoadedElement element = elementFromDocument(svgDocument(R"~(
      <path d="M0 0h24v24H0z" fill="none" stroke="none"/>
      <path d="M4 4 H10 V10 H4 Z"/>)~"));
  EXPECT_EQ(element.element.shapes.size(), 1u);
  EXPECT_TRUE(element.warnings.empty()) << element.warnings.front().message;
  EXPECT_NEAR(area(element.element.outline), 36.0, 1e-9);
}

TEST(ElementLoaderErrors, ZeroAreaElement) {
  const std::string message = errorOf([] {
    elementFromDocument(svgDocument(R"~(<path d="M0 0 L10 0 L20 0 Z"/><path d="M0 0 L10 10" fill="none"/>)~", "flat.svg"));
  });
  EXPECT_NE(message.find("flat.svg: the element paints no area"), std::string::npos) << message;
  const std::string empty = errorOf([] { elementFromDocument(svgDocument("", "nothing.svg")); });
  EXPECT_NE(empty.find("nothing.svg: the element has no shapes"), std::string::npos) << empty;
}

TEST(ElementLoader, TopLevelGroupsAreSeparateElements) {
  const std::vector<LoadedElement> library = elementsFromDocument(svgDocument(R"~(
      <g id="Leaf"><rect width="10" height="10" fill="green"/></g>
      <g id="fish"><circle cx="50" cy="50" r="5"/><circle cx="60" cy="50" r="2" fill="white"/></g>
      <g id="empty"><path d="M0 0 L1 0"/></g>)~", "library.svg"));
  ASSERT_EQ(library.size(), 2u);
  EXPECT_EQ(library[0].element.name, "leaf");
  EXPECT_EQ(library[0].element.shapes.size(), 1u);
  EXPECT_EQ(library[1].element.name, "fish");
  EXPECT_EQ(library[1].element.shapes.size(), 2u);
  // One group (an Inkscape layer around everything) is one element named after the file.
  const std::vector<LoadedElement> single =
      elementsFromDocument(svgDocument(R"~(<g id="layer1"><rect width="1" height="1"/></g>)~", "one.svg"));
  ASSERT_EQ(single.size(), 1u);
  EXPECT_EQ(single[0].element.name, "one");
}

TEST(ElementLoader, LibraryFromFilesAndFolders) {
  TempFolder folder;
  folder.write("b.svg", kSquare);
  folder.write("a.path", "1\n0 1 0 0 0 10 0 10 10\n");
  folder.write("notes.txt", "not an element");
  const std::string extra = folder.write("c.svg", kSquare);
  fs::create_directories(fs::path(folder.path()) / "sub");
  Library library = loadLibrary({folder.path()});
  ASSERT_EQ(library.size(), 3u);
  EXPECT_EQ(library[0].name, "a");
  EXPECT_EQ(library[1].name, "b");
  EXPECT_EQ(library[2].name, "c");
  EXPECT_NEAR(area(library[1].outline), 20.0, 1e-9);
  Library files = loadLibrary({extra});
  EXPECT_EQ(files.size(), 1u);
}

TEST(ElementLoaderErrors, LibraryWithNothingInIt) {
  TempFolder folder;
  folder.write("readme.txt", "nothing here");
  const std::string none = errorOf([&] { loadLibrary({folder.path()}); });
  EXPECT_NE(none.find(folder.path()), std::string::npos) << none;
  EXPECT_NE(none.find("no element files found"), std::string::npos) << none;
  const std::string missing = errorOf([] { loadLibrary({"/no/such/elements"}); });
  EXPECT_NE(missing.find("/no/such/elements: no such file or folder"), std::string::npos) << missing;
}

TEST(SceneLoaderErrors, ReadDocumentByExtension) {
  TempFolder folder;
  const std::string text = folder.write("drawing.txt", "hello");
  EXPECT_NE(errorOf([&] { readDocument(text); }).find("unknown file type '.txt'"), std::string::npos);
  EXPECT_NE(errorOf([] { readDocument("/no/such/file.svg"); }).find("/no/such/file.svg: cannot open"),
            std::string::npos);
  const std::string upper = folder.write("SQUARE.SVG", kSquare);
  EXPECT_EQ(readDocument(upper).shapes.size(), 1u);
}

TEST(SceneLoaderErrors, SvgWithNoUsableShapeAsContainerAndAsElement) {
  TempFolder folder;
  const std::string file = folder.write("blank.svg", R"~(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10">
      <text x="1" y="1">only words</text></svg>)~");
  const std::string asScene = errorOf([&] { loadScene(file); });
  EXPECT_NE(asScene.find(file + ": no usable container"), std::string::npos) << asScene;
  const std::string asElement = errorOf([&] { loadLibrary({file}); });
  EXPECT_NE(asElement.find(file + ": the element has no shapes"), std::string::npos) << asElement;
}

// ---- drawing -----------------------------------------------------------------------------

TEST(DrawingFromDocument, OneGroupPerLayerInOrder) {
  Drawing drawing = drawingFromDocument(svgDocument(R"~(
      <rect id="loose" width="1" height="1"/>
      <g id="container"><rect id="c1" width="1" height="1"/><rect id="c2" width="1" height="1"/></g>
      <g id="fixed"><rect id="f" width="1" height="1"/></g>)~"));
  EXPECT_DOUBLE_EQ(drawing.viewBox.width(), 100.0);
  ASSERT_EQ(drawing.groups.size(), 3u);
  EXPECT_EQ(drawing.groups[0].id, "");
  EXPECT_EQ(drawing.groups[1].id, "container");
  ASSERT_EQ(drawing.groups[1].shapes.size(), 2u);
  EXPECT_EQ(drawing.groups[1].shapes[0].id, "c1");
  EXPECT_EQ(drawing.groups[1].shapes[1].id, "c2");
  EXPECT_EQ(drawing.groups[2].id, "fixed");
}

// Shapes are drawn in document order even when a layer comes back after other shapes (a
// group with an id copied by a <use> further on, as flag-icons' gi.svg does): the black
// behind comes before the red in front. The name stays on the layer's first run.
TEST(DrawingFromDocument, LayersThatComeBackKeepTheDocumentOrder) {
  Drawing drawing = drawingFromDocument(svgDocument(R"~(
      <g id="tower"><rect id="behind" width="10" height="10" fill="#000"/></g>
      <rect id="front" width="5" height="5" fill="#f00"/>
      <use href="#tower" x="20"/>)~"));
  ASSERT_EQ(drawing.groups.size(), 3u);
  EXPECT_EQ(drawing.groups[0].id, "tower");
  EXPECT_EQ(drawing.groups[0].shapes[0].id, "behind");
  EXPECT_EQ(drawing.groups[1].id, "");
  EXPECT_EQ(drawing.groups[1].shapes[0].id, "front");
  EXPECT_EQ(drawing.groups[2].id, "");
  EXPECT_EQ(drawing.groups[2].shapes[0].id, "behind");
}

}  // namespace
}  // namespace pak
