#pragma once
// The mass-spring constants RepulsionPak (thesis 4.5) and AnimationPak (5.5) share: force
// strengths, the explicit Euler step, growth and the neighbour grid, in canonical units (the
// container's bounding square is 1000 wide). The defaults are RepulsionPak's; the thesis uses
// 80/80/80/40/10 with Δt 0.1.
namespace pak {

struct SimulationParameters {
  double repulsionStrength = 80.0;      // k_rpl (eq. 4.2)
  double overlapStrength = 80.0;        // k_ovr (eq. 4.4)
  double boundaryStrength = 300.0;      // k_bdr (eq. 4.5; thesis 80, see docs/repulsionpak.md)
  double edgeStrength = 40.0;           // k_edg for edge and shear springs (eq. 4.3)
  double negativeSpaceStrength = 10.0;  // k_edg for negative-space springs
  double torsionStrength = 0.0;         // k_tor (eq. 4.6; 0: no pull toward a rest angle)
  double soft = 1.0;                    // ς of eq. 4.2
  double timeStep = 0.1;                // Δt
  double velocityCap = 2.0;             // |v| ≤ this (thesis: 5 Δt = 0.5; see docs/repulsionpak.md)
  double damping = 0.2;                 // fraction of velocity lost per step (thesis: none)
  double growthRate = 0.01;             // k_g: g += k_g Δt per step while an element has room
  // Neighbour grid cell, also the repulsion cut-off; 0 asks the packer for its own (RepulsionPak:
  // 2 × mesh spacing).
  double cellSize = 0.0;
  // An element with a vertex pushed further than this outside the container stops growing,
  // as one with a vertex inside another element does (thesis: no such rule; use a huge value).
  double outsideTolerance = 0.5;
  // RepulsionPak: a triangle squeezed below a quarter of its rest area pushes its vertices
  // apart with this strength, so a thin limb bends instead of folding over (thesis: none, 0).
  double inversionStrength = 5000.0;
  // RepulsionPak: a far part of an element's own skin (a limb bending onto its body) repels
  // with this share of k_rpl, so an element does not fold over itself (thesis: none, 0).
  double selfRepulsion = 1.0;
  // RepulsionPak: a skin vertex of an element that has stopped growing, farther than
  // pocketClearance from every other skin and the wall, is pushed outward with this strength,
  // so the element bulges into the pocket beside it (thesis: none, 0).
  double pocketPressure = 1500.0;
  double pocketClearance = 5.0;
  // RepulsionPak: in the clean-up, the mesh around a crossing of an element's art is pulled
  // toward its best-fit rest shape with this strength per unit of distance, doubled each round
  // the crossing stays (thesis: none, 0).
  double unfoldStrength = 20.0;
};

// Throws InputError naming the option as `pak` spells it (--k-edge, --time-step, …) for a
// negative or non-finite strength or rate, a time step or velocity cap that is not positive,
// or damping outside [0, 1), and for a time step or cell size beyond pak/limits.hpp.
void checkSimulationParameters(const SimulationParameters& parameters);

}  // namespace pak
