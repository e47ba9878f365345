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
  std::function<void(const struct Packing&)> onSnapshot;
  int snapshotEvery = 0;
};

struct PlacedElement {
  int libraryIndex = 0;
  std::string source;
  std::vector<Shape> art;   // deformed art in input coordinates, original paint
  Ring skin;                // deformed skin in input coordinates
  std::vector<Vec2> meshVertices;                // input coordinates
  std::vector<std::array<int, 3>> meshTriangles;
  double growth = 0.0;      // final growth factor g
  bool secondary = false;   // placed by the secondary pass; libraryIndex is then in the secondary library
  double maxEdgeStrain = 0.0;  // largest |length / (g × rest length) − 1| over its edge springs
  double meanEdgeStrain = 0.0; // mean of the same over its edge springs
  int container = 0;        // index into Packing::containers: the one it was seeded in
};

enum class StopReason { TargetFill, Stalled, IterationCap };
const char* toString(StopReason reason);

// One simulation pass: the primary one, then the secondary one when it runs (4.6).
struct PackingPass {
  int elements = 0;          // elements this pass moved
  int iterations = 0;
  StopReason stopReason = StopReason::IterationCap;
  double seconds = 0.0;      // wall time of the pass, seeding and meshing included
  double skinFill = 0.0;     // at the pass's end; as Packing::skinFill
  double artFill = 0.0;      // at the pass's end; as artFill()
};

struct Packing {
  std::vector<PlacedElement> elements;
  Region container;              // input coordinates
  std::vector<Region> containers;  // the separate containers (parts of `container`), input coordinates
  double canonicalScale = 1.0;   // canonical units per input unit
  int iterations = 0;
  StopReason stopReason = StopReason::IterationCap;
  double skinFill = 0.0;         // (skin area + area blocked by fixed elements) / container area
  std::vector<PackingPass> passes;
  // Fixed elements (Scene::fixed): what they paint inside the container, input coordinates.
  Region fixedArt;
  int vertexCount = 0;
  int springCount = 0;
  // Shape matching (empty / 0 when off): the salient corners (input coordinates), how many
  // elements were docked at them, and the matching stage's time.
  std::vector<Vec2> salientCorners;
  int dockedElements = 0;
  double shapeMatchingSeconds = 0.0;
  Vec2 tile{};                   // W × H of a tileable packing (input units); 0: not tiled
};

// Throws InputError for an empty library or container, or bad options.
Packing packRepulsion(const Scene& scene, const Library& library, const RepulsionOptions& options = {},
                      const RepulsionCallbacks& callbacks = {});
// The same, then a secondary pass with `secondaryLibrary` (4.6) when it is not empty.
Packing packRepulsion(const Scene& scene, const Library& library, const Library& secondaryLibrary,
                      const RepulsionOptions& options = {}, const RepulsionCallbacks& callbacks = {});

// What each placed element paints, as one region per element (the union of its shapes).
std::vector<Region> artOutlines(const Packing& packing);
// Total painted area of the elements and the fixed elements over the container area.
double artFill(const Packing& packing);

}  // namespace pak
