// Hairline cusps (pak/geom/hairline_cusps.hpp): found, and redrawn without them.
#include "pak/geom/hairline_cusps.hpp"

#include <gtest/gtest.h>

#include "pak/geom/verify.hpp"

namespace pak {
namespace {

Ring square(double side) { return {{0, 0}, {side, 0}, {side, side}, {0, side}}; }

// A 10 × 10 square with a slit 0.02 wide cut from its top edge down to its middle.
Ring slitSquare() {
  return {{0, 0}, {10, 0}, {10, 10}, {5.01, 10}, {5.01, 5}, {4.99, 5}, {4.99, 10}, {0, 10}};
}

Shape filled(const Ring& ring) {
  Shape s;
  s.subpaths.push_back({ring, true});
  s.fill = Color{0, 0, 0};
  return s;
}

TEST(HairlineCusps, ASlitIsAHairlineAndASquareIsNot) {
  EXPECT_TRUE(ringHasHairline(slitSquare(), 0.2));
  EXPECT_FALSE(ringHasHairline(slitSquare(), 0.01));  // wider than asked for
  EXPECT_FALSE(ringHasHairline(square(10), 0.2));
  // A sharp corner (neighbouring edges) is not a hairline, however sharp.
  EXPECT_FALSE(ringHasHairline({{0, 0}, {10, 0}, {0, 0.01}}, 0.2));
}

TEST(HairlineCusps, TheSlitIsFilledAndNothingElseMoves) {
  std::vector<Shape> art{filled(slitSquare()), filled(square(4))};
  EXPECT_EQ(removeHairlineCusps(art, 0.2), 1);
  ASSERT_EQ(art[0].subpaths.size(), 1u);
  for (const Subpath& s : art[0].subpaths) {
    EXPECT_FALSE(ringHasHairline(s.points, 0.2));
    EXPECT_FALSE(ringSelfIntersects(s.points));
    // The art bends with its mesh at its points only: no edge longer than the drawn ones.
    for (std::size_t k = 0; k < s.points.size(); ++k)
      EXPECT_LE(distance(s.points[k], s.points[(k + 1) % s.points.size()]), 10.0 + 1e-9);
  }
  // The slit closed: the square's full area but for its corners, rounded by a tenth of a unit.
  EXPECT_NEAR(area(filledRegion(art[0])), 100.0, 0.1);
  EXPECT_EQ(art[1].subpaths.front().points, square(4));  // clean: left as drawn
}

TEST(HairlineCusps, RingsDrawnCrossingThemselvesAreLeftAsDrawn) {
  const Ring figureEight{{0, 0}, {10, 10}, {10, 0}, {0, 10}};
  std::vector<Shape> art{filled(figureEight)};
  EXPECT_EQ(removeHairlineCusps(art, 0.2), 0);
  EXPECT_EQ(art[0].subpaths.front().points, figureEight);
}

TEST(HairlineCusps, StrokedShapesAreLeftAsDrawn) {
  std::vector<Shape> art{filled(slitSquare())};
  art[0].stroke = Color{255, 0, 0};
  EXPECT_EQ(removeHairlineCusps(art, 0.2), 0);
  EXPECT_EQ(art[0].subpaths.front().points, slitSquare());
}

}  // namespace
}  // namespace pak
