#pragma once
// RepulsionPak (thesis chapter 4): pack a container with deformable elements.
//
//   Packing p = packRepulsion(scene, library, options);
//
// The scene and library are in the input's own coordinates; Pak maps the container's
// bounding square to a canonical 1000 × 1000 frame, simulates there, and maps back, so every
// distance-like option below is in canonical units.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "pak/geom/art.hpp"
#include "pak/geom/scene.hpp"
#include "pak/repulsion/orientation.hpp"
#include "pak/sim/packing.hpp"

namespace pak {

struct RepulsionOptions {
  // --- elements and seeding (4.4)
  double gap = 10.0;              // d_gap between neighbouring elements
  // Boundary/interior sample spacing; 0: max(gap, √(nominal skin area) / 10), which gives
  // each element mesh about 100 vertices (the thesis's Table 4.1 has ~96 per element).
  double meshSpacing = 0.0;
  int count = 0;                  // elements to seed; 0: from elementArea
  double elementArea = 1.0 / 30;  // nominal skin area of an average element / free area
  double initialCoverage = 0.08;  // skins cover this fraction of the container at the start
  // --- forces (4.5); the thesis uses 80/80/80/40/10 with Δt 0.1 on a 1000-wide container
  double repulsionStrength = 80.0;       // k_rpl
  double overlapStrength = 80.0;         // k_ovr
  double boundaryStrength = 300.0;       // k_bdr (thesis 80; see docs/repulsionpak.md)
  double edgeStrength = 40.0;            // k_edg for edge and shear springs
  double negativeSpaceStrength = 10.0;   // k_edg for negative-space springs
  double torsionStrength = 0.0;          // k_tor (0: no preferred orientation)
  // Preferred orientation (eq. 4.6, Figure 4.11): Upright and Field seed every element at its
  // preferred angle and pull it there with k_tor = torsionStrength, or `orientationTorsion`
  // when torsionStrength is 0. Random (default): random seeded angles, torsionStrength only.
  OrientationMode orientation = OrientationMode::Random;
  OrientationField orientationField;     // the angle per position, for OrientationMode::Field
  double orientationTorsion = 10.0;      // k_tor for Upright/Field when torsionStrength is 0
  double soft = 1.0;                     // ς
  double timeStep = 0.1;                 // Δt
  double velocityCap = 2.0;              // |v| ≤ this (thesis: 5 Δt = 0.5; see docs/repulsionpak.md)
  double damping = 0.2;                  // fraction of velocity lost per step (thesis: none)
  double growthRate = 0.01;              // k_g: g += k_g Δt per iteration while not overlapping
  double cellSize = 0.0;                 // neighbour grid cell and repulsion reach; 0: 2 × mesh spacing
  // A mesh with a vertex pushed further than this outside the container stops growing,
  // as one with a vertex inside another mesh does (thesis: no such rule; use a huge value).
  double outsideTolerance = 0.5;
  // --- stopping (4.5.2); whichever comes first
  double targetFill = 0.80;       // skin area / container area
  int stallWindow = 100;          // w of eq. 4.7
  double stallEpsilon = 3e-5;     // ε of eq. 4.7, per iteration
  // Eq. 4.7's area fraction: false, the meshes' rest area (g² × skin area at rest), which
  // moves only by growth; true, the measured skin area as in the thesis (jitters more).
  bool stallOnMeasuredArea = false;
  int maxIterations = 30000;
  // --- secondary elements (4.6), packed when a secondary library is given
  // A secondary's nominal skin is this times a primary's in linear size (the thesis's are small).
  double secondaryScale = 0.4;
  // d_min and d_sep (thesis 5–10 and 10 on a 1000 grid), canonical units. 0: from the nominal
  // secondary skin's size L = √(area): d_min = max(gap, L / 4), d_sep = L, so a pocket takes
  // one secondary about as large as it can grow there.
  double secondaryMinDistance = 0.0;
  double secondarySeparation = 0.0;
  int secondaryResolution = 1000;     // distance transform cells across the canonical frame
  // The secondary pass stops at this total skin fill (primaries, secondaries and fixed
  // elements), else by eq. 4.7 or the iteration cap as the primary pass.
  double secondaryTargetFill = 0.95;
  // --- shape matching (4.7): elements whose shape fits are placed at the container's salient
  // convex corners instead of random seeds and held there by docking springs
  bool shapeMatching = false;
  double dockingStrength = 20.0;  // k of the docking spring from a matched tip vertex to its corner
  // --- tileable packing (thesis 4.8): W × H > 0 packs the periodic rectangle [0, W] × [0, H]
  // (input units) instead of the scene's container; clones in the 8 neighbouring cells act
  // on their originals, so the result tiles the plane. See docs/tiling.md.
  Vec2 tile{};
  // --- run
  std::uint64_t seed = 1;
  int threads = 0;                // 0: all cores; results do not depend on it
};

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
