#pragma once
// The simulator constants the PackingSimulation unit tests were written for: the thesis's k_bdr
// 80 and |v| ≤ 0.5, no damping, a 30-unit grid and a 2-unit outside tolerance (RepulsionPak's
// own defaults, SimulationParameters{}, differ).
#include "pak/sim/simulation_parameters.hpp"

namespace pak::test {

inline SimulationParameters thesisParameters() {
  return {.boundaryStrength = 80.0, .velocityCap = 0.5, .damping = 0.0, .cellSize = 30.0, .outsideTolerance = 2.0};
}

}  // namespace pak::test
