#pragma once
// The loop both packers run (thesis 4.5.2 and 5.5.3): step, record the stall measure, let
// the packer report (progress, snapshots, checkpoints), then ask its stop tests, until one
// of them names a reason or the iteration cap is reached. The packer owns the window, so it
// can save and restore it with the rest of its state.
#include <optional>

#include "sim/stall_window.hpp"

namespace pak {

// `measure()` is the value recorded for the iteration just stepped; `afterStep(iteration)`
// runs the packer's callbacks; `stopTest(window)` returns a reason to stop, or nullopt.
// Returns that reason, or nullopt when the simulation reached `maxIterations`.
template <class Reason, class Simulation, class Measure, class AfterStep, class StopTest>
std::optional<Reason> runUntilStopped(Simulation& simulation, int maxIterations, StallWindow& window,
                                      Measure&& measure, AfterStep&& afterStep, StopTest&& stopTest) {
  while (simulation.iteration() < maxIterations) {
    simulation.step();
    const int iteration = simulation.iteration();
    window.record(iteration, measure());
    afterStep(iteration);
    if (std::optional<Reason> reason = stopTest(window)) return reason;
  }
  return std::nullopt;
}

}  // namespace pak
