#include "pak/geom/distance_field.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "pak/error.hpp"
#include "pak/geom/closest_point.hpp"
#include "pak/geom/rng.hpp"

using namespace pak;

namespace {

Ring square(double x0, double y0, double side) {
  return {{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}};
}

Box box(double x0, double y0, double x1, double y1) {
  Box b;
  b.add(Vec2{x0, y0});
  b.add(Vec2{x1, y1});
  return b;
}

double analyticSquare(Vec2 p, double side) {
  const double dx = std::max({-p.x, 0.0, p.x - side}), dy = std::max({-p.y, 0.0, p.y - side});
  if (dx > 0.0 || dy > 0.0) return std::hypot(dx, dy);
  return -std::min({p.x, side - p.x, p.y, side - p.y});
}

// The reference the fast field must reproduce: every segment, every cell.
double bruteForce(Vec2 p, const Region& region) {
  const double d = closestPointOnBoundary(p, region).distance;
  return pointInRegion(p, region) ? -d : d;
}

Ring star(int points, double inner, double outer, Vec2 centre) {
  Ring r;
  for (int k = 0; k < 2 * points; ++k) {
    const double a = M_PI * k / points;
    const double radius = k % 2 ? inner : outer;
    r.push_back(centre + Vec2{radius * std::cos(a), radius * std::sin(a)});
  }
  return r;
}

}  // namespace

TEST(DistanceField, SquareMatchesAnalyticDistance) {
  Region region{Polygon{square(0, 0, 10), {}}};
  DistanceGrid g = signedDistanceField(region, box(-5, -5, 15, 15), 40);
  ASSERT_EQ(g.nx, 40);
  ASSERT_EQ(g.ny, 40);
  EXPECT_DOUBLE_EQ(g.cell, 0.5);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) ASSERT_NEAR(g.at(i, j), analyticSquare(g.center(i, j), 10.0), 1e-9) << i << "," << j;
  EXPECT_LT(g.at(20, 20), 0.0);  // inside is negative
  EXPECT_GT(g.at(0, 0), 0.0);
}

TEST(DistanceField, DiscMatchesBruteForceExactlyAndCircleWithinSagitta) {
  Ring disc;
  const int n = 64;
  for (int k = 0; k < n; ++k) disc.push_back({5.0 * std::cos(2 * M_PI * k / n), 5.0 * std::sin(2 * M_PI * k / n)});
  Region region{Polygon{disc, {}}};
  DistanceGrid g = signedDistanceField(region, box(-8, -8, 8, 8), 64);
  const double sagitta = 5.0 * (1.0 - std::cos(M_PI / n));
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const Vec2 p = g.center(i, j);
      ASSERT_NEAR(g.at(i, j), bruteForce(p, region), 1e-12);
      ASSERT_NEAR(g.at(i, j), length(p) - 5.0, sagitta + 1e-12);
    }
}

TEST(DistanceField, ManySegmentsMatchBruteForce) {
  // Two stars, one with a hole: exercises the pruning with many nearly equidistant segments.
  Region region{Polygon{star(40, 20, 30, {0, 0}), {star(12, 5, 8, {2, 1})}},
                Polygon{star(25, 6, 10, {45, 30}), {}}};
  DistanceGrid g = signedDistanceField(region, box(-40, -40, 60, 50), 150);
  EXPECT_EQ(g.nx, 150);
  EXPECT_EQ(g.ny, 135);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) ASSERT_NEAR(g.at(i, j), bruteForce(g.center(i, j), region), 1e-12) << i << "," << j;
}

TEST(DistanceField, HoleIsOutside) {
  Region region{Polygon{square(0, 0, 10), {square(4, 4, 2)}}};
  DistanceGrid g = signedDistanceField(region, box(0, 0, 10, 10), 10);
  EXPECT_DOUBLE_EQ(g.at(5, 5), 0.5);   // centre (5.5, 5.5): 0.5 from the hole's side, outside
  EXPECT_DOUBLE_EQ(g.at(2, 5), -1.5);  // centre (2.5, 5.5): 1.5 from the hole, inside
}

TEST(DistanceField, NonSquareAreaAndEmptyRegion) {
  DistanceGrid g = signedDistanceField(Region{}, box(0, 0, 20, 10), 40);
  EXPECT_EQ(g.nx, 40);
  EXPECT_EQ(g.ny, 20);
  ASSERT_EQ(g.values.size(), 800u);
  for (double v : g.values) EXPECT_TRUE(std::isinf(v) && v > 0.0);
}

TEST(DistanceField, BadInputThrows) {
  Region region{Polygon{square(0, 0, 1), {}}};
  EXPECT_THROW(signedDistanceField(region, box(0, 0, 1, 1), 0), InputError);
  EXPECT_THROW(signedDistanceField(region, Box{}, 10), InputError);
  EXPECT_THROW(signedDistanceField(region, box(0, 0, 0, 0), 10), InputError);
  Region bad{Polygon{{{0, 0}, {std::numeric_limits<double>::quiet_NaN(), 0}, {0, 1}}, {}}};
  EXPECT_THROW(signedDistanceField(bad, box(0, 0, 1, 1), 10), InputError);
}

TEST(DistanceField, BilinearSample) {
  DistanceGrid g;
  g.origin = {0, 0};
  g.cell = 1.0;
  g.nx = 2;
  g.ny = 2;
  g.values = {0.0, 1.0, 2.0, 3.0};  // value = i + 2j at centres (0.5 + i, 0.5 + j)
  EXPECT_DOUBLE_EQ(g.sample({0.5, 0.5}), 0.0);
  EXPECT_DOUBLE_EQ(g.sample({1.5, 1.5}), 3.0);
  EXPECT_DOUBLE_EQ(g.sample({1.0, 1.0}), 1.5);
  EXPECT_DOUBLE_EQ(g.sample({1.0, 0.5}), 0.5);
  EXPECT_DOUBLE_EQ(g.sample({-10.0, -10.0}), 0.0);  // clamped
  EXPECT_DOUBLE_EQ(g.sample({10.0, 0.5}), 1.0);
  DistanceGrid single;
  single.nx = single.ny = 1;
  single.values = {7.0};
  EXPECT_DOUBLE_EQ(single.sample({3, 3}), 7.0);
}

TEST(DistanceField, EdtOfSingleCellIsEuclidean) {
  const int nx = 13, ny = 9;
  std::vector<std::uint8_t> occupied(nx * ny, 0);
  occupied[4 * nx + 3] = 1;
  std::vector<double> d = euclideanDistanceTransform(occupied, nx, ny);
  ASSERT_EQ(d.size(), occupied.size());
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) EXPECT_DOUBLE_EQ(d[j * nx + i], std::sqrt(double((i - 3) * (i - 3) + (j - 4) * (j - 4))));
}

TEST(DistanceField, EdtMatchesBruteForceOnRandomMask) {
  const int nx = 37, ny = 23;
  Rng rng(7);
  std::vector<std::uint8_t> occupied(nx * ny);
  for (auto& o : occupied) o = rng.uniform() < 0.03;
  std::vector<double> d = euclideanDistanceTransform(occupied, nx, ny);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      double best = std::numeric_limits<double>::infinity();
      for (int jj = 0; jj < ny; ++jj)
        for (int ii = 0; ii < nx; ++ii)
          if (occupied[jj * nx + ii]) best = std::min(best, std::hypot(double(i - ii), double(j - jj)));
      ASSERT_DOUBLE_EQ(d[j * nx + i], best) << i << "," << j;
    }
}

TEST(DistanceField, EdtEdgeCases) {
  std::vector<double> empty = euclideanDistanceTransform(std::vector<std::uint8_t>(6, 0), 3, 2);
  for (double v : empty) EXPECT_TRUE(std::isinf(v));
  std::vector<double> full = euclideanDistanceTransform(std::vector<std::uint8_t>(6, 1), 3, 2);
  for (double v : full) EXPECT_EQ(v, 0.0);
  EXPECT_TRUE(euclideanDistanceTransform({}, 0, 0).empty());
  // One row: occupied only at the ends.
  std::vector<double> row = euclideanDistanceTransform({1, 0, 0, 0, 0, 1}, 6, 1);
  EXPECT_EQ(row, (std::vector<double>{0, 1, 2, 2, 1, 0}));
}

TEST(DistanceField, SampleOfAFieldWithoutBoundaryIsInfinite) {
  DistanceGrid g = signedDistanceField(Region{}, box(0, 0, 4, 4), 4);
  EXPECT_TRUE(std::isinf(g.sample({1.0, 1.0})));
  EXPECT_TRUE(std::isinf(g.sample({0.5, 0.5})));
}
