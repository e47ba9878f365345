#pragma once
// What packRepulsion takes: the element and seeding options, then one sub-struct per concern.
// Every distance-like option is in canonical units (the container's bounding square is 1000 wide).
#include "pak/geom/vec2.hpp"
#include "pak/repulsion/orientation.hpp"
#include "pak/sim/run_options.hpp"
#include "pak/sim/simulation_parameters.hpp"

namespace pak {

// When a pass stops (4.5.2): whichever comes first.
struct RepulsionStopRule {
  double targetFill = 0.90;  // skin area / container area (measured: pocket pressure's bulges count)
  int stallWindow = 100;     // w of eq. 4.7
  double stallEpsilon = 3e-5;  // ε of eq. 4.7, per iteration
  // Eq. 4.7's area fraction: false, the meshes' rest area (g² × skin area at rest), which
  // moves only by growth; true, the measured skin area as in the thesis (jitters more).
  bool stallOnMeasuredArea = false;
  int maxIterations = 30000;
  double timeLimit = 0.0;    // seconds of wall time from the start of the run; 0: none
  // The clean-up after a pass stops (docs/repulsionpak.md): nothing grows, and every element
  // with a vertex deeper than a quarter of the gap inside another one (or outside the
  // container beyond outsideTolerance) shrinks a growth step,
  // for at most this many iterations, until none is. 0: none (the thesis).
  int settleIterations = 1500;
};

// Secondary elements (4.6), packed when a secondary library is given.
struct SecondaryPassOptions {
  // A secondary's nominal skin is this times a primary's in linear size (the thesis's are small).
  double scale = 0.4;
  // d_min and d_sep (thesis 5–10 and 10 on a 1000 grid). 0: from the nominal secondary skin's
  // size L = √(area): d_min = max(gap, L / 4), d_sep = L, so a pocket takes one secondary
  // about as large as it can grow there.
  double minDistance = 0.0;
  double separation = 0.0;
  int resolution = 1000;  // distance transform cells across the canonical frame
  // The pass stops at this total skin fill (primaries, secondaries and fixed elements), else
  // by eq. 4.7 or the iteration cap as the primary pass.
  double targetFill = 0.95;
  // After the pass stops, the primaries (frozen through it) are freed and every element is
  // pressed into the pockets left for this many iterations, nothing growing, before the
  // clean-up. 0: none (the thesis: the primaries stay where the primary pass left them).
  int pressIterations = 300;
};

// Shape matching (4.7): elements whose shape fits are placed at the container's salient
// convex corners instead of random seeds and held there by docking springs.
struct CornerDockingOptions {
  bool enabled = false;
  double dockingStrength = 20.0;  // k of the spring from a matched tip vertex to its corner
};

// Tileable packing (4.8): W × H > 0 packs the periodic rectangle [0, W] × [0, H] (input units)
// instead of the scene's container; clones in the 8 neighbouring cells act on their
// originals, so the result tiles the plane. See docs/tiling.md.
struct TilingOptions {
  Vec2 size{};
};

// Preferred orientation (eq. 4.6, Figure 4.11): Upright and Field seed every element at its
// preferred angle and pull it there with k_tor = SimulationParameters::torsionStrength, or
// `torsion` when that is 0. Random: random seeded angles, torsionStrength only.
struct OrientationOptions {
  OrientationMode mode = OrientationMode::Random;
  OrientationField field;  // the angle per position, for OrientationMode::Field
  double torsion = 10.0;
};

// RepulsionPak's forces: the shared defaults with edge springs half as stiff as the thesis's
// k_edg 40, since the pocket pressure now does the bending into pockets that stiffer springs
// resisted (docs/repulsionpak.md, "Even negative space").
inline SimulationParameters repulsionSimulationDefaults() {
  SimulationParameters p;
  p.edgeStrength = 20.0;
  return p;
}

struct RepulsionOptions {
  // --- elements and seeding (4.4)
  // d_gap between neighbouring elements. 8 gives channels as wide as the thesis's Fig. 4.1d
  // (median half-width 7.7 against 7.1 per 1000; docs/repulsionpak.md).
  double gap = 8.0;
  // Boundary/interior sample spacing; 0: max(gap, √(nominal skin area) / 10), which gives
  // each element mesh about 100 vertices (the thesis's Table 4.1 has ~96 per element).
  double meshSpacing = 0.0;
  int count = 0;                  // elements to seed; 0: from elementArea
  double elementArea = 1.0 / 30;  // nominal skin area of an average element / free area
  double initialCoverage = 0.08;  // skins cover this fraction of the container at the start
  SimulationParameters simulation = repulsionSimulationDefaults();  // forces (4.5), integration, growth, grid
  RepulsionStopRule stop;
  SecondaryPassOptions secondary;
  CornerDockingOptions shapeMatching;
  TilingOptions tiling;
  OrientationOptions orientation;
  // The output draws each element's art on its mesh with the thesis's piecewise-linear map, as
  // the simulation's checks do, instead of a smoothed one (replayDrawnArt): the art then bends
  // a little at every triangle edge, and its fitted curves need about twice the points.
  bool linearArt = false;
  RunOptions run;
};

}  // namespace pak
