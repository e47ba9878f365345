#pragma once
// Seeding several separate containers (thesis Figure 4.10, 4.12b): how many seeds each gets,
// and seeding each with its own element types (sim/scene_containers.hpp finds them).
#include <cstdint>
#include <vector>

#include "pak/geom/polygon.hpp"
#include "repulsion/seeding.hpp"
#include "sim/region_index.hpp"

namespace pak {

// Seeds per container, proportional to area (largest remainders), summing to `count`; a
// container of at least `minimumArea` gets one even when its share rounds to 0 (so the total
// may exceed `count` when there are more such containers than seeds).
std::vector<int> seedsPerContainer(const std::vector<double>& areas, int count, double minimumArea);

struct ContainerSeeding {
  const Region* region = nullptr;
  const RegionIndex* index = nullptr;
  int count = 0;
  std::vector<int> types;  // the element types (global indices) it is filled with
};

// seedElements in each container, types cycled through its own list, Seed::container set.
// Container 0 uses `seed` itself, so a single container seeds exactly as seedElements does.
// `period`: SeedingOptions::period (a tile).
std::vector<Seed> seedContainers(const std::vector<ContainerSeeding>& containers, std::uint64_t seed, Vec2 period = {});

}  // namespace pak
