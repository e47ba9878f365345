// packAnimation: AnimationPak's phases in order (animation_phases.hpp).
#include <chrono>
#include <cmath>
#include <string>

#include "animation/animation_phases.hpp"
#include "animation/frame_separation.hpp"
#include "pak/animation/animation.hpp"
#include "pak/error.hpp"
#include "pak/geom/clipping.hpp"

namespace pak {

const char* toString(AnimationStop reason) {
  switch (reason) {
    case AnimationStop::AllTouching: return "all-slices-touching";
    case AnimationStop::GrowthCap: return "growth-cap";
    case AnimationStop::Stalled: return "stalled";
    case AnimationStop::IterationCap: return "iteration-cap";
    case AnimationStop::TimeLimit: return "time-limit";
    case AnimationStop::Interrupted: return "interrupted";
  }
  return "?";
}

Scene simulatedPart(const Scene& scene, const AnimationOptions& options) {
  if (!options.mirrorX) return scene;
  if (!std::isfinite(*options.mirrorX)) throw InputError("--mirror", "needs a finite x");
  const Box box = bounds(scene.container);
  const Vec2 low = box.min - Vec2{1.0, 1.0}, high{*options.mirrorX, box.max.y + 1.0};
  Scene half = scene;
  half.container = intersect(scene.container, Region{Polygon{Ring{low, {high.x, low.y}, high, {low.x, high.y}}, {}}});
  if (area(half.container) <= 0.0)
    throw InputError("--mirror", "the container has no part left of the line x = " + messageNumber(*options.mirrorX));
  return half;
}

AnimatedPacking packAnimation(const Scene& scene, const Library& library, const AnimationScript& script,
                              const AnimationOptions& options, const AnimationCallbacks& callbacks,
                              const AnimationState* resumeFrom) try {
  using Clock = std::chrono::steady_clock;
  const auto started = Clock::now();
  const Scene simulated = simulatedPart(scene, options);  // the run keeps a reference to it
  const AnimationRun run = prepareAnimation(simulated, library, script, options);
  const AnimationSeeding seeding = seedAnimation(run);
  ThreadPool pool(options.run.threads);
  SpacetimeSimulation sim = spacetimeSimulation(run, seeding, pool, resumeFrom);
  const auto setUp = Clock::now();
  const AnimationStop stop = simulateAnimation(sim, run, callbacks, resumeFrom);
  AnimatedPacking result = collectAnimation(run, seeding, sim, stop, pool);
  result.loop = script.loop;
  if (options.mirrorX) {  // the frames show, and are checked over, the whole container
    result.mirrorX = options.mirrorX;
    result.container = scene.container;
    if (!run.setup.fixedPainted.empty()) result.fixedArt = intersect(run.setup.fixedPainted, scene.container, run.setup.clip);
  }
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
