#include "sim/scene_containers.hpp"

#include <algorithm>

namespace pak {

SceneContainers sceneContainers(const Scene& scene, const Library& library) {
  SceneContainers result;
  std::vector<const Library*> libraryOf;
  if (scene.containers.empty()) {
    for (const Polygon& polygon : scene.container) result.regions.push_back(Region{polygon});
  } else {
    for (const ContainerPart& part : scene.containers) {
      result.regions.push_back(part.region);
      libraryOf.push_back(part.library.empty() ? &library : &part.library);
    }
  }
  libraryOf.resize(result.regions.size(), &library);
  std::vector<const Library*> used;  // distinct, in order of first use
  std::vector<int> first;            // the index of each one's first type
  int types = 0;
  for (const Library* l : libraryOf)
    if (std::find(used.begin(), used.end(), l) == used.end()) {
      used.push_back(l);
      first.push_back(types);
      types += static_cast<int>(l->size());
    }
  if (used.size() != 1 || used.front() != &library)
    for (const Library* l : used) result.combined.insert(result.combined.end(), l->begin(), l->end());
  for (const Library* l : libraryOf) {
    const int begin = first[static_cast<std::size_t>(std::find(used.begin(), used.end(), l) - used.begin())];
    std::vector<int>& typesOf = result.typesOf.emplace_back();
    for (int k = 0; k < static_cast<int>(l->size()); ++k) typesOf.push_back(begin + k);
  }
  return result;
}

}  // namespace pak
