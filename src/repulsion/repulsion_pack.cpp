// packRepulsion: RepulsionPak's phases in order (repulsion_phases.hpp).
#include "pak/error.hpp"
#include "pak/repulsion/repulsion.hpp"
#include "pak/repulsion/tiling.hpp"
#include "repulsion/repulsion_phases.hpp"

namespace pak {

Packing packRepulsion(const Scene& scene, const Library& library, const RepulsionOptions& options,
                      const RepulsionCallbacks& callbacks) {
  return packRepulsion(scene, library, Library{}, options, callbacks);
}

Packing packRepulsion(const Scene& scene, const Library& library, const Library& secondaryLibrary,
                      const RepulsionOptions& options, const RepulsionCallbacks& callbacks) try {
  // Tile mode packs the rectangle [0, W] × [0, H] in place of the scene's container.
  const Vec2 tile = options.tiling.size;
  if (isTiled(tile) && !secondaryLibrary.empty()) throw InputError("--secondary", "is not supported with --tile yet");
  if (isTiled(tile) && !isTileScene(scene, tile)) return packRepulsion(tileScene(tile), library, options, callbacks);

  const RepulsionRun run = prepareRepulsion(scene, library, options);
  Seeding seeding = seedPrimaries(run);
  shrinkSeeds(run, seeding);
  ThreadPool pool(options.run.threads);
  PackingSimulation sim = primarySimulation(run, seeding, pool);
  const StopReason reason = simulate(sim, run, options.stop, options.stop.targetFill, 0, callbacks,
                                     [&] { return collectPacking(run, sim, run.types); });
  const int settled = settle(sim, run, options.stop, run.types);
  Packing packing = collectPrimary(run, sim, seeding, reason);
  packing.passes.back().settleIterations = settled;
  if (!secondaryLibrary.empty()) secondaryPass(run, sim, secondaryLibrary, pool, callbacks, packing);
  return packing;
} catch (const InputError& error) {
  throw attributed(error, scene.source);
}

}  // namespace pak
