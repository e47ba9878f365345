#include "pak/repulsion/repulsion_presets.hpp"

#include "pak/error.hpp"

namespace pak {

const std::vector<RepulsionPreset>& repulsionPresets() {
  static const std::vector<RepulsionPreset> presets{
      {.name = "default",
       .description = "Pak's tuned strengths (k_rpl 80, k_ovr 80, k_bdr 300, k_edg 20, negative space 10, pocket pressure 1500)",
       .simulation = repulsionSimulationDefaults(),
       .stop = {}},
      // Thesis 6.4 changes only the edge and shear springs, not the negative-space ones. Its
      // k_edg 5 tears elements apart with our boundary strength (overlaps and limbs outside the
      // heart, docs/secondary-fixed-rigid.md), hence 10.
      {.name = "soft",
       .description = "k_edg 10: elements bend more for evener negative space (toward thesis 6.4's deformable end)",
       .simulation = {.edgeStrength = 10.0},
       .stop = {}},
      // k_edg 1000 as thesis 6.4's rigid packings. Explicit Euler keeps a spring of stiffness k
      // (unit masses) stable only while Δt √k stays below a bound: at Δt 0.1 these springs ring
      // at the velocity cap (strain 4e-2 that never decays), 0.05 is marginal, 0.04 relaxes
      // (tests/repulsion/rigid_stability_test.cpp; docs/secondary-fixed-rigid.md). Eq. 4.7 and
      // the cap then count in simulated time, not iterations: the default rule's window 100,
      // ε 3e-5 and cap 30000 at Δt 0.1, scaled by 0.04 / 0.1 (else the slower per-iteration
      // growth reads as a stall).
      // No pocket pressure: it would bend what is meant to keep its shape.
      {.name = "rigid",
       .description = "k_edg 1000 with time step 0.04 (stable), no pocket pressure: elements keep their shapes (thesis 6.4's rigid end)",
       .simulation = {.edgeStrength = 1000.0, .timeStep = 0.04, .pocketPressure = 0.0},
       .stop = {.stallWindow = 250, .stallEpsilon = 3e-5 * (0.04 / 0.1), .maxIterations = 75000}},
  };
  return presets;
}

void applyRepulsionPreset(const std::string& name, RepulsionOptions& options) {
  for (const RepulsionPreset& preset : repulsionPresets())
    if (preset.name == name) {
      options.simulation = preset.simulation;
      options.stop = preset.stop;
      return;
    }
  std::string known;
  for (const RepulsionPreset& p : repulsionPresets()) known += (known.empty() ? "" : ", ") + p.name;
  throw InputError("--preset", "unknown preset \"" + name + "\" (known: " + known + ")");
}

}  // namespace pak
