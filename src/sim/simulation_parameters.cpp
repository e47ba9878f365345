#include "pak/sim/simulation_parameters.hpp"

#include <cmath>
#include <utility>

#include "pak/error.hpp"
#include "pak/limits.hpp"

namespace pak {

void checkSimulationParameters(const SimulationParameters& p) {
  using P = SimulationParameters;
  const std::pair<double P::*, const char*> nonNegative[] = {
      {&P::repulsionStrength, "--k-repulsion"}, {&P::overlapStrength, "--k-overlap"},
      {&P::boundaryStrength, "--k-boundary"},   {&P::edgeStrength, "--k-edge"},
      {&P::negativeSpaceStrength, "--k-negative-space"}, {&P::torsionStrength, "--k-torsion"},
      {&P::soft, "--soft"},                     {&P::growthRate, "--growth-rate"},
      {&P::cellSize, "--cell-size"},           {&P::inversionStrength, "--k-inversion"},
      {&P::selfRepulsion, "--self-repulsion"},
      {&P::pocketPressure, "--pocket-pressure"}, {&P::pocketClearance, "--pocket-clearance"},
      {&P::unfoldStrength, "--k-unfold"},
  };
  for (const auto& [member, option] : nonNegative)
    if (!(p.*member >= 0.0) || !std::isfinite(p.*member)) throw InputError(option, "must be a non-negative number");
  // An infinite tolerance is the thesis's rule: nothing outside stops growth.
  if (!(p.outsideTolerance >= 0.0)) throw InputError("--outside-tolerance", "must not be negative");
  const std::pair<double P::*, const char*> positive[] = {{&P::timeStep, "--time-step"},
                                                          {&P::velocityCap, "--velocity-cap"}};
  for (const auto& [member, option] : positive)
    if (!(p.*member > 0.0) || !std::isfinite(p.*member)) throw InputError(option, "must be a positive number");
  if (!(p.damping >= 0.0 && p.damping < 1.0)) throw InputError("--damping", "must be in [0, 1)");
  if (p.timeStep > limits::kMaxTimeStep)
    throw InputError("--time-step", "must be at most " + messageNumber(limits::kMaxTimeStep) + " (thesis: 0.1)");
  // 0 asks the packer for its own cell (pack: 2 × mesh spacing); animate requires one.
  if (p.cellSize != 0.0 && !(p.cellSize >= limits::kMinCellSize && p.cellSize <= limits::kMaxCellSize))
    throw InputError("--cell-size", "must be " + messageNumber(limits::kMinCellSize) + " to " +
                                        messageNumber(limits::kMaxCellSize) + " canonical units (0: automatic)");
}

}  // namespace pak
