#pragma once
// What packAnimation takes. Distances are in canonical units (the container's bounding square
// is 1000 wide), times along the t axis of SpacetimeParameters::timeLength.
#include <optional>

#include "pak/animation/spacetime_parameters.hpp"
#include "pak/sim/run_options.hpp"
#include "pak/sim/simulation_parameters.hpp"

namespace pak {

// When the spacetime simulation stops (5.5.3): whichever comes first, or when every slice
// reached the growth cap (SpacetimeParameters::maxGrowth).
struct AnimationStopRule {
  // Every slice is this close to another element or the wall: the thesis's rule, at 6 (0.006 of
  // the container). 0: off. In Pak a slice in contact keeps growing while it overlaps nothing,
  // and pocket pressure draws it on, so the rule ended runs with hundreds of slices still
  // growing (the stars' seed 3 at 890 iterations, negative space 0.533: docs/animationpak.md,
  // twentieth round); the stall rule ends them instead.
  double closeness = 0.0;
  // The slices' mean growth rose by less than this over the last stallWindow iterations: two
  // free iterations' growth (growthRate × Δt = 0.0015 each), as 0.002 was at the rate of 0.01.
  // 0.005 stopped the stars a few hundred iterations early, with pockets still closing
  // (docs/animationpak.md, third and twenty-first rounds).
  double stallGrowth = 0.003;
  int stallWindow = 100;
  int maxIterations = 3000;
  double timeLimit = 0.0;  // seconds of wall time from the start of the run; 0: none
  // The settle after the stop (not after a time limit or an interruption, which also end it):
  // this many more steps in which nothing grows and the overlap force (eq. 4.4) has
  // settleOverlapStrength. The run ends with about half the slices pressed into a neighbour;
  // the stronger pull lets their skins give way there instead of the frame separation
  // shrinking whole elements (docs/animationpak.md, twelfth round). 0: none, as in the thesis.
  int settleIterations = 100;
  double settleOverlapStrength = 1500.0;
};

// A frame between two slices interpolates them, and two elements passing each other can
// overlap there by a sliver (thesis 5.8). Each element of a frame in an overlapping pair (or
// out of the container) by more than areaTolerance × the container's area, as verifyPacking
// sees the art, is scaled about its skin's centre by `step`, for at most `rounds` rounds, until
// none is. rounds = 0: frames as interpolated (the thesis).
struct FrameSeparationOptions {
  int rounds = 20;  // at most 0.99^20 = 0.82 of an element's size (10 left a chase frame overlapping)
  double step = 0.99;
  double areaTolerance = 1e-6;
  int samples = 0;     // frames checked over t ∈ [0, 1]; 0: twice the slices
  double ramp = 0.05;  // an element's shrinking eases in and out over this much of t
  // By default an unguided element overlapping a guided one first moves away from where they
  // overlap, by (1 − step) of its radius per round, for at most twice `rounds` rounds; only
  // then do the two shrink. A guided element is held on its path, and shrinking both about their
  // centres cannot take a tail off its back (docs/animationpak.md, sixth round). true: every
  // offending element shrinks, as before.
  bool shrinkOnly = false;
  // By default two unguided elements that overlap also move apart first, each away from where
  // they overlap: a sliver costs a small eased shift, not a smaller element (docs/animationpak.md,
  // seventh round). true: they shrink at once (only a guided element's partner moves).
  bool shrinkPairs = false;
};

struct AnimationOptions {
  int slices = 0;                 // n_s; 0: the script's
  // Nominal skin area of one element (growth 1) as a fraction of the container's area;
  // 0: 1 / (number of elements), the size at which they would exactly fill it.
  double elementArea = 0.0;
  double gap = 0.08;              // d_gap as a fraction of the nominal element size (thesis 0.08)
  double meshSpacing = 0.0;       // slice mesh spacing, canonical units; 0: nominal size / 4
  double initialScale = 0.1;      // elements start shrunk to this (thesis 5–10 %), or less to fit
  // RepulsionPak's forces, but the grid cell is the exact repulsion reach (5.5.1), k_tor acts on
  // the elements with a preferred orientation only, the edge springs are half the thesis's 40,
  // as in `pak pack`: softer slices fill the pockets (docs/animationpak.md, third round), and
  // the slices grow 1.5 times as fast: the stars and the chase pack in 13–32 % fewer steps,
  // as evenly as the quality issue asks (twenty-first round). 0.02 jams the slices into one
  // another; SpacetimeParameters::growthSpeedCap slows large elements.
  SimulationParameters simulation{
      .edgeStrength = 20.0, .torsionStrength = 10.0, .growthRate = 0.015, .cellSize = 40.0};
  SpacetimeParameters spacetime;
  AnimationStopRule stop;
  FrameSeparationOptions frameSeparation;
  RunOptions run;
  // Mirror symmetry (thesis Fig. 5.18): simulate the part of the container left of the
  // vertical line x = mirrorX (input units) and show it reflected across the line as well.
  std::optional<double> mirrorX;
};

}  // namespace pak
