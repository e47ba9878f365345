#include "pak/geom/art.hpp"

#include <gtest/gtest.h>

#include <numbers>

using namespace pak;

namespace {

std::vector<Vec2> square(double x0, double y0, double side) {
  return {{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}};
}

Shape filledShape(std::vector<Subpath> subpaths, FillRule rule) {
  Shape s;
  s.subpaths = std::move(subpaths);
  s.fill = Color{255, 0, 0, 1.0};
  s.fillRule = rule;
  return s;
}

}  // namespace

TEST(Art, FillRuleDecidesHoles) {
  std::vector<Subpath> nested{{square(0, 0, 10), true}, {square(2, 2, 4), true}};
  EXPECT_NEAR(area(filledRegion(filledShape(nested, FillRule::EvenOdd))), 84.0, 1e-9);
  EXPECT_NEAR(area(filledRegion(filledShape(nested, FillRule::NonZero))), 100.0, 1e-9);
}

TEST(Art, OpenSubpathIsFilledAsIfClosed) {
  Shape s = filledShape({{{{0, 0}, {4, 0}, {4, 3}}, false}}, FillRule::NonZero);
  EXPECT_NEAR(area(filledRegion(s)), 6.0, 1e-9);
  // Too few points to enclose anything.
  EXPECT_TRUE(filledRegion(filledShape({{{{0, 0}, {4, 0}}, false}}, FillRule::NonZero)).empty());
}

TEST(Art, FilledRegionIsGeometryEvenWithoutFillPaint) {
  Shape s = filledShape({{square(0, 0, 2), true}}, FillRule::NonZero);
  s.fill.reset();
  EXPECT_NEAR(area(filledRegion(s)), 4.0, 1e-9);
  EXPECT_TRUE(paintedRegion(s).empty());  // neither fill nor stroke paint
}

TEST(Art, PaintedRegionAddsTheStrokeBand) {
  const double s = 10.0, w = 2.0, d = w / 2;
  Shape shape = filledShape({{square(0, 0, s), true}}, FillRule::NonZero);
  shape.stroke = Color{0, 0, 0, 1.0};
  shape.strokeWidth = w;
  const double exact = s * s + 4 * s * d + std::numbers::pi * d * d;
  const double painted = area(paintedRegion(shape));
  EXPECT_NEAR(painted, exact, 0.05);
  EXPECT_LT(painted, exact + 1e-6);
  // Stroke only: an annulus around the ring.
  shape.fill.reset();
  Region ring = paintedRegion(shape);
  ASSERT_EQ(ring.size(), 1u);
  EXPECT_EQ(ring[0].holes.size(), 1u);
  EXPECT_NEAR(area(ring), exact - (s - 2 * d) * (s - 2 * d), 0.05);
}

TEST(Art, OpenStrokeIsABandNotARing) {
  Shape line;
  line.subpaths = {{{{0, 0}, {10, 0}}, false}};
  line.stroke = Color{};
  line.strokeWidth = 2.0;
  Region band = paintedRegion(line);
  ASSERT_EQ(band.size(), 1u);
  EXPECT_TRUE(band[0].holes.empty());
  EXPECT_NEAR(area(band), 20.0 + std::numbers::pi, 0.05);
  // An open L-shaped stroke is not closed back to its start: two 2x10 bands sharing a 1x1
  // square at the inner corner, a quarter disc at the outer corner and two half-disc caps.
  line.subpaths = {{{{0, 0}, {10, 0}, {10, 10}}, false}};
  EXPECT_NEAR(area(paintedRegion(line)), 39.0 + 1.25 * std::numbers::pi, 0.1);
  line.strokeWidth = 0.0;
  EXPECT_TRUE(paintedRegion(line).empty());
}

TEST(Art, Bounds) {
  Shape shape = filledShape({{square(1, 2, 3), true}, {{{-1, 0}, {0, 0}}, false}}, FillRule::NonZero);
  Box b = bounds(shape);
  EXPECT_EQ(b.min, (Vec2{-1, 0}));
  EXPECT_EQ(b.max, (Vec2{4, 5}));
  shape.stroke = Color{};
  shape.strokeWidth = 2.0;
  b = bounds(shape);
  EXPECT_EQ(b.min, (Vec2{-2, -1}));
  EXPECT_EQ(b.max, (Vec2{5, 6}));
  Shape other = filledShape({{square(10, 10, 1), true}}, FillRule::NonZero);
  Box all = bounds(std::vector<Shape>{shape, other});
  EXPECT_EQ(all.max, (Vec2{11, 11}));
  EXPECT_TRUE(bounds(Shape{}).empty());
}
