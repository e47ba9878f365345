// Reading packings for the metrics: Pak's layout, named layers, and the largest-shape fallback.
#include "pak/io/packing_reader.hpp"

#include <gtest/gtest.h>

#include <string>

#include "pak/error.hpp"
#include "pak/io/svg_reader.hpp"

namespace {

using pak::InputError;
using pak::PackingGeometry;
using pak::PackingReadOptions;

PackingGeometry read(const std::string& body, const PackingReadOptions& options = {}) {
  std::string svg = "<svg xmlns='http://www.w3.org/2000/svg' viewBox='0 0 100 100' width='100' height='100'>" + body +
                    "</svg>";
  return pak::packingFromDocument(pak::readSvgString(svg, "test.svg"), options);
}

// Pak's output: one element per <g class="element">, however many shapes it paints; a shape
// directly in the layer is an element by itself.
const std::string kPakLayout =
    "<g id='container'><rect x='0' y='0' width='100' height='100' fill='#eee'/></g>"
    "<g id='elements'>"
    "  <g class='element'><rect x='10' y='10' width='10' height='10'/><rect x='15' y='10' width='10' height='10'/></g>"
    "  <g class='element'><rect x='50' y='50' width='20' height='10'/></g>"
    "  <rect x='80' y='80' width='5' height='5'/>"
    "</g>";

TEST(PackingReader, PakLayoutGivesOneOutlinePerElementGroup) {
  PackingGeometry packing = read(kPakLayout);
  EXPECT_EQ(packing.source, "test.svg");
  EXPECT_NEAR(pak::area(packing.container), 10000.0, 1e-6);
  ASSERT_EQ(packing.elements.size(), 3u);
  EXPECT_NEAR(pak::area(packing.elements[0]), 150.0, 1e-6);  // two overlapping squares, united
  EXPECT_NEAR(pak::area(packing.elements[1]), 200.0, 1e-6);
  EXPECT_NEAR(pak::area(packing.elements[2]), 25.0, 1e-6);
}

// Pak writes fixed elements in a `fixed` layer: their paint is the fixed art, not elements.
TEST(PackingReader, FixedLayerIsFixedArt) {
  const std::string fixedLayer =
      "<g id='fixed'><rect x='30' y='30' width='10' height='10'/><rect x='60' y='10' width='5' height='4'/></g>";
  PackingGeometry packing = read(kPakLayout + fixedLayer);
  EXPECT_EQ(packing.elements.size(), 3u);
  EXPECT_NEAR(pak::area(packing.fixed), 120.0, 1e-6);
  PackingReadOptions named;
  named.fixedLayer = "Obstacles";
  PackingGeometry renamed = read(kPakLayout + "<g id='obstacles'><rect x='30' y='30' width='10' height='10'/></g>", named);
  EXPECT_NEAR(pak::area(renamed.fixed), 100.0, 1e-6);
  EXPECT_TRUE(read(kPakLayout).fixed.empty());
}

TEST(PackingReader, StrokesCountAsPaintedArt) {
  PackingGeometry packing = read(
      "<g id='container'><rect width='100' height='100' fill='none' stroke='black'/></g>"
      "<g id='elements'><g class='element'><rect x='10' y='10' width='10' height='10' fill='red' stroke='black' "
      "stroke-width='2'/></g></g>");
  ASSERT_EQ(packing.elements.size(), 1u);
  EXPECT_NEAR(pak::area(packing.elements[0]), 144.0, 0.05);  // 12²: 10² + stroke, miter joins (SVG's default)
  EXPECT_NEAR(pak::area(packing.container), 10000.0, 1e-6);  // the container's own stroke is not area
}

TEST(PackingReader, OtherLayerNamesByOption) {
  const std::string body =
      "<g id='Frame'><rect width='100' height='50'/></g>"
      "<g id='Tiles'><g><rect x='1' y='1' width='4' height='4'/></g><g><rect x='10' y='1' width='3' height='3'/></g></g>";
  PackingGeometry packing = read(body, PackingReadOptions{"Frame", "Tiles"});
  EXPECT_NEAR(pak::area(packing.container), 5000.0, 1e-6);
  ASSERT_EQ(packing.elements.size(), 2u);
  EXPECT_NEAR(pak::area(packing.elements[0]), 16.0, 1e-6);
  EXPECT_NEAR(pak::area(packing.elements[1]), 9.0, 1e-6);
}

TEST(PackingReader, FallbackLargestClosedShapeIsTheContainer) {
  PackingGeometry packing = read(
      "<circle cx='50' cy='50' r='5'/>"
      "<rect x='0' y='0' width='100' height='100' fill='none' stroke='black'/>"
      "<g><rect x='10' y='10' width='10' height='10'/><rect x='30' y='10' width='10' height='10'/></g>"
      "<rect x='60' y='60' width='10' height='20'/>");
  EXPECT_NEAR(pak::area(packing.container), 10000.0, 1e-6);
  ASSERT_EQ(packing.elements.size(), 3u);  // the circle, the group, the loose rect
  double total = 0.0;
  for (const pak::Region& element : packing.elements) total += pak::area(element);
  EXPECT_NEAR(total, 200.0 + 200.0 + 3.14159 * 25.0, 0.5);
}

TEST(PackingReader, FallbackInsideAnEditorsWrapperLayer) {
  PackingGeometry packing = read(
      "<g id='Layer_1'>"
      "  <rect width='100' height='100' fill='none' stroke='black'/>"
      "  <g><rect x='10' y='10' width='10' height='10'/><rect x='12' y='30' width='2' height='2'/></g>"
      "  <g><rect x='50' y='50' width='10' height='10'/></g>"
      "</g>");
  EXPECT_NEAR(pak::area(packing.container), 10000.0, 1e-6);
  ASSERT_EQ(packing.elements.size(), 2u);
  EXPECT_NEAR(pak::area(packing.elements[0]), 104.0, 1e-6);
  EXPECT_NEAR(pak::area(packing.elements[1]), 100.0, 1e-6);
}

TEST(PackingReader, BadPackingsAreClearErrors) {
  auto message = [](const std::string& body) {
    try {
      read(body);
    } catch (const InputError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("<g id='container'><rect width='100' height='100'/></g>").find("no elements"), std::string::npos);
  EXPECT_NE(message("<g id='container'><rect width='100' height='100'/></g><g id='elements'></g>").find("no elements"),
            std::string::npos);
  EXPECT_NE(message("<path d='M0 0 L 50 50' stroke='black'/>").find("no container"), std::string::npos);
  EXPECT_NE(message("<g id='container'><rect width='50' height='50'/></g>"
                    "<g id='elements'><g><rect x='70' y='70' width='5' height='5'/></g></g>")
                .find("outside the container"),
            std::string::npos);
}

}  // namespace
