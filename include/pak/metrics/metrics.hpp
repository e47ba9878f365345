#pragma once
// Negative-space metrics of a 2D packing (thesis chapter 6): spherical contact probability
// Q(r), distance histogram H(r) = -Q'(r), overlap function O(r), and calibration.
//
//   PackingMetrics m = measurePacking(geometry, options);
//
// All lengths are in the packing's own units; ratios are over the container area.
#include <string>
#include <vector>

#include "pak/geom/polygon.hpp"

namespace pak {

// What the metrics need of a packing: the container and one outline per element (the union
// of everything the element paints).
struct PackingGeometry {
  std::string source;
  Region container;
  std::vector<Region> elements;
  // What the fixed elements paint. Positive space for the evenness measure (evenness.hpp);
  // the chapter-6 measures here look at `elements` only.
  Region fixed;
};

struct MetricsOptions {
  int radii = 100;              // samples of r, evenly spaced from 0 to the largest empty radius
  int gridResolution = 1000;    // EDT grid cells along the container's bounding square
  int histogramBins = 50;       // discrete histogram of the EDT
  double gap = 0.0;             // d_gap; 0: estimate it (see estimateGap)
  double overlapMaxRadius = 0.0;  // O(r) sampled on [0, this]; 0: up to d_gap
  double arcTolerance = 0.0;    // of the offsets; 0: 1e-4 of the container's bounding square
};

struct Curve {
  std::vector<double> r;
  std::vector<double> value;
};

struct PackingMetrics {
  std::string source;
  double containerArea = 0.0;
  double positiveRatio = 0.0;     // union of element outlines inside the container / container
  double negativeRatio = 0.0;     // 1 - positiveRatio
  int elementCount = 0;
  double largestEmptyRadius = 0.0;  // largest r with Q(r) > 0
  Curve sphericalContact;         // Q(r), exact (polygon offsets)
  Curve distanceHistogram;        // H(r) = -Q'(r), from the exact Q
  Curve overlap;                  // O(r), exact
  Curve gridSphericalContact;     // Q(r) from the grid EDT, for comparison
  std::vector<double> binEdges;   // discrete EDT histogram: histogramBins + 1 edges
  std::vector<double> binDensity; // fraction of container area per unit r, per bin
  double gap = 0.0;
  bool gapEstimated = false;
  double contactAtHalfGap = 0.0;  // Q(d_gap / 2)
  double overlapAtHalfGap = 0.0;  // O(d_gap / 2)
};

// Q(r) = area(negative space eroded by a disc of radius r) / container area.
double sphericalContact(const PackingGeometry& packing, double r, double arcTolerance = 0.0);
// O(r) = area covered by two or more element outlines offset by r / container area.
double overlapFunction(const PackingGeometry& packing, double r, double arcTolerance = 0.0);
// A d_gap estimate from the negative space alone: four times the radius at which Q falls to
// half of Q(0) (stripes: Q falls linearly to 0 at d_gap / 2, so to half at d_gap / 4).
double estimateGap(const PackingGeometry& packing);

PackingMetrics measurePacking(const PackingGeometry& packing, const MetricsOptions& options = {});

// The discrete distance transform of thesis 6.3.2 (Figure 6.3b): `resolution` cells along the
// container's bounding square, row-major from `origin`, each free cell holding the distance
// from its centre to the nearest element or container boundary, every other cell -1.
struct DistanceMap {
  Vec2 origin;
  double cell = 0.0;
  int columns = 0, rows = 0;
  std::vector<double> distance;
  double largest = 0.0;   // over the free cells
};
DistanceMap distanceMap(const PackingGeometry& packing, int resolution = 1000);

// Thesis 6.4: offsets every element outline uniformly (by bisection on the offset) until the
// negative-space ratio equals `targetNegativeRatio` within `tolerance`.
struct Calibration {
  double offset = 0.0;           // applied to every element outline (negative: shrunk)
  PackingGeometry calibrated;
  double negativeRatio = 0.0;    // reached
};
Calibration calibrateNegativeSpace(const PackingGeometry& packing, double targetNegativeRatio,
                                   double tolerance = 1e-5);

}  // namespace pak
