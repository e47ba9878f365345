#include "shared_options.hpp"

namespace pak::cli {

const OptionTable<SimulationParameters>& simulationOptions() {
  using P = SimulationParameters;
  // The names before "k-" came from `pak animate`'s first spellings.
  static const OptionTable<P> table{
      {"k-repulsion", field(&P::repulsionStrength), "k_rpl, repulsion strength (eq. 4.2)", {"repulsion"}},
      {"k-overlap", field(&P::overlapStrength), "k_ovr, overlap strength (eq. 4.4)", {"overlap"}},
      {"k-boundary", field(&P::boundaryStrength), "k_bdr, boundary strength (eq. 4.5)", {"boundary"}},
      {"k-edge", field(&P::edgeStrength), "k_edg for edge and shear springs (eq. 4.3): higher keeps shapes stiffer", {"edge"}},
      {"k-negative-space", field(&P::negativeSpaceStrength), "k_edg for negative-space springs", {"negative-space"}},
      {"k-torsion", field(&P::torsionStrength), "k_tor, pull toward the preferred orientation (eq. 4.6): pack, every element toward its seeded angle (0: off); animate, the elements the animation gives an orientation", {"torsion"}},
      {"soft", field(&P::soft), "the soft parameter of eq. 4.2"},
      {"time-step", field(&P::timeStep), "Δt of the explicit Euler step"},
      {"velocity-cap", field(&P::velocityCap), "largest vertex speed (canonical units per unit time)"},
      {"damping", field(&P::damping), "fraction of each vertex's velocity lost per step (0: none)"},
      {"growth-rate", field(&P::growthRate), "k_g: growth factor increase per unit time while an element has room"},
      {"cell-size", length(&P::cellSize), "neighbour grid cell and repulsion reach, canonical units (pack: 0 = 2 × mesh spacing; animate: the exact reach, thesis 0.04 of the container)"},
      {"pocket-pressure", field(&P::pocketPressure), "strength pushing the skin of an element (animate: a slice) that has stopped growing outward where it borders a pocket (no other skin or wall within --pocket-clearance), so it bulges into it (0: none, as in the thesis)"},
      {"pocket-clearance", length(&P::pocketClearance), "with --pocket-pressure: skin-to-skin distance (canonical units) beyond which a skin vertex borders a pocket"},
      {"outside-tolerance", length(&P::outsideTolerance), "an element pushed further than this outside the container stops growing (canonical units; 1e9: never, as in the thesis)"},
  };
  return table;
}

const OptionTable<RunOptions>& runOptions() {
  static const OptionTable<RunOptions> table{
      seedOption(field(&RunOptions::seed)),
      {"threads", field(&RunOptions::threads), "worker threads (0: all cores); the result does not depend on it"},
  };
  return table;
}

}  // namespace pak::cli
