#pragma once
// The forces, integration and growth constants of AnimationPak's spacetime simulation.
namespace pak {

// Canonical units: x, y in the 1000-wide container frame, t ∈ [0, timeLength].
struct SpacetimeParameters {
  double repulsionStrength = 80.0;      // k_rpl
  double overlapStrength = 80.0;        // k_ovr
  double boundaryStrength = 300.0;      // k_bdr
  double edgeStrength = 40.0;           // edge and shear springs
  double negativeSpaceStrength = 10.0;  // negative-space springs
  double timeStrength = 4.0;            // time springs
  double targetStrength = 2.0;          // target-point springs (linear pull toward the target)
  double temporalStrength = 1.0;        // k_tmp, eq. 5.2
  double soft = 1.0;                    // ς of eq. 4.2
  double timeStep = 0.1;                // Δt_sim
  double velocityCap = 2.0;
  double damping = 0.2;                 // fraction of velocity lost per step
  double growthRate = 0.01;             // a free slice's g grows by growthRate × Δt per step
  double maxGrowth = 1.5;               // g cap (reference shapes have the nominal size at g = 1)
  // A slice grows only while its g stays within this of both neighbouring slices' g, so an
  // element blocked at one moment does not pulse in size around it. 0: off (thesis: slices
  // grow independently).
  double growthSpread = 0.01;
  double cellSize = 40.0;               // collision grid cell = exact repulsion reach (5.5.1)
  double outsideTolerance = 0.5;        // a slice with a vertex further outside stops growing
  double timeLength = 1000.0;           // canonical length of the t axis
};

}  // namespace pak
