#pragma once
// What every packer sets up before it places an element (RepulsionPak 4.4, AnimationPak 5.4,
// FLOWPAK 3.3.1): the canonical frame the thesis's constants hold in; the fixed elements and
// the obstacles they make; the container in that frame with the obstacles cut out; the
// separate containers, each with its element types; and, once the packer knows its mesh
// spacing, point-location indexes of them.
#include <optional>
#include <vector>

#include "pak/geom/clipping.hpp"
#include "pak/geom/polygon.hpp"
#include "pak/geom/scene.hpp"
#include "sim/canonical_frame.hpp"
#include "sim/region_index.hpp"
#include "sim/scene_containers.hpp"

namespace pak {

struct PackingSetupOptions {
  // FLOWPAK's l_canvas (3.3.1) spans the fixed elements as well as the containers; the
  // simulators map the container's bounding square.
  bool frameSpansFixed = false;
  // Fixed art grown by this (canonical units; a skin's d_gap / 2) is cut out of the
  // containers, so the boundary force keeps elements off it. nullopt: the fixed elements
  // are not obstacles here (FLOWPAK subtracts them from its free space itself).
  std::optional<double> obstacleMargin;
  // Precision of the booleans on the scene (input units); nullopt: 1e-7 of the frame's side.
  std::optional<ClipOptions> clip;
};

struct PackingSetup {
  CanonicalFrame frame;
  Box frameBox;             // input: what the frame maps (its longer side to kCanonicalSide)
  double side = 0.0;        // the longer side of frameBox
  ClipOptions clip;         // precision of booleans on the scene in input units
  Region fixedPainted;      // input: the union of what the fixed elements paint
  Region container;         // canonical: the containers minus the obstacles, interior on the left
  double containerArea = 0.0;
  double blockedArea = 0.0; // canonical area of the container that the obstacles took
  SceneContainers containers;      // input: the separate containers and each one's element types
  std::vector<Region> parts;       // canonical: each separate container minus the obstacles
  std::vector<double> partAreas;
  // After indexContainers: the whole container, and each part when there are several.
  RegionIndex containerIndex;
  std::vector<RegionIndex> partIndexes;

  // The element types: the run's library, or every library the containers use.
  const Library& types(const Library& runLibrary) const {
    return containers.combined.empty() ? runLibrary : containers.combined;
  }
  bool severalParts() const { return parts.size() > 1; }
  const RegionIndex& partIndex(std::size_t c) const { return severalParts() ? partIndexes[c] : containerIndex; }
  // One pointer per part (the setup must outlive their users).
  std::vector<const RegionIndex*> partIndexPointers() const;
  // The part that contains p (canonical), or -1.
  int partAt(Vec2 p) const;
};

// Throws InputError when the container has no area or the obstacles cover it.
PackingSetup preparePacking(const Scene& scene, const Library& library, const PackingSetupOptions& options);
// Builds the point-location indexes with cells of about `cellSize` canonical units.
void indexContainers(PackingSetup& setup, double cellSize);

}  // namespace pak
