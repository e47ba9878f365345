// Top-level groups that are layers of one drawing make one element; a library's groups, laid
// out apart, stay separate elements. (An OpenMoji-like emoji: tests/svg/layered-emoji.svg in
// svg_corpus_test.)
#include "io/drawing_layers.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "pak/io/scene_loader.hpp"

namespace pak {
namespace {

using Drawings = std::vector<std::vector<int>>;

SvgDocument svgDocument(const std::string& body, const std::string& name = "file.svg") {
  return readSvgString(R"~(<svg xmlns="http://www.w3.org/2000/svg" )~"
                       R"~(xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape" viewBox="0 0 100 100">)~" +
                           body + "</svg>",
                       name);
}

// A library file: three elements side by side, with space between them.
TEST(DrawingLayers, GroupsApartAreSeparateElements) {
  const SvgDocument library = svgDocument(R"~(
      <g id="leaf"><rect width="20" height="20"/></g>
      <g id="fish"><circle cx="45" cy="10" r="10"/></g>
      <g id="moon"><circle cx="80" cy="10" r="10" fill="none" stroke="#000" stroke-width="4"/></g>)~");
  EXPECT_EQ(drawingsOfGroups(library), (Drawings{{0}, {1}, {2}}));
  const std::vector<LoadedElement> elements = elementsFromDocument(library);
  ASSERT_EQ(elements.size(), 3u);
  EXPECT_EQ(elements[0].element.name, "leaf");
  EXPECT_EQ(elements[1].element.name, "fish");
  EXPECT_EQ(elements[2].element.name, "moon");
}

// Boxes that touch are layers too (a flag's stripes abut, stripes placed by <use> to the last
// bits); groups overlapping through a third are one drawing; space between boxes keeps groups
// apart.
TEST(DrawingLayers, TouchingBoxesAreLayersSpaceKeepsGroupsApart) {
  EXPECT_EQ(drawingsOfGroups(svgDocument(R"~(
      <g><rect width="20" height="20"/></g>
      <g><rect x="20" width="20" height="20"/></g>
      <g><rect x="40.5" width="20" height="20"/></g>)~")),
            (Drawings{{0, 1}, {2}}));
  EXPECT_EQ(drawingsOfGroups(svgDocument(R"~(
      <defs><rect id="stripe" width="100" height="21.6"/></defs>
      <rect y="153.6" width="100" height="20" fill="#000"/>
      <use href="#stripe" transform="translate(0 -194.4)" y="326.4" fill="#fff"/>
      <g><rect width="100" height="10" fill="#00f"/></g>)~")),
            (Drawings{{-1, 0}, {1}}));
  EXPECT_EQ(drawingsOfGroups(svgDocument(R"~(
      <g><rect width="20" height="20"/></g>
      <g><rect x="60" width="20" height="20"/></g>
      <g><rect x="10" y="5" width="60" height="2"/></g>)~")),
            (Drawings{{0, 1, 2}}));
  // A small detail inside a big group's box is a layer of it.
  EXPECT_EQ(drawingsOfGroups(svgDocument(R"~(
      <g><rect width="50" height="50" fill="none" stroke="#000"/></g>
      <g><rect x="20" y="20" width="2" height="2"/></g>
      <g><rect x="70" width="20" height="20"/></g>)~")),
            (Drawings{{0, 1}, {2}}));
}

// What paints nothing has no box: the invisible frame of outline icons does not tie groups.
TEST(DrawingLayers, UnpaintedShapesDoNotOverlap) {
  EXPECT_EQ(drawingsOfGroups(svgDocument(R"~(
      <g><rect width="100" height="100" fill="none"/><rect width="20" height="20"/></g>
      <g><rect x="60" width="20" height="20"/></g>)~")),
            (Drawings{{0}, {1}}));
}

// Inkscape layers are layers of one drawing, wherever they lie; shapes outside every group
// and a group that paints nothing (a spine) go with the one drawing.
TEST(DrawingLayers, InkscapeLayersAreOneDrawing) {
  const SvgDocument layered = svgDocument(R"~(
      <path id="spine" d="M0 50 L100 50" fill="none"/>
      <g inkscape:groupmode="layer" inkscape:label="body"><rect width="20" height="20"/></g>
      <g inkscape:groupmode="layer" inkscape:label="tail"><rect x="60" width="20" height="20"/></g>)~",
                                          "kite.svg");
  EXPECT_EQ(layered.inkscapeLayers, (std::vector<bool>{true, true}));
  EXPECT_EQ(drawingsOfGroups(layered), (Drawings{{-1, 0, 1}}));
  const std::vector<LoadedElement> elements = elementsFromDocument(layered);
  ASSERT_EQ(elements.size(), 1u);
  EXPECT_EQ(elements[0].element.name, "kite");
  ASSERT_TRUE(elements[0].element.spine.has_value());
  EXPECT_NEAR(area(elements[0].element.outline), 800.0, 1e-6);
  // A plain group beside the layers is not one of them.
  EXPECT_EQ(drawingsOfGroups(svgDocument(R"~(
      <g inkscape:groupmode="layer"><rect width="20" height="20"/></g>
      <g inkscape:groupmode="layer"><rect x="60" width="20" height="20"/></g>
      <g><rect x="30" y="60" width="20" height="20"/></g>)~")),
            (Drawings{{0, 1}, {2}}));
}

}  // namespace
}  // namespace pak
