#include "sim/packing_setup.hpp"

#include <algorithm>

#include "pak/error.hpp"
#include "pak/geom/art.hpp"

namespace pak {

Box canonicalFrameBox(const Scene& scene, bool spansFixed) {
  Box box = bounds(scene.container);
  if (spansFixed && !box.empty())
    for (const Shape& s : scene.fixed) box.add(bounds(s));
  return box;
}

PackingSetup preparePacking(const Scene& scene, const Library& library, const PackingSetupOptions& options) {
  PackingSetup setup;
  if (bounds(scene.container).empty() || !(area(scene.container) > 0.0)) throw InputError(scene.source, "container has no area");
  const Box box = canonicalFrameBox(scene, options.frameSpansFixed);
  setup.frameBox = box;
  setup.side = std::max(box.width(), box.height());
  setup.frame = CanonicalFrame::of(box);
  setup.clip = options.clip.value_or(ClipOptions{1e-7 * setup.side});
  const double scale = setup.frame.scale;
  const Vec2 shift = -box.min * scale;

  setup.container = transformed(scene.container, scale, shift);
  normalizeOrientation(setup.container);
  // Fixed elements as obstacles: their art, grown as a skin is, leaves the container; the
  // area it takes counts as filled.
  Region obstacles;
  if (!scene.fixed.empty()) {
    std::vector<Region> painted;
    for (const Shape& shape : scene.fixed) painted.push_back(paintedRegion(shape, setup.clip));
    setup.fixedPainted = unite(painted, setup.clip);
    if (options.obstacleMargin) {
      const double fullArea = area(setup.container);
      obstacles = offset(transformed(setup.fixedPainted, scale, shift), *options.obstacleMargin);
      setup.container = subtract(setup.container, obstacles);
      normalizeOrientation(setup.container);
      setup.blockedArea = fullArea - area(setup.container);
      if (!(area(setup.container) > 0.0)) throw InputError(scene.source, "the fixed elements cover the whole container");
    }
  }
  setup.containerArea = area(setup.container);

  setup.containers = sceneContainers(scene, library);
  for (const Region& input : setup.containers.regions) {
    Region part = transformed(input, scale, shift);
    if (!obstacles.empty()) part = subtract(part, obstacles);
    normalizeOrientation(part);
    setup.partAreas.push_back(area(part));
    setup.parts.push_back(std::move(part));
  }
  return setup;
}

void indexContainers(PackingSetup& setup, double cellSize) {
  // Every simulation step asks these for the nearest wall of many vertices.
  setup.containerIndex = RegionIndex(setup.container, cellSize);
  setup.containerIndex.listNearSegments();
  setup.partIndexes.clear();
  if (setup.severalParts())
    for (const Region& part : setup.parts) setup.partIndexes.emplace_back(part, cellSize).listNearSegments();
}

std::vector<const RegionIndex*> PackingSetup::partIndexPointers() const {
  std::vector<const RegionIndex*> pointers;
  for (std::size_t c = 0; c < parts.size(); ++c) pointers.push_back(&partIndex(c));
  return pointers;
}

int PackingSetup::partAt(Vec2 p) const {
  for (std::size_t c = 0; c < parts.size(); ++c)
    if (partIndex(c).query(p, false).inside) return static_cast<int>(c);
  return -1;
}

}  // namespace pak
