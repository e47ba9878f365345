#pragma once
// Initial placement (thesis 4.4): evenly spread seed points inside the free region,
// element types assigned cyclically in random order with random orientations.
#include <cstdint>
#include <vector>

#include "pak/geom/polygon.hpp"
#include "sim/region_index.hpp"

namespace pak {

struct Seed {
  Vec2 position;
  double angle = 0.0;  // radians
  int type = 0;        // library index
  int container = 0;   // which separate container it is in (see containers.hpp)
};

struct SeedingOptions {
  int count = 1;
  int types = 1;
  std::uint64_t seed = 1;
  Vec2 period{};  // tile W × H: distances on the torus and no boundary (thesis 4.8); 0: off
};

// `count` points spread evenly over `region` (blue-noise candidates, then farthest-point
// selection that also keeps away from the boundary), shuffled, with types 0,1,2,… cycled.
std::vector<Seed> seedElements(const Region& region, const RegionIndex& index, const SeedingOptions& options);

}  // namespace pak
