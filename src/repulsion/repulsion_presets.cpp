#include "pak/repulsion/repulsion_presets.hpp"

#include <cmath>

#include "pak/error.hpp"

namespace pak {

const std::vector<RepulsionPreset>& repulsionPresets() {
  static const std::vector<RepulsionPreset> presets{
      {"default", "Pak's tuned strengths (k_rpl 80, k_ovr 80, k_bdr 300, k_edg 40, negative space 10)"},
      {"soft", "k_edg 10: elements bend more for evener negative space (toward thesis 6.4's deformable end)"},
      {"rigid", "k_edg 1000 with time step 0.04 (stable): elements keep their shapes (thesis 6.4's rigid end)"},
  };
  return presets;
}

void applyRepulsionPreset(const std::string& name, RepulsionOptions& options) {
  const RepulsionOptions defaults;
  auto reset = [&] {
    options.repulsionStrength = defaults.repulsionStrength;
    options.overlapStrength = defaults.overlapStrength;
    options.boundaryStrength = defaults.boundaryStrength;
    options.edgeStrength = defaults.edgeStrength;
    options.negativeSpaceStrength = defaults.negativeSpaceStrength;
    options.timeStep = defaults.timeStep;
    options.stallWindow = defaults.stallWindow;
    options.stallEpsilon = defaults.stallEpsilon;
    options.maxIterations = defaults.maxIterations;
  };
  if (name == "default") return reset();
  if (name == "soft") {
    // Thesis 6.4 changes only the edge and shear springs, not the negative-space ones. Its
    // k_edg 5 tears elements apart with our boundary strength (overlaps and limbs outside the
    // heart, docs/secondary-fixed-rigid.md), hence 10.
    reset();
    options.edgeStrength = 10.0;
    return;
  }
  if (name == "rigid") {
    // k_edg 1000 as thesis 6.4's rigid packings. Explicit Euler keeps a spring of stiffness k
    // (unit masses) stable only while Δt √k stays below a bound: at Δt 0.1 these springs ring
    // at the velocity cap (strain 4e-2 that never decays), 0.05 is marginal, 0.04 relaxes
    // (tests/repulsion/rigid_stability_test.cpp; docs/secondary-fixed-rigid.md).
    reset();
    const double ratio = 0.04 / defaults.timeStep;
    options.edgeStrength = 1000.0;
    options.timeStep = 0.04;
    // Eq. 4.7 per unit of simulated time, not per iteration: the same window and threshold
    // in time as the default step (else the slower per-iteration growth reads as a stall).
    options.stallWindow = static_cast<int>(std::lround(defaults.stallWindow / ratio));
    options.stallEpsilon = defaults.stallEpsilon * ratio;
    options.maxIterations = static_cast<int>(std::lround(defaults.maxIterations / ratio));
    return;
  }
  std::string known;
  for (const RepulsionPreset& p : repulsionPresets()) known += (known.empty() ? "" : ", ") + p.name;
  throw InputError("", "unknown preset \"" + name + "\" (known: " + known + ")");
}

}  // namespace pak
