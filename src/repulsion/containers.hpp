#pragma once
// Several separate containers (issue 5 item 3; thesis Figure 4.10, 4.12b): how many seeds
// each gets, and seeding each with its own element types.
#include <cstdint>
#include <vector>

#include "pak/geom/polygon.hpp"
#include "pak/geom/scene.hpp"
#include "repulsion/seeding.hpp"
#include "sim/region_index.hpp"

namespace pak {

// The scene's separate containers and the element types each is filled with.
struct SceneContainers {
  std::vector<Region> regions;  // input coordinates: Scene::containers, else each polygon
  // Every library in use (the containers' own, the run's), in order of first use; empty when
  // that is just the run's library, which is then the element types as it is.
  Library combined;
  std::vector<std::vector<int>> typesOf;  // per container: its element types
};
SceneContainers sceneContainers(const Scene& scene, const Library& library);

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
