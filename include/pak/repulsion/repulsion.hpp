#pragma once
// RepulsionPak (thesis chapter 4): pack a container with deformable elements.
//
//   Packing p = packRepulsion(scene, library, options);
//
// The scene and library are in the input's own coordinates; Pak maps the container's
// bounding square to a canonical 1000 × 1000 frame, simulates there, and maps back, so every
// distance-like option (repulsion_options.hpp) is in canonical units.
#include <functional>
#include <string>
#include <vector>

#include "pak/geom/art.hpp"
#include "pak/geom/scene.hpp"
#include "pak/repulsion/repulsion_options.hpp"
#include "pak/sim/packing.hpp"

namespace pak {

struct RepulsionProgress {
  int iteration = 0;
  double fill = 0.0;   // skin area / container area
  int growing = 0;     // elements still allowed to grow
  int elements = 0;
  int touchingNeighbours = 0;  // not growing: a vertex inside another element's mesh
  int againstWall = 0;         // not growing: pushed out of the container
};

struct RepulsionCallbacks {
  // Called every `progressEvery` iterations and at the end.
  std::function<void(const RepulsionProgress&)> onProgress;
  int progressEvery = 100;
  // Called every `snapshotEvery` iterations (0: never) with the current packing.
  std::function<void(const Packing&)> onSnapshot;
  int snapshotEvery = 0;
};

// Throws InputError for an empty library or container, or bad options.
Packing packRepulsion(const Scene& scene, const Library& library, const RepulsionOptions& options = {},
                      const RepulsionCallbacks& callbacks = {});
// The same, then a secondary pass with `secondaryLibrary` (4.6) when it is not empty.
Packing packRepulsion(const Scene& scene, const Library& library, const Library& secondaryLibrary,
                      const RepulsionOptions& options = {}, const RepulsionCallbacks& callbacks = {});

}  // namespace pak
