#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "metrics_fixtures.hpp"
#include "pak/error.hpp"

using namespace pak;
using namespace pak::test;

namespace {

// The exact Q at r +- `slack` brackets the grid's Q at r, up to `eps` of area quantisation.
void expectGridMatchesExact(const PackingGeometry& p, int resolution, double eps) {
  MetricsOptions o;
  o.radii = 21;
  o.gridResolution = resolution;
  o.arcTolerance = 1e-6;
  const PackingMetrics m = measurePacking(p, o);
  const double cell = std::max(std::abs(p.container[0].outer[2].x - p.container[0].outer[0].x),
                               std::abs(p.container[0].outer[2].y - p.container[0].outer[0].y)) /
                      resolution;
  const double slack = 2 * cell;
  for (std::size_t k = 0; k < m.sphericalContact.r.size(); ++k) {
    const double r = m.sphericalContact.r[k];
    const double upper = sphericalContact(p, std::max(0.0, r - slack), 1e-6);
    const double lower = sphericalContact(p, r + slack, 1e-6);
    EXPECT_LE(m.gridSphericalContact.value[k], upper + eps) << r;
    EXPECT_GE(m.gridSphericalContact.value[k], lower - eps) << r;
  }
}

}  // namespace

TEST(MeasurePacking, SquareGridSummary) {
  const double s = 2, g = 0.5;
  const PackingGeometry p = squareGrid(4, s, g);
  MetricsOptions o;
  o.radii = 11;
  o.gridResolution = 200;
  o.histogramBins = 10;
  o.arcTolerance = 1e-7;
  const PackingMetrics m = measurePacking(p, o);
  EXPECT_EQ(m.elementCount, 16);
  EXPECT_NEAR(m.containerArea, 100.0, 1e-9);
  EXPECT_NEAR(m.negativeRatio, 1 - 0.64, 1e-9);
  EXPECT_NEAR(m.positiveRatio, 0.64, 1e-9);
  EXPECT_NEAR(m.largestEmptyRadius, g * std::sqrt(2.0) / 2, 1e-5);
  ASSERT_EQ(m.sphericalContact.r.size(), 11u);
  ASSERT_EQ(m.overlap.r.size(), 11u);
  EXPECT_NEAR(m.sphericalContact.value.front(), m.negativeRatio, 1e-12);
  EXPECT_NEAR(m.sphericalContact.r.back(), m.largestEmptyRadius, 1e-12);
  for (std::size_t k = 1; k < m.sphericalContact.value.size(); ++k)
    EXPECT_LE(m.sphericalContact.value[k], m.sphericalContact.value[k - 1]);
  for (double h : m.distanceHistogram.value) EXPECT_GE(h, 0.0);
  EXPECT_TRUE(m.gapEstimated);
  EXPECT_GT(m.gap, 0.0);
  EXPECT_NEAR(m.overlap.r.back(), m.gap, 1e-12);
  ASSERT_EQ(m.binEdges.size(), 11u);
  ASSERT_EQ(m.binDensity.size(), 10u);
  // The discrete histogram integrates to the grid's negative ratio.
  double mass = 0;
  for (std::size_t k = 0; k < m.binDensity.size(); ++k)
    mass += m.binDensity[k] * (m.binEdges[k + 1] - m.binEdges[k]);
  EXPECT_NEAR(mass, m.gridSphericalContact.value.front(), 1e-9);
  EXPECT_NEAR(mass, m.negativeRatio, 0.02);
}

TEST(MeasurePacking, GivenGapIsUsedAtHalfGap) {
  const PackingGeometry p = stripes(100, 5, 3, 1);
  MetricsOptions o;
  o.radii = 5;
  o.gridResolution = 100;
  o.gap = 1.0;
  const PackingMetrics m = measurePacking(p, o);
  EXPECT_FALSE(m.gapEstimated);
  EXPECT_EQ(m.gap, 1.0);
  EXPECT_NEAR(m.contactAtHalfGap, 0.0, 1e-3);
  EXPECT_NEAR(m.overlapAtHalfGap, 0.0, 1e-6);
  // Stripes: H is the step (2 / (g + b)) * (W - 2r)/W-ish, positive up to g/2.
  EXPECT_NEAR(m.distanceHistogram.value[1], 2.0 / 4.0, 0.01);
}

TEST(MeasurePacking, GridQMatchesExactQWithinResolution) {
  expectGridMatchesExact(squareGrid(4, 2, 0.5), 400, 0.01);
  expectGridMatchesExact(stripes(20, 5, 3, 1), 400, 0.01);
  PackingGeometry d;
  d.container = rect(0, 0, 1, 1);
  d.elements.push_back(disc({0.5, 0.5}, 0.2, 512));
  d.elements.push_back(disc({0.15, 0.15}, 0.1, 512));
  expectGridMatchesExact(d, 400, 0.01);
}

TEST(MeasurePacking, BadInputThrows) {
  PackingGeometry none;
  none.elements.push_back(rect(0, 0, 1, 1));
  EXPECT_THROW(measurePacking(none), InputError);
  try {
    sphericalContact(none, 0.0);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no container"), std::string::npos);
  }
  PackingGeometry empty;
  empty.source = "a.svg";
  empty.container = rect(0, 0, 10, 10);
  try {
    measurePacking(empty);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "a.svg: no elements");
  }
  PackingGeometry outside = empty;
  outside.elements.push_back(rect(1, 1, 2, 2));
  outside.elements.push_back(rect(20, 20, 30, 30));
  try {
    overlapFunction(outside, 0.0);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "a.svg: element 2 lies entirely outside the container");
  }
  MetricsOptions o;
  o.radii = 1;
  EXPECT_THROW(measurePacking(squareGrid(2, 1, 0.5), o), InputError);
}
