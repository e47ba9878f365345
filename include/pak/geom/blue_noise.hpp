#pragma once
// Blue-noise (Poisson-disk) sampling inside a region with holes (Bridson 2007).
#include <cstdint>
#include <vector>

#include "pak/geom/polygon.hpp"

namespace pak {

struct BlueNoiseOptions {
  // Minimum distance between two samples.
  double radius = 1.0;
  // Candidates tried around each active sample before it retires (Bridson's k).
  int attempts = 30;
  // Keep samples at least this far from the region's boundary (0: anywhere inside).
  double boundaryMargin = 0.0;
  // Stop after this many samples (0: fill the region).
  std::size_t maxSamples = 0;
  std::uint64_t seed = 1;
};

// Samples inside `region` (outside its holes), pairwise at least `radius` apart.
// Deterministic for a seed.
std::vector<Vec2> blueNoiseSample(const Region& region, const BlueNoiseOptions& options);

}  // namespace pak
