// A packing Pak has just made, as the metrics see it: what the report of `pak pack` measures.
#include <gtest/gtest.h>

#include "metrics_fixtures.hpp"
#include "pak/metrics/evenness.hpp"
#include "pak/metrics/packing_geometry.hpp"
#include "pak/repulsion/repulsion.hpp"

namespace pak {
namespace {

Shape filledSquare(double x, double y, double side) {
  Shape s;
  s.subpaths.push_back({{{x, y}, {x + side, y}, {x + side, y + side}, {x, y + side}}, true});
  s.fill = Color{200, 40, 40};
  return s;
}

TEST(PackingGeometry, ElementArtAndFixedArtOfAPacking) {
  Packing packing;
  packing.container = test::rect(0, 0, 100, 100);
  PlacedElement element;
  element.art = {filledSquare(10, 10, 20), filledSquare(25, 10, 20)};  // overlapping shapes: one outline
  packing.elements.push_back(element);
  packing.fixedArt = test::rect(60, 60, 90, 90);
  const PackingGeometry geometry = packingGeometry(packing, "made.svg");
  EXPECT_EQ(geometry.source, "made.svg");
  ASSERT_EQ(geometry.elements.size(), 1u);
  EXPECT_NEAR(area(geometry.elements[0]), 35.0 * 20.0, 1e-6);
  EXPECT_NEAR(area(geometry.fixed), 900.0, 1e-9);
  EXPECT_NEAR(area(geometry.container), 1e4, 1e-9);
  EvennessOptions options;
  options.resolution = 100;  // cells of 1 × 1 on the squares' edges: exact counts
  const Evenness e = measureEvenness(geometry, options);
  EXPECT_EQ(e.negativeCells, 10000 - 700 - 900);
}

}  // namespace
}  // namespace pak
