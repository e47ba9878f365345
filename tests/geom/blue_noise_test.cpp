#include "pak/geom/blue_noise.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "pak/error.hpp"
#include "pak/geom/clipping.hpp"
#include "pak/geom/closest_point.hpp"

using namespace pak;

namespace {

Ring square(double x0, double y0, double side) {
  return {{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}};
}

double minPairwiseDistance(const std::vector<Vec2>& points) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < points.size(); ++a)
    for (std::size_t b = a + 1; b < points.size(); ++b) best = std::min(best, distance(points[a], points[b]));
  return best;
}

// Largest distance from a point of the region (probed on a fine lattice) to its nearest sample.
double coverageRadius(const std::vector<Vec2>& samples, const Region& region, double step) {
  const Box b = bounds(region);
  double worst = 0.0;
  for (double y = b.min.y + step / 2; y < b.max.y; y += step)
    for (double x = b.min.x + step / 2; x < b.max.x; x += step) {
      if (!pointInRegion({x, y}, region)) continue;
      double nearest = std::numeric_limits<double>::infinity();
      for (Vec2 s : samples) nearest = std::min(nearest, distance(s, {x, y}));
      worst = std::max(worst, nearest);
    }
  return worst;
}

}  // namespace

TEST(BlueNoise, SamplesInsideOutsideHolesAndApart) {
  Region region{Polygon{square(0, 0, 40), {square(10, 10, 12)}}};
  BlueNoiseOptions options;
  options.radius = 1.5;
  options.seed = 42;
  std::vector<Vec2> samples = blueNoiseSample(region, options);
  ASSERT_FALSE(samples.empty());
  for (Vec2 p : samples) {
    ASSERT_TRUE(pointInPolygon(p, region[0])) << p.x << "," << p.y;
    ASSERT_FALSE(pointInRing(p, region[0].holes[0]));
  }
  EXPECT_GE(minPairwiseDistance(samples), options.radius);

  // Count bounds. Discs of radius r/2 around the samples are disjoint and lie within the
  // region grown by r/2: an exact upper bound. A maximal sampling covers the region with
  // discs of radius r, so N * pi r^2 >= area; Bridson is near-maximal, so ask for 0.8 of it.
  const double r = options.radius;
  const double grownArea = area(offset(region, r / 2));
  EXPECT_LE(samples.size() * std::numbers::pi * r * r / 4, grownArea);
  EXPECT_GT(static_cast<double>(samples.size()), 0.8 * area(region) / (std::numbers::pi * r * r));
  // No big empty spots: every point of the region is within 2r of a sample.
  EXPECT_LT(coverageRadius(samples, region, 0.5), 2.0 * r);
}

TEST(BlueNoise, SameSeedSamePointsOtherSeedOtherPoints) {
  Region region{Polygon{square(0, 0, 20), {}}};
  BlueNoiseOptions options;
  options.radius = 1.0;
  options.seed = 3;
  std::vector<Vec2> a = blueNoiseSample(region, options), b = blueNoiseSample(region, options);
  EXPECT_EQ(a, b);
  options.seed = 4;
  EXPECT_NE(a, blueNoiseSample(region, options));
}

TEST(BlueNoise, FillsEveryPolygonOfTheRegion) {
  Region region{Polygon{square(0, 0, 10), {}}, Polygon{square(30, 0, 10), {}}, Polygon{square(0, 30, 3), {}}};
  BlueNoiseOptions options;
  options.radius = 1.0;
  std::vector<Vec2> samples = blueNoiseSample(region, options);
  int counts[3] = {0, 0, 0};
  for (Vec2 p : samples)
    for (int k = 0; k < 3; ++k) counts[k] += pointInPolygon(p, region[k]);
  EXPECT_EQ(counts[0] + counts[1] + counts[2], static_cast<int>(samples.size()));
  EXPECT_GT(counts[0], 100 / M_PI);
  EXPECT_GT(counts[1], 100 / M_PI);
  EXPECT_GT(counts[2], 9 / M_PI);
}

TEST(BlueNoise, BoundaryMarginAndMaxSamples) {
  Region region{Polygon{square(0, 0, 20), {square(8, 8, 4)}}};
  BlueNoiseOptions options;
  options.radius = 0.8;
  options.boundaryMargin = 1.5;
  std::vector<Vec2> samples = blueNoiseSample(region, options);
  ASSERT_FALSE(samples.empty());
  for (Vec2 p : samples) {
    EXPECT_TRUE(pointInRegion(p, region));
    EXPECT_GE(closestPointOnBoundary(p, region).distance, options.boundaryMargin);
  }
  options.maxSamples = 17;
  EXPECT_EQ(blueNoiseSample(region, options).size(), 17u);
}

TEST(BlueNoise, ThinPartsAndDegenerateInput) {
  // A strip narrower than the radius still gets samples along it.
  Region strip{Polygon{Ring{{0, 0}, {50, 0}, {50, 0.5}, {0, 0.5}}, {}}};
  BlueNoiseOptions options;
  options.radius = 2.0;
  std::vector<Vec2> samples = blueNoiseSample(strip, options);
  EXPECT_GE(samples.size(), 13u);  // at most 4 apart along 50 in a maximal set
  for (Vec2 p : samples) EXPECT_TRUE(pointInRegion(p, strip));
  EXPECT_TRUE(blueNoiseSample(Region{}, options).empty());
  EXPECT_TRUE(blueNoiseSample(Region{Polygon{Ring{{0, 0}, {1, 1}, {2, 2}}, {}}}, options).empty());
  // A margin larger than the region's inradius leaves nothing.
  options.boundaryMargin = 1.0;
  EXPECT_TRUE(blueNoiseSample(strip, options).empty());
}

TEST(BlueNoise, BadOptionsThrow) {
  Region region{Polygon{square(0, 0, 1), {}}};
  BlueNoiseOptions options;
  options.radius = 0.0;
  EXPECT_THROW(blueNoiseSample(region, options), InputError);
  options.radius = 1e-9;  // far too many grid cells
  EXPECT_THROW(blueNoiseSample(Region{Polygon{square(0, 0, 1000), {}}}, options), InputError);
  options.radius = 0.1;
  options.attempts = 0;
  EXPECT_THROW(blueNoiseSample(region, options), InputError);
  options.attempts = 30;
  options.boundaryMargin = -1.0;
  EXPECT_THROW(blueNoiseSample(region, options), InputError);
  options.boundaryMargin = 0.0;
  Region bad{Polygon{Ring{{0, 0}, {std::numeric_limits<double>::quiet_NaN(), 0}, {0, 1}}, {}}};
  EXPECT_THROW(blueNoiseSample(bad, options), InputError);
}
