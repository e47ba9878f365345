#pragma once
// Seeds for secondary elements (thesis 4.6): points far from every primary element, found on
// a distance transform of the negative space left by the primary pass.
#include <vector>

#include "pak/geom/polygon.hpp"

namespace pak {

struct SecondarySeed {
  Vec2 position;
  double radius = 0.0;  // an empty disc here: the seed's distance to the nearest skin or wall,
                        // capped at half the distance to the nearest other seed
};

struct SecondarySeedingOptions {
  double minDistance = 10.0;  // d_min: only points at least this far from any skin or wall
  double separation = 10.0;   // d_sep: chosen seeds keep at least this far apart
  int resolution = 1000;      // distance grid cells along the longer side of `area`
};

// `freeSpace` is the negative space (container minus skins and obstacles) and `area` the
// frame the grid covers (the thesis's 1000 × 1000 grid fit to the container's bounds).
// Candidates are grid cells with distance ≥ d_min, visited by decreasing distance (ties by
// cell index, so the result is deterministic); a candidate within d_sep of a chosen seed is
// dropped.
std::vector<SecondarySeed> secondarySeeds(const Region& freeSpace, const Box& area,
                                          const SecondarySeedingOptions& options);

}  // namespace pak
