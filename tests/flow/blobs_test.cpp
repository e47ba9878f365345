// Sub-region blobs (thesis 3.3.4): a Voronoi split of the free space around streamlines, the
// extension of streamlines to their blob, and blob growth.
#include <gtest/gtest.h>

#include <cmath>

#include "flow/blobs.hpp"
#include "pak/geom/clipping.hpp"

namespace pak {
namespace {

Region rect(double x0, double y0, double x1, double y1) {
  return Region{Polygon{Ring{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}}};
}

VectorField uniformX() {
  VectorFieldOptions o;
  o.sampleSpacing = 2.0;
  o.resolution = 32;
  return buildVectorField(rect(0, 0, 200, 100), {{{0, 50}, {200, 50}}}, o);
}

TEST(Blobs, TwoParallelStreamlinesSplitARectangleAtTheMidline) {
  Region space = rect(0, 0, 200, 100);
  std::vector<Region> blobs = computeBlobs(space, {{{20, 30}, {180, 30}}, {{20, 70}, {180, 70}}}, {256});
  ASSERT_EQ(blobs.size(), 2u);
  EXPECT_NEAR(area(blobs[0]), 10000.0, 100.0);
  EXPECT_NEAR(area(blobs[1]), 10000.0, 100.0);
  EXPECT_LT(bounds(blobs[0]).max.y, 51.0);
  EXPECT_GT(bounds(blobs[1]).min.y, 49.0);
}

TEST(Blobs, AreDisjointCoverTheFreeSpaceAndAvoidObstacles) {
  Region obstacle = rect(90, 40, 110, 60);
  Region space = subtract(rect(0, 0, 200, 100), obstacle);
  std::vector<Polyline> lines{{{10, 20}, {190, 20}}, {{10, 50}, {80, 50}}, {{120, 50}, {190, 50}}, {{10, 80}, {190, 80}}};
  std::vector<Region> blobs = computeBlobs(space, lines, {300});
  double total = 0.0;
  for (std::size_t a = 0; a < blobs.size(); ++a) {
    total += area(blobs[a]);
    EXPECT_LT(area(intersect(blobs[a], obstacle)), 1e-9);
    for (std::size_t b = a + 1; b < blobs.size(); ++b) EXPECT_LT(area(intersect(blobs[a], blobs[b])), 1e-6);
  }
  EXPECT_NEAR(total, area(space), 0.01 * area(space));
}

TEST(Blobs, ExtendingAStreamlineReachesItsBlobsEdge) {
  Region blob = rect(0, 0, 200, 100);
  Polyline line = extendToBlob({{80, 50}, {120, 50}}, blob, uniformX(), 1.0);
  EXPECT_LT(line.front().x, 1.0 + 1e-9);
  EXPECT_GT(line.back().x, 199.0 - 1e-9);
  for (Vec2 p : line) EXPECT_NEAR(p.y, 50.0, 1e-9);
}

TEST(Blobs, GrowthIsBoundedAndNeverEntersOccupiedSpace) {
  Region blob = rect(50, 40, 150, 60);
  Region occupied = rect(0, 65, 200, 100);
  Region grown = growBlob(blob, occupied, rect(0, 0, 200, 100), 10.0);
  EXPECT_GT(area(grown), area(blob));
  EXPECT_LE(area(grown), area(offset(blob, 10.0)) + 1e-6);
  EXPECT_LT(area(intersect(grown, occupied)), 1e-9);
  EXPECT_GE(bounds(grown).min.y, 30.0 - 1e-6);
  EXPECT_LE(bounds(grown).max.y, 65.0 + 1e-6);
}

}  // namespace
}  // namespace pak
