// The secondary pass (thesis 4.6): seeds in the pockets the primaries left, small elements
// shrunk into them, the primaries frozen where they stopped (they repel but neither move nor
// grow).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "pak/geom/clipping.hpp"
#include "pak/geom/rng.hpp"
#include "repulsion/repulsion_phases.hpp"
#include "repulsion/secondary_seeding.hpp"

namespace pak {
namespace {

// The skin rings of all meshes as one region (canonical units).
Region skinsRegion(const PackingSimulation& sim) {
  std::vector<Region> skins;
  for (const MeshInstance& m : sim.meshes()) {
    const Vec2* v = sim.positions().data() + m.vertexBegin;
    skins.push_back(Region{Polygon{Ring(v, v + m.boundaryCount), {}}});
  }
  return unite(skins);
}

double maxRestRadius(const ElementMesh& mesh) {
  double r = 0.0;
  for (int k = 0; k < mesh.boundaryCount; ++k) r = std::max(r, distance(mesh.mesh.vertices[k], mesh.restCentroid));
  return r;
}

}  // namespace

void secondaryPass(const RepulsionRun& run, const PackingSimulation& primary, const Library& secondaryLibrary,
                   ThreadPool& pool, const RepulsionCallbacks& callbacks, Packing& packing) {
  const auto started = std::chrono::steady_clock::now();
  const RepulsionOptions& options = run.options;
  const PackingSetup& setup = run.setup;
  const double secondaryArea = run.nominalSkinArea * options.secondary.scale * options.secondary.scale;
  SecondarySeedingOptions seeding;
  seeding.minDistance = options.secondary.minDistance > 0.0 ? options.secondary.minDistance
                                                            : std::max(options.gap, 0.25 * std::sqrt(secondaryArea));
  seeding.separation = options.secondary.separation > 0.0 ? options.secondary.separation : std::sqrt(secondaryArea);
  seeding.resolution = options.secondary.resolution;
  const std::vector<SecondarySeed> pockets =
      secondarySeeds(subtract(setup.container, skinsRegion(primary)), bounds(setup.container), seeding);
  PackingPass pass{static_cast<int>(pockets.size()), 0, StopReason::IterationCap, 0.0, packing.skinFill,
                   packing.passes.front().artFill};
  if (!pockets.empty()) {
    const double spacing = options.meshSpacing > 0.0 ? options.meshSpacing
                                                     : std::max(0.5 * options.gap, std::sqrt(secondaryArea) / 7.0);
    std::vector<PreparedElement> types = run.types;
    const int firstSecondary = static_cast<int>(types.size());
    const double scale = librarySkinScale(secondaryLibrary, secondaryArea, options.gap);
    ElementMeshOptions meshOptions;
    meshOptions.gap = options.gap;
    meshOptions.spacing = spacing;
    for (std::size_t i = 0; i < secondaryLibrary.size(); ++i) {
      meshOptions.seed = options.run.seed * 7919 + i;
      types.push_back(prepareElement(secondaryLibrary[i], scale, meshOptions));
    }
    const int secondaryTypes = static_cast<int>(types.size()) - firstSecondary;

    PackingSimulation second(setup.containerIndex, setup.containerArea + setup.blockedArea, run.parameters, pool,
                             run.domain);
    for (const MeshInstance& m : primary.meshes()) {
      const int id = second.addMesh(types[m.type].mesh, m.type, {}, 0.0, m.growth, true);
      second.meshes()[id].container = m.container;
      second.meshes()[id].settleFloor = m.settleFloor;  // the clean-up shrinks none below its first floor
      std::copy(primary.positions().begin() + m.vertexBegin, primary.positions().begin() + m.vertexBegin + m.vertexCount,
                second.positions().begin() + second.meshes()[id].vertexBegin);
    }
    // Random types and angles; each shrunk so its skin fits the pocket's empty disc.
    Rng rng(options.run.seed * 0x9E3779B97F4A7C15ull + 46);
    for (const SecondarySeed& pocket : pockets) {
      const int type = firstSecondary + static_cast<int>(rng.below(static_cast<std::uint64_t>(secondaryTypes)));
      const double angle = rng.uniform(0.0, 2.0 * std::numbers::pi);
      const double g = std::min(1.0, 0.9 * pocket.radius / maxRestRadius(types[type].mesh));
      const int id = second.addMesh(types[type].mesh, type, pocket.position, angle, g);
      if (setup.severalParts())
        if (const int c = setup.partAt(pocket.position); c >= 0) second.meshes()[id].container = c;
    }
    setUpContainers(run, second);
    second.finalize(run.simulationArea);
    const int primaryIterations = primary.iteration();
    auto relabel = [&](Packing p) {
      p.iterations += primaryIterations;
      for (PlacedElement& e : p.elements)
        if (e.libraryIndex >= firstSecondary) {
          e.secondary = true;
          e.libraryIndex -= firstSecondary;
        }
      return p;
    };
    auto collect = [&] { return relabel(collectPacking(run, second, types)); };
    // Eq. 4.7 with ε scaled by the pass's nominal area over the primaries' (the free area):
    // a few small elements change the fill far less per iteration than the primaries did, so
    // the unscaled ε would stop them before they grow (see docs/secondary-fixed-rigid.md).
    RepulsionStopRule stop = options.stop;
    stop.stallEpsilon *= static_cast<double>(pockets.size()) * secondaryArea / setup.containerArea;
    pass.stopReason = simulate(second, run, stop, options.secondary.targetFill, primaryIterations, callbacks, collect);
    // The primaries, frozen while the secondaries grew, are freed and pressed with them into
    // the pockets both left (docs/secondary-fixed-rigid.md); then the clean-up.
    if (options.secondary.pressIterations > 0 && !stoppedEarly(pass.stopReason)) {
      for (std::size_t m = 0; m < primary.meshes().size(); ++m) second.meshes()[m].frozen = primary.meshes()[m].frozen;
      press(second, run, stop, options.secondary.pressIterations);
    }
    pass.settleIterations = settle(second, run, stop, types);
    pass.iterations = second.iteration();
    Packing result = relabel(cleanArt(run, second, types));
    packing.elements = std::move(result.elements);
    packing.iterations = result.iterations;
    packing.skinFill = result.skinFill;
    packing.vertexCount = result.vertexCount;
    packing.springCount = result.springCount;
    packing.stopReason = pass.stopReason;
    pass.skinFill = packing.skinFill;
    pass.artFill = artFill(packing);
  }
  pass.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  packing.passes.push_back(pass);
}

}  // namespace pak
