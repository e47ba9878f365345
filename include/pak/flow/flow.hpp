#pragma once
// FLOWPAK (thesis chapter 3): fill containers with elements bent along the streamlines of a
// flow the artist sketches with guide strokes.
//
//   FlowPacking p = packFlow(scene, library, options);
//
// Distances in the options are in canonical units, where l_canvas (the larger side of the
// bounds of the containers and fixed elements, 3.3.1) is 1000; the thesis's "0.005 l_canvas"
// is therefore 5. Results are in the input's own coordinates.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "pak/flow/lr_function.hpp"
#include "pak/flow/skeletal_stroke.hpp"
#include "pak/flow/vector_field.hpp"
#include "pak/geom/art.hpp"
#include "pak/geom/mirror_line.hpp"
#include "pak/geom/scene.hpp"
#include "pak/sim/packing.hpp"
#include "pak/sim/run_options.hpp"

namespace pak {

struct FlowOptions {
  // --- density: 0 (a negative spacing) leaves a value to Pak, which picks the gap that gives
  // about `count` elements and lengths and spacing in proportion (FlowPacking::density)
  int count = 100;            // elements wanted, about (in the output, both halves under a mirror)
  double gap = 0.0;           // s_gap: desired space between streamlines, about an element's width
  double minLength = 0.0;     // s_min
  double maxLength = 0.0;     // s_max
  // Space kept between neighbouring elements and between an element and the walls/fixed
  // elements (the thesis's blobs touch; a margin keeps the negative space visible).
  double spacing = -1.0;
  // --- streamlines (3.3.3)
  double stopRatio = 0.8;     // s_stop = stopRatio × s_gap
  double sampleSpacing = 5.0; // guide, boundary and streamline sampling (0.005 l_canvas)
  int fieldResolution = 256;  // vector field grid cells along the longer side
  // --- blobs and placement (3.3.4, 3.3.5)
  int blobResolution = 512;   // Voronoi grid cells along the longer side
  int lrSamples = 100;        // n_f
  // Each side of a placed element widens where its blob leaves room, part by part, up to this
  // many times its uniform width (fitWidening); 1: uniform, as in the thesis. It widens only
  // into room farther than widenMargin × spacing from the blob's edge (and the others' skins),
  // so that it narrows the wide channels and pockets, not every channel: the negative space
  // gets more even, not only smaller (docs/flowpak.md, "Widening").
  double widen = 1.6;
  double widenMargin = 1.25;
  // --- refinement (3.3.6, Algorithm 2)
  int iterations = 15;
  // Seconds of wall time from the start after which refinement stops, between two of its
  // waves, with the packing as it is then (every accepted step leaves it clean); 0: none.
  // RunOptions::stopRequest stops it the same way.
  double timeLimit = 0.0;
  double growthTolerance = 0.9;  // α: a new placement is kept if its area ≥ α × the old one
  double growthLimit = 5.0;      // g_limit (0.005 l_canvas)
  int maxRotationDegrees = 10;   // rotations ±1°…±max° tried during refinement
  // Pockets: where streamlines stop, converge or part, Jobard–Lefer leaves room no element
  // reaches. After every infillEvery-th refinement iteration, each piece of room at least
  // infillWidth × s_gap wide gets a streamline traced through it and an element on it, kept
  // if its area is at least infillMinArea × the median element's; refinement then grows it
  // with the others. 0: none, as in the thesis (docs/flowpak.md, "Pockets").
  int infillEvery = 5;
  double infillWidth = 0.3;
  double infillMinArea = 0.2;
  // A bent element whose outline or art would cross itself (a turn sharper than it is wide;
  // thesis 3.5 leaves it as future work) goes on the longer side of the spine's sharpest
  // turn, or is not placed there. true: kept folded, as in the thesis.
  bool keepFolds = false;
  double shiftDistanceWeight = 0.1;  // w_d (eq. 3.2)
  double shiftFieldWeight = 1.0;     // w_f
  double shiftFieldPower = 3.0;      // p
  int shiftNeighbours = 150;
  // --- extras (3.4)
  bool fillGaps = false;         // negative-space elements from offset leftover gaps (Fig. 3.15)
  double fillGapsInset = 0.0;    // their inset from the placed elements; 0: spacing / 2
  // Mirror symmetry (Fig. 3.13): pack the part on the line's packed side and reflect it.
  std::optional<MirrorLine> mirror;
  // --- run: the seed; threads for the refinement (the result is the same for any count)
  RunOptions run;
};

struct FlowProgress {
  std::string phase;       // "field", "streamlines", "blobs", "placement", "refinement"
  int iteration = 0;       // refinement iteration (1-based) when phase is "refinement"
  int iterations = 0;
  int elements = 0;
  double elementArea = 0.0;  // total placed element art / free area
};

struct FlowCallbacks {
  std::function<void(const FlowProgress&)> onProgress;
  // Called after the initial placement (iteration 0) and every refinement iteration.
  std::function<void(const struct FlowPacking&, int iteration)> onIteration;
};

struct FlowElement {
  int libraryIndex = -1;     // into the library of its container (-1: a gap-filling shape)
  std::string source;
  std::vector<Shape> art;    // bent art, original paint
  Region outline;            // the bent outline (what the art paints)
  Polyline streamline;       // the spine it is bent along (input coordinates)
  Region blob;               // its sub-region blob
  StrokeFrame frame;
  int container = 0;
  bool fixedSpine = false;   // placed on one of the scene's fixed spines
  double area = 0.0;
};

// The density a run used, canonical units: the options' values, or what Pak worked out.
struct FlowDensity {
  double gap = 0.0, minLength = 0.0, maxLength = 0.0, spacing = 0.0;
};

struct FlowPhaseTimes {
  double field = 0.0, streamlines = 0.0, blobs = 0.0, placement = 0.0, refinement = 0.0, extras = 0.0;
};

struct FlowPacking {
  std::vector<FlowElement> elements;
  std::vector<FlowElement> gapElements;  // --fill-gaps shapes
  Region container;          // union of the containers, input coordinates
  std::vector<Region> containers;
  Region fixedArt;           // what the fixed elements paint
  Region freeSpace;          // containers minus fixed elements
  std::vector<VectorField> fields;  // one per container
  std::vector<Polyline> streamlines;  // as first traced (before extension), all containers
  double canonicalScale = 1.0;  // canonical units per input unit
  FlowDensity density;
  int iterations = 0;         // refinement iterations completed
  // IterationCap: all of them; TimeLimit or Interrupted: refinement stopped early.
  StopReason stopReason = StopReason::IterationCap;
  // Placements tried and accepted during refinement (shift and growth phases together).
  int placementsTried = 0, placementsAccepted = 0;
  int infilled = 0;  // elements added in pockets during refinement (FlowOptions::infillEvery)
  std::vector<double> areaPerIteration;  // total element area after placement and each iteration
  FlowPhaseTimes seconds;
};

// Throws InputError for an empty library, a container without a guide, bad options.
FlowPacking packFlow(const Scene& scene, const Library& library, const FlowOptions& options = {},
                     const FlowCallbacks& callbacks = {});

// Total element (and gap element) area over the free area.
double flowFill(const FlowPacking& packing);

}  // namespace pak
