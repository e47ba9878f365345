#pragma once
// The loop both packers run (thesis 4.5.2 and 5.5.3): step, record the stall measure, ask
// the stop tests, and unless one names a reason, let the packer report (progress, snapshots,
// checkpoints); until the iteration cap. The packer owns the window, so it can save and
// restore it with the rest of its state. The callbacks come after the stop tests so that no
// checkpoint holds the state a run stopped in: resumed, it would take a step more.
#include <optional>

#include "sim/stall_window.hpp"

namespace pak {

// `measure()` is the value recorded for the iteration just stepped; `afterStep(iteration)`
// runs the packer's callbacks (not after the last step); `stopTest(window)` returns a reason to stop, or nullopt.
// Returns that reason, or nullopt when the simulation reached `maxIterations`.
template <class Reason, class Simulation, class Measure, class AfterStep, class StopTest>
std::optional<Reason> runUntilStopped(Simulation& simulation, int maxIterations, StallWindow& window,
                                      Measure&& measure, AfterStep&& afterStep, StopTest&& stopTest) {
  while (simulation.iteration() < maxIterations) {
    simulation.step();
    const int iteration = simulation.iteration();
    window.record(iteration, measure());
    if (std::optional<Reason> reason = stopTest(window)) return reason;
    afterStep(iteration);
  }
  return std::nullopt;
}

}  // namespace pak
