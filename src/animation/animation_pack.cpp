// packAnimation: AnimationPak's phases in order (animation_phases.hpp).
#include <chrono>

#include "animation/animation_phases.hpp"
#include "animation/frame_separation.hpp"
#include "pak/animation/animation.hpp"
#include "pak/error.hpp"

namespace pak {

const char* toString(AnimationStop reason) {
  switch (reason) {
    case AnimationStop::AllTouching: return "all-slices-touching";
    case AnimationStop::GrowthCap: return "growth-cap";
    case AnimationStop::Stalled: return "stalled";
    case AnimationStop::IterationCap: return "iteration-cap";
    case AnimationStop::TimeLimit: return "time-limit";
  }
  return "?";
}

AnimatedPacking packAnimation(const Scene& scene, const Library& library, const AnimationScript& script,
                              const AnimationOptions& options, const AnimationCallbacks& callbacks,
                              const AnimationState* resumeFrom) try {
  using Clock = std::chrono::steady_clock;
  const auto started = Clock::now();
  const AnimationRun run = prepareAnimation(scene, library, script, options);
  const AnimationSeeding seeding = seedAnimation(run);
  ThreadPool pool(options.run.threads);
  SpacetimeSimulation sim = spacetimeSimulation(run, seeding, pool, resumeFrom);
  const auto setUp = Clock::now();
  const AnimationStop stop = simulateAnimation(sim, run, callbacks, resumeFrom);
  AnimatedPacking result = collectAnimation(run, seeding, sim, stop, pool);
  result.loop = script.loop;
  const auto separating = Clock::now();
  separateAnimation(result, options.frameSeparation, pool);
  result.separationSeconds = std::chrono::duration<double>(Clock::now() - separating).count();
  result.setupSeconds = std::chrono::duration<double>(setUp - started).count();
  result.seconds = std::chrono::duration<double>(Clock::now() - started).count();
  return result;
} catch (const InputError& error) {
  throw attributed(error, scene.source);
}

}  // namespace pak
