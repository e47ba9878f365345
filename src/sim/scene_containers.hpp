#pragma once
// A scene's separate containers (thesis Figure 4.10, 4.12b: several regions, or the elements of
// a previous packing), each filled from its own library or the run's. Every packer starts from
// them (sim/packing_setup.hpp).
#include <vector>

#include "pak/geom/polygon.hpp"
#include "pak/geom/scene.hpp"

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

}  // namespace pak
