#include "pak/repulsion_presets.hpp"

#include "pak/error.hpp"

namespace pak {

const std::vector<RepulsionPreset>& repulsionPresets() {
  static const std::vector<RepulsionPreset> presets{
      {"default", "Pak's tuned strengths (k_rpl 80, k_ovr 80, k_bdr 300, k_edg 40, negative space 10)"},
      {"soft", "k_edg 5: elements bend a lot for evener negative space (thesis 6.4's deformable end)"},
      {"rigid", "k_edg 1000 with time step 0.04 (stable): elements keep their shapes (thesis 6.4's rigid end)"},
      {"thesis", "the thesis's constants (4.5): k_rpl = k_ovr = k_bdr = 80, k_edg 40, velocity cap 0.5, no damping"},
  };
  return presets;
}

void applyRepulsionPreset(const std::string& name, RepulsionOptions& options) {
  const RepulsionOptions defaults;
  auto strengths = [&](const RepulsionOptions& from) {
    options.repulsionStrength = from.repulsionStrength;
    options.overlapStrength = from.overlapStrength;
    options.boundaryStrength = from.boundaryStrength;
    options.edgeStrength = from.edgeStrength;
    options.negativeSpaceStrength = from.negativeSpaceStrength;
    options.timeStep = from.timeStep;
    options.velocityCap = from.velocityCap;
    options.damping = from.damping;
  };
  strengths(defaults);
  if (name == "default") return;
  if (name == "soft") {
    // Thesis 6.4 changes only the edge and shear springs, not the negative-space ones.
    options.edgeStrength = 5.0;
    return;
  }
  if (name == "rigid") {
    // k_edg 1000 as thesis 6.4's rigid packings. Explicit Euler keeps a spring of stiffness k
    // (unit masses) stable only while Δt √k stays below a bound: at Δt 0.1 these springs ring
    // at the velocity cap (strain 4e-2 that never decays), 0.05 is marginal, 0.04 relaxes
    // (tests/repulsion/rigid_stability_test.cpp; docs/secondary-fixed-rigid.md).
    options.edgeStrength = 1000.0;
    options.timeStep = 0.04;
    return;
  }
  if (name == "thesis") {
    options.boundaryStrength = 80.0;
    options.velocityCap = 0.5;
    options.damping = 0.0;
    return;
  }
  std::string known;
  for (const RepulsionPreset& p : repulsionPresets()) known += (known.empty() ? "" : ", ") + p.name;
  throw InputError("", "unknown preset \"" + name + "\" (known: " + known + ")");
}

}  // namespace pak
