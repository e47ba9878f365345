#pragma once
// The constants only AnimationPak's spacetime simulation has; the forces, integration and
// growth it shares with RepulsionPak are SimulationParameters.
namespace pak {

// Canonical units: x, y in the 1000-wide container frame, t ∈ [0, timeLength].
struct SpacetimeParameters {
  double timeStrength = 4.0;      // time springs
  double targetStrength = 2.0;    // target-point springs (linear pull toward the target)
  double temporalStrength = 1.0;  // k_tmp, eq. 5.2
  double maxGrowth = 1.5;         // g cap (reference shapes have the nominal size at g = 1)
  // A slice grows only while its g stays within this of both neighbouring slices' g, so an
  // element blocked at one moment does not pulse in size around it. 0: off (thesis: slices
  // grow independently).
  double growthSpread = 0.01;
  // A guided element's slice grows while its g is below this share of the median g of the
  // unguided elements' slices of the same index, even when it touches or overlaps them: it
  // pushes through the crowd instead of staying small (the unguided ones give way). 0: off
  // (thesis: guided slices grow by the common rule).
  double guidedGrowth = 0.8;
  // A step of an element's growth moves its skin (the first slice's, at its mean distance
  // from the centre) by at most this many velocity-cap steps (v_max Δt): growth that outruns
  // the springs jams a large element into its neighbours (six stars in the disc at
  // --growth-rate 0.015 ended with 72 of 100 frames outside; docs/animationpak.md,
  // twenty-first round). 0: off (thesis: one rate for every element).
  double growthSpeedCap = 1.2;
  // A guided slice is held on its path by its targets, so the crowd can press it past the wall
  // (by 1–1.5 units on the chase example); it still grows to its guidedGrowth share while no
  // deeper than this, in canonical units (the end projects every vertex back inside).
  // Set to SimulationParameters::outsideTolerance, a pressed guided slice stops growing, as
  // every slice does (the rule before; see docs/animationpak.md).
  double guidedWallGive = 4.0;
  double timeLength = 1000.0;     // canonical length of the t axis
};

}  // namespace pak
