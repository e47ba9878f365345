// The evenness measure against closed forms. Grid values carry two raster errors, each stated
// where it is used: a cell's D is within half a cell of the true distance, and so is h (the
// medial axis is located between cell centres, its radius from the two nearest boundary cells).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "metrics_fixtures.hpp"
#include "pak/error.hpp"
#include "pak/metrics/evenness.hpp"

namespace pak {
namespace {

constexpr double kPi = std::numbers::pi;

EvennessOptions atResolution(int resolution) {
  EvennessOptions options;
  options.resolution = resolution;
  return options;
}

// Stripes: channels of width g bounded by straight walls on both sides. Every channel's axis
// is its midline with radius g/2, nothing is deeper than that, so P2 = P3 = 0.
TEST(Evenness, StripesHaveHalfTheGapAndNoPockets) {
  const double b = 27.0, g = 23.0;  // period 50; 20 periods make a 1000 × 1000 container
  const PackingGeometry p = test::stripes(1000.0, 20, b, g);
  const Evenness e = measureEvenness(p, atResolution(500));  // cell 2: g = 11.5 cells
  ASSERT_DOUBLE_EQ(e.cell, 2.0);
  // Each channel's h is within half a cell of g/2, so the median is too.
  EXPECT_NEAR(e.halfWidth, g / 2, 0.5 * e.cell);
  EXPECT_DOUBLE_EQ(e.pocketShare[1], 0.0);
  EXPECT_DOUBLE_EQ(e.pocketShare[2], 0.0);
  // D > h only where a channel's own h exceeds the median: at most the two rows beside its
  // midline, 2 of its g / cell rows.
  EXPECT_LE(e.pocketShare[0], 2.0 * e.cell / g);
  EXPECT_NEAR(e.largestRadiusOverHalfWidth, 1.0, e.cell / e.halfWidth);
  EXPECT_LE(e.widthSpread, e.cell / e.halfWidth);  // channel widths differ by < 1 cell
  // Every gap is g/(g+b) of its period, each to within a row of cells (cell / period).
  EXPECT_NEAR(e.negativeRatio, g / (g + b), e.cell / (g + b));
  EXPECT_EQ(e.filledHoleCells, 0);
  // The axis is the 20 midlines across the square, less about g/2 at each end (the channel's
  // right-angle corners have no branches).
  EXPECT_NEAR(e.axisLength, 20 * (1000.0 - g), 20 * 2.0 * e.cell);
}

// n × n squares of side s with gap g between them and to the walls: every channel has
// half-width g/2, so h = g/2. D exceeds g/2 only in the junctions: in a crossing's g × g
// square minus the quarter discs of radius g/2 around its four corners, (1 - π/4) g²; a
// wall junction holds half of that and a container corner a quarter, so with (n-1)²
// crossings, 4(n-1) wall junctions and 4 corners the set D > h has area (1 - π/4) g² n².
// The deepest point, a crossing's centre, is g/√2 from the corners: D_max / h = √2.
TEST(Evenness, SquareGridOfSquares) {
  const int n = 3;
  const double s = 200.0, g = 100.0, side = n * s + (n + 1) * g;  // 1000
  PackingGeometry p;
  p.source = "squares";
  p.container = test::rect(0, 0, side, side);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = g + i * (s + g), y = g + j * (s + g);
      p.elements.push_back(test::rect(x, y, x + s, y + s));
    }
  const Evenness e = measureEvenness(p, atResolution(997));  // cells not aligned to the squares
  const double negative = side * side - n * n * s * s;
  const double p1 = (1.0 - kPi / 4.0) * g * g * n * n / negative;
  EXPECT_NEAR(e.negativeRatio, negative / (side * side), 4.0 * (n + 1) * e.cell / side);
  EXPECT_NEAR(e.halfWidth, g / 2, 0.5 * e.cell);
  // D and h each within half a cell: the set D > h moves by up to a cell along its
  // boundary, the n² circles of radius g/2: n² π g × cell over the negative area.
  EXPECT_NEAR(e.pocketShare[0], p1, n * n * kPi * g * e.cell / negative);
  EXPECT_DOUBLE_EQ(e.pocketShare[1], 0.0);
  EXPECT_DOUBLE_EQ(e.pocketShare[2], 0.0);
  EXPECT_NEAR(e.largestRadiusOverHalfWidth, std::sqrt(2.0), 2.0 * e.cell / e.halfWidth);
  // Over 80% of the axis is straight channel at exactly g/2 (the junctions are wider), so
  // the quartiles differ only by the channels' raster offsets, under a cell.
  EXPECT_LE(e.widthSpread, e.cell / e.halfWidth);
}

// Thin channels (stripes of width g) and one round pocket of radius R, a hole in a thicker
// band. The channels carry the axis, so h = g/2; the pocket's D is R - |x - centre|, so
// {D > k h} is a disc of radius R - k g/2 and P_k = π (R - k g/2)² / |negative space|, and
// D_max / h = 2R / g. The channels' cells are aligned here (no D > h in them).
TEST(Evenness, RoundPocketAmongThinChannels) {
  const double side = 1000.0, b = 30.0, g = 10.0, thick = 150.0, radius = 60.0;
  PackingGeometry p;
  p.container = test::rect(0, 0, side, side);
  double channels = 0.0;
  Vec2 centre;
  bool pocketPlaced = false;
  for (double y = -b / 2; y < side;) {
    const bool pocket = !pocketPlaced && y > side / 2 - thick;
    const double top = y + (pocket ? thick : b);
    Region band = test::rect(-1, y, side + 1, top);
    if (pocket) {
      centre = {side / 2 + 0.3, (y + top) / 2};
      Ring hole = test::disc(centre, radius).front().outer;
      band.front().holes.push_back(Ring(hole.rbegin(), hole.rend()));
      pocketPlaced = true;
    }
    p.elements.push_back(band);
    channels += std::max(0.0, std::min(top + g, side) - std::max(top, 0.0)) * side;
    y = top + g;
  }
  ASSERT_TRUE(pocketPlaced);
  const double pocketArea = area(test::disc(centre, radius));
  const double negative = channels + pocketArea;
  const Evenness e = measureEvenness(p);  // cell 1
  EXPECT_NEAR(e.negativeRatio, negative / (side * side), 1e-3);
  EXPECT_NEAR(e.halfWidth, g / 2, 1e-9);  // channel walls on cell edges: exact
  for (int k = 1; k <= 3; ++k) {
    const double r = radius - k * g / 2;
    const double expected = kPi * r * r / negative;
    // A disc whose edge moves by half a cell: relative area error 1 / r.
    EXPECT_NEAR(e.pocketShare[k - 1], expected, expected / r) << "P" << k;
  }
  // The deepest cell is up to √2/2 cell from the centre, and the boundary's nearest occupied
  // centres lie on the circle rather than half a cell beyond it: D_max within 1.5 cells.
  EXPECT_NEAR(e.largestRadiusOverHalfWidth, 2 * radius / g, 1.5 / (g / 2));
  EXPECT_LE(e.widthSpread, 1e-9);
}

// A packing of unlike discs, some with eyes and some missing (pockets), in a polygon: every
// figure is a ratio of grid lengths, so scaling and moving the whole packing changes only the
// lengths, by the scale.
PackingGeometry irregularPacking(double scale, Vec2 shift) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto place = [&](Vec2 v) { return v * scale + shift; };
  PackingGeometry p;
  Ring outline;
  for (int k = 0; k < 9; ++k) {
    const double t = 2.0 * kPi * k / 9, r = 500.0 * (0.9 + 0.1 * std::cos(3.0 * t));
    outline.push_back(place(Vec2{500, 500} + Vec2{std::cos(t), std::sin(t)} * r));
  }
  p.container = {Polygon{outline, {}}};
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) {
      const Vec2 c{50.0 + 100.0 * i + 10.0 * (unit(random) - 0.5), 50.0 + 100.0 * j + 10.0 * (unit(random) - 0.5)};
      const double r = 15.0 + 30.0 * unit(random);
      if (unit(random) < 0.12 || !pointInRegion(place(c), p.container)) continue;
      Region disc = test::disc(place(c), r * scale, 64);
      if ((i + j) % 3 == 0) {  // an eye
        Ring eye = test::disc(place(c + Vec2{r / 3, 0}), r * scale / 4, 32).front().outer;
        disc.front().holes.push_back(Ring(eye.rbegin(), eye.rend()));
      }
      p.elements.push_back(disc);
    }
  return p;
}

TEST(Evenness, InvariantUnderScalingTheWholePacking) {
  const double scale = 3.7;
  const Evenness a = measureEvenness(irregularPacking(1.0, {0, 0}));
  const Evenness b = measureEvenness(irregularPacking(scale, {123.4, -56.7}));
  ASSERT_GT(a.halfWidth, 0.0);
  ASSERT_GT(a.pocketShare[1], 0.01);
  ASSERT_GT(a.filledHoleCells, 0);
  // The same cells in exact arithmetic; rounding may move a cell centre lying on an edge.
  EXPECT_NEAR(b.negativeRatio, a.negativeRatio, 1e-5);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(b.pocketShare[k], a.pocketShare[k], 1e-4) << "P" << k + 1;
  EXPECT_NEAR(b.halfWidth / scale, a.halfWidth, 1e-6 * a.halfWidth);
  EXPECT_NEAR(b.largestEmptyRadius / scale, a.largestEmptyRadius, 1e-6 * a.largestEmptyRadius);
  EXPECT_NEAR(b.largestRadiusOverHalfWidth, a.largestRadiusOverHalfWidth, 1e-6);
  EXPECT_NEAR(b.widthSpread, a.widthSpread, 1e-6);
  EXPECT_NEAR(b.axisLength / scale, a.axisLength, 1e-4 * a.axisLength);
}

// The same packing on a finer grid measures about the same: the figures are properties of the
// geometry, not of the grid.
TEST(Evenness, ConvergesWithResolution) {
  const PackingGeometry p = irregularPacking(1.0, {0, 0});
  const Evenness coarse = measureEvenness(p, atResolution(1000));
  const Evenness fine = measureEvenness(p, atResolution(2000));
  EXPECT_NEAR(fine.halfWidth, coarse.halfWidth, coarse.cell);
  EXPECT_NEAR(fine.pocketShare[1], coarse.pocketShare[1], 0.1 * coarse.pocketShare[1]);
  EXPECT_NEAR(fine.negativeRatio, coarse.negativeRatio, 0.005);
}

// Holes of the positive space under 400 cells of a 1000² grid (4e-4 of the square) are
// filled: an eye of 15 × 15 cells is positive, one of 25 × 25 stays negative space, and so does
// a 10 × 10 notch that opens onto the wall (not a hole of the art). Fixed art is positive
// space like element art. Every edge lies on a cell edge, so the counts are exact.
TEST(Evenness, SmallHolesAreFilledLargeOnesAndNotchesAtTheWallAreNot) {
  const double side = 1000.0;
  auto squareWithHole = [](double x0, double y0, double size, double hx, double hy, double hole) {
    Region r = test::rect(x0, y0, x0 + size, y0 + size);
    r.front().holes.push_back({{hx, hy}, {hx, hy + hole}, {hx + hole, hy + hole}, {hx + hole, hy}});
    return r;
  };
  PackingGeometry p;
  p.container = test::rect(0, 0, side, side);
  p.elements.push_back(squareWithHole(100, 100, 200, 190, 190, 15));  // 225-cell eye
  p.elements.push_back(squareWithHole(500, 500, 200, 580, 580, 25));  // 625-cell hole
  // Against the right wall, with a notch at the wall: [990, 1000] × [495, 505].
  p.elements.push_back({Polygon{{{880, 400}, {1000, 400}, {1000, 495}, {990, 495}, {990, 505}, {1000, 505}, {1000, 600}, {880, 600}}, {}}});
  const Evenness e = measureEvenness(p);
  EXPECT_EQ(e.containerCells, 1000000);
  EXPECT_EQ(e.filledHoleCells, 225);
  const long long negative = 1000000 - 200 * 200 - (200 * 200 - 625) - (120 * 200 - 100);
  EXPECT_EQ(e.negativeCells, negative);
  EXPECT_DOUBLE_EQ(e.negativeRatio, negative / 1e6);

  // The limit is an area, not a cell count: at a 500² grid it is 100 cells, the eye covers
  // 7 × 7 cell centres and is filled, the larger hole 12 × 12 and is not.
  const Evenness coarse = measureEvenness(p, atResolution(500));
  EXPECT_EQ(coarse.filledHoleCells, 49);
  // Fixed art counts as positive space, exactly like the same art as an element.
  PackingGeometry withFixed = p;
  withFixed.fixed = withFixed.elements.front();
  withFixed.elements.erase(withFixed.elements.begin());
  const Evenness f = measureEvenness(withFixed);
  EXPECT_EQ(f.negativeCells, e.negativeCells);
  EXPECT_EQ(f.filledHoleCells, e.filledHoleCells);
  EXPECT_DOUBLE_EQ(f.halfWidth, e.halfWidth);
  EXPECT_DOUBLE_EQ(f.pocketShare[1], e.pocketShare[1]);
}

TEST(Evenness, DegenerateAndBadInput) {
  PackingGeometry p;
  EXPECT_THROW(measureEvenness(p), InputError);  // no container
  p.container = test::rect(0, 0, 10, 10);
  EXPECT_THROW(measureEvenness(p, atResolution(1)), InputError);
  EvennessOptions negativeHoles;
  negativeHoles.smallHoleArea = -1.0;
  EXPECT_THROW(measureEvenness(p, negativeHoles), InputError);
  // Everything positive: no negative space, no axis, every ratio 0.
  p.elements.push_back(test::rect(-1, -1, 11, 11));
  const Evenness full = measureEvenness(p, atResolution(50));
  EXPECT_EQ(full.negativeCells, 0);
  EXPECT_EQ(full.halfWidth, 0.0);
  EXPECT_EQ(full.pocketShare[1], 0.0);
}

}  // namespace
}  // namespace pak
