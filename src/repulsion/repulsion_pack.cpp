// packRepulsion: canonical frame, element preparation, seeding, simulation, art replay.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <string>

#include "pak/error.hpp"
#include "pak/geom/clipping.hpp"
#include "pak/geom/rng.hpp"
#include "pak/geom/verify.hpp"
#include "pak/repulsion/repulsion.hpp"
#include "pak/repulsion/tiling.hpp"
#include "repulsion/containers.hpp"
#include "repulsion/corner_docking.hpp"
#include "repulsion/packing_simulation.hpp"
#include "repulsion/secondary_seeding.hpp"
#include "repulsion/seeding.hpp"
#include "sim/canonical_frame.hpp"
#include "sim/simulation_loop.hpp"
#include "sim/stall_window.hpp"

namespace pak {
namespace {

// A library element scaled into canonical units, centred on its outline's centroid.
struct PreparedElement {
  std::vector<Shape> art;
  Region outline;
  ElementMesh mesh;
  std::string source;
};

// Each error names the option as `pak pack` spells it (the flag is also the --config key).
void checkOptions(const RepulsionOptions& o) {
  auto positive = [](double v, const char* option) {
    if (!(v > 0.0) || !std::isfinite(v)) throw InputError(option, "must be a positive number");
  };
  auto nonNegative = [](double v, const char* option) {
    if (!(v >= 0.0) || !std::isfinite(v)) throw InputError(option, "must be a non-negative number");
  };
  positive(o.gap, "--gap");
  nonNegative(o.meshSpacing, "--mesh-spacing");
  if (o.count < 0) throw InputError("--count", "must not be negative");
  if (o.count > 100000) throw InputError("--count", std::to_string(o.count) + " is absurdly large");
  positive(o.elementArea, "--element-area");
  positive(o.initialCoverage, "--initial-coverage");
  checkSimulationParameters(o.simulation);
  positive(o.stop.targetFill, "--target-fill");
  if (o.stop.stallWindow < 1) throw InputError("--stall-window", "must be at least 1");
  nonNegative(o.stop.stallEpsilon, "--stall-epsilon");
  if (o.stop.maxIterations < 0) throw InputError("--max-iterations", "must not be negative");
  if (!(o.secondary.scale > 0.0 && o.secondary.scale <= 10.0)) throw InputError("--secondary-scale", "must be in (0, 10]");
  nonNegative(o.secondary.minDistance, "--secondary-min-distance");
  nonNegative(o.secondary.separation, "--secondary-separation");
  if (o.secondary.resolution < 16 || o.secondary.resolution > 8000)
    throw InputError("--secondary-resolution", "must be between 16 and 8000 cells");
  positive(o.secondary.targetFill, "--secondary-target-fill");
  nonNegative(o.shapeMatching.dockingStrength, "--docking-strength");
  if (o.tiling.size != Vec2{} && !isTiled(o.tiling.size)) throw InputError("--tile", "must be two positive numbers W,H");
  if (o.shapeMatching.enabled && isTiled(o.tiling.size))
    throw InputError("--shape-matching", "needs container corners; a tile has none");
  if (o.orientation.field.axis != 'x' && o.orientation.field.axis != 'y')
    throw InputError("--orientation-field", "the axis must be x or y");
  if (!std::isfinite(o.orientation.field.fromDegrees) || !std::isfinite(o.orientation.field.toDegrees))
    throw InputError("--orientation-field", "the angles must be finite");
  nonNegative(o.orientation.torsion, "--orientation-torsion");
}

// The simulation's constants as the run resolves them: a cell size of 0 asks for
// 2 × mesh spacing, and a preferred orientation without --k-torsion pulls with its own k_tor.
SimulationParameters resolvedParameters(const RepulsionOptions& options, double spacing) {
  SimulationParameters parameters = options.simulation;
  if (parameters.cellSize == 0.0) parameters.cellSize = 2.0 * spacing;
  if (options.orientation.mode != OrientationMode::Random && parameters.torsionStrength == 0.0)
    parameters.torsionStrength = options.orientation.torsion;
  return parameters;
}

std::vector<Shape> transformedArt(const std::vector<Shape>& art, Vec2 centre, double scale) {
  std::vector<Shape> result = art;
  for (Shape& shape : result) {
    shape.strokeWidth *= scale;
    for (Subpath& sub : shape.subpaths)
      for (Vec2& p : sub.points) p = (p - centre) * scale;
  }
  return result;
}

std::vector<PreparedElement> prepareLibrary(const Library& library, double nominalSkinArea, double spacing,
                                            const RepulsionOptions& options) {
  const double scale = librarySkinScale(library, nominalSkinArea, options.gap);

  ElementMeshOptions meshOptions;
  meshOptions.gap = options.gap;
  meshOptions.spacing = spacing;
  std::vector<PreparedElement> prepared;
  for (std::size_t i = 0; i < library.size(); ++i) {
    const ElementArt& e = library[i];
    Vec2 centre = centroid(e.outline);
    PreparedElement p;
    p.source = e.source;
    p.art = transformedArt(e.shapes, centre, scale);
    p.outline = transformed(e.outline, scale, -centre * scale);
    meshOptions.seed = options.run.seed * 7919 + i;
    try {
      p.mesh = buildElementMesh(p.art, p.outline, meshOptions);
    } catch (const InputError& error) {
      throw InputError(e.source, error.what());
    }
    prepared.push_back(std::move(p));
  }
  return prepared;
}

// Skins of the seeded meshes at growth g: overlap-free and inside the container?
bool seedingIsClear(const std::vector<PreparedElement>& types, const std::vector<Seed>& seeds, double g,
                    const std::vector<const RegionIndex*>& containers, Vec2 period = {}) {
  std::vector<Region> skins;
  std::vector<Box> boxes;
  for (const Seed& s : seeds) {
    const ElementMesh& mesh = types[s.type].mesh;
    Ring ring;
    for (int k = 0; k < mesh.boundaryCount; ++k) {
      Vec2 p = s.position + rotated(mesh.mesh.vertices[k] - mesh.restCentroid, s.angle) * g;
      if (!isTiled(period) && !containers[s.container]->query(p, false).inside) return false;  // a tile has no walls
      ring.push_back(p);
    }
    boxes.push_back(bounds(ring));
    skins.push_back(Region{Polygon{std::move(ring), {}}});
  }
  for (std::size_t i = 0; i < skins.size(); ++i)
    for (std::size_t j = i + 1; j < skins.size(); ++j)
      if (boxes[i].overlaps(boxes[j]) && area(intersect(skins[i], skins[j])) > 0.0) return false;
  return !isTiled(period) || !clonesOverlap(skins, period);
}

Packing collectPacking(const PackingSimulation& sim, const std::vector<PreparedElement>& types,
                       const CanonicalFrame& frame, const Region& container) {
  Packing packing;
  packing.container = container;
  packing.canonicalScale = frame.scale;
  packing.iterations = sim.iteration();
  packing.skinFill = sim.fill();
  packing.vertexCount = static_cast<int>(sim.positions().size());
  packing.springCount = static_cast<int>(sim.springCount());
  std::vector<Vec2> artPoints;
  for (const MeshInstance& mesh : sim.meshes()) {
    const PreparedElement& type = types[mesh.type];
    const Vec2* vertices = sim.positions().data() + mesh.vertexBegin;
    replayArt(type.mesh, vertices, artPoints);
    PlacedElement placed;
    placed.libraryIndex = mesh.type;
    placed.source = type.source;
    placed.growth = mesh.growth;
    placed.container = mesh.container;
    placed.art = type.art;
    std::size_t k = 0;
    for (Shape& shape : placed.art) {
      shape.strokeWidth *= mesh.growth / frame.scale;
      for (Subpath& sub : shape.subpaths)
        for (Vec2& p : sub.points) p = frame.toInput(artPoints[k++]);
    }
    int edges = 0;
    for (const Spring& s : type.mesh.springs)
      if (s.kind == SpringKind::Edge) {
        const double strain = std::abs(distance(vertices[s.a], vertices[s.b]) / (s.restLength * mesh.growth) - 1.0);
        placed.maxEdgeStrain = std::max(placed.maxEdgeStrain, strain);
        placed.meanEdgeStrain += strain;
        ++edges;
      }
    if (edges > 0) placed.meanEdgeStrain /= edges;
    for (int v = 0; v < mesh.vertexCount; ++v) placed.meshVertices.push_back(frame.toInput(vertices[v]));
    placed.skin.assign(placed.meshVertices.begin(), placed.meshVertices.begin() + mesh.boundaryCount);
    placed.meshTriangles = type.mesh.mesh.triangles;
    packing.elements.push_back(std::move(placed));
  }
  return packing;
}

// Steps `sim` until the target fill, eq. 4.7 or the iteration cap (4.5.2). Progress and
// snapshots count iterations on from `iterationOffset` (the iterations of earlier passes).
template <class Snapshot>
StopReason simulateUntilStopped(PackingSimulation& sim, const RepulsionOptions& options, double targetFill,
                                int iterationOffset, const RepulsionCallbacks& callbacks, const Snapshot& snapshot) {
  // Eq. 4.7 over a window of the last w + 1 area fractions. The fraction is the meshes' rest
  // area (see restFill): the measured skin area jitters by more than ε from step to step.
  StallWindow window(options.stop.stallWindow);
  auto report = [&] {
    if (!callbacks.onProgress) return;
    RepulsionProgress progress{iterationOffset + sim.iteration(), sim.fill(), sim.growingCount(),
                               static_cast<int>(sim.meshes().size())};
    for (const MeshInstance& m : sim.meshes()) {
      progress.touchingNeighbours += m.overlapping ? 1 : 0;
      progress.againstWall += (!m.overlapping && m.outside) ? 1 : 0;
    }
    callbacks.onProgress(progress);
  };
  const std::optional<StopReason> reason = runUntilStopped<StopReason>(
      sim, options.stop.maxIterations, window,
      [&] { return options.stop.stallOnMeasuredArea ? sim.fill() : sim.restFill(); },
      [&](int iteration) {
        const int total = iterationOffset + iteration;
        if (callbacks.onProgress && callbacks.progressEvery > 0 && total % callbacks.progressEvery == 0) report();
        if (callbacks.onSnapshot && callbacks.snapshotEvery > 0 && total % callbacks.snapshotEvery == 0)
          callbacks.onSnapshot(snapshot());
      },
      [&](const StallWindow& w) -> std::optional<StopReason> {
        if (sim.fill() >= targetFill) return StopReason::TargetFill;
        if (w.full() && w.rms() < options.stop.stallEpsilon) return StopReason::Stalled;
        return std::nullopt;
      });
  report();
  return reason.value_or(StopReason::IterationCap);
}

// Whether no element's art overlaps another's or the fixed art, or leaves the container, by
// more than verifyPacking's tolerance (as `pak pack` checks it).
bool artIsClean(const Packing& packing, const Region& fixedArt) {
  std::vector<Region> checked = artOutlines(packing);
  if (!fixedArt.empty()) checked.push_back(fixedArt);
  PackingCheckOptions options;
  options.areaTolerance = 1e-6 * area(packing.container);
  return verifyPacking(checked, packing.container, options).ok;
}

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

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

Packing packRepulsion(const Scene& scene, const Library& library, const RepulsionOptions& options,
                      const RepulsionCallbacks& callbacks) {
  return packRepulsion(scene, library, Library{}, options, callbacks);
}

Packing packRepulsion(const Scene& scene, const Library& library, const Library& secondaryLibrary,
                      const RepulsionOptions& options, const RepulsionCallbacks& callbacks) try {
  const auto passStart = std::chrono::steady_clock::now();
  checkOptions(options);
  // Tile mode packs the rectangle [0, W] × [0, H] in place of the scene's container.
  if (isTiled(options.tiling.size) && !secondaryLibrary.empty())
    throw InputError("--secondary", "is not supported with --tile yet");
  if (isTiled(options.tiling.size) && !isTileScene(scene, options.tiling.size))
    return packRepulsion(tileScene(options.tiling.size), library, options, callbacks);
  if (library.empty()) throw InputError("--elements", "no elements to pack");
  Box box = bounds(scene.container);
  double containerAreaInput = area(scene.container);
  if (box.empty() || !(containerAreaInput > 0.0)) throw InputError(scene.source, "container has no area");

  const CanonicalFrame frame = CanonicalFrame::of(box);
  Region container = transformed(scene.container, frame.scale, -box.min * frame.scale);
  normalizeOrientation(container);
  // Fixed elements: obstacles. Their art, offset by gap/2 as a skin is, is cut out of the
  // container, so the boundary force (eq. 4.5) and the reflex-corner push keep elements off
  // them; the area they block counts as filled.
  Region fixedArt, obstacles;
  double blockedArea = 0.0;
  if (!scene.fixed.empty()) {
    const ClipOptions clip{1e-7 * std::max(box.width(), box.height())};
    std::vector<Region> painted;
    for (const Shape& shape : scene.fixed) painted.push_back(paintedRegion(shape, clip));
    const Region fixedAll = unite(painted, clip);
    fixedArt = intersect(fixedAll, scene.container, clip);
    const double fullArea = area(container);
    obstacles = offset(transformed(fixedAll, frame.scale, -box.min * frame.scale), 0.5 * options.gap);
    container = subtract(container, obstacles);
    normalizeOrientation(container);
    blockedArea = fullArea - area(container);
    if (!(area(container) > 0.0)) throw InputError(scene.source, "the fixed elements cover the whole container");
  }
  const double containerArea = area(container);
  const int count = options.count > 0 ? options.count : std::max(1, static_cast<int>(std::lround(1.0 / options.elementArea)));
  const double nominalSkinArea = containerArea / count;
  const double spacing = options.meshSpacing > 0.0 ? options.meshSpacing
                                                   : std::max(options.gap, std::sqrt(nominalSkinArea) / 10.0);
  RegionIndex containerIndex(container, std::max(spacing, 5.0));

  // Separate containers (several regions, a previous packing's elements), each with its own
  // library or the run's; their libraries together are the element types.
  const SceneContainers containers = sceneContainers(scene, library);
  const std::vector<Region>& partsInput = containers.regions;
  std::vector<PreparedElement> types = prepareLibrary(containers.combined.empty() ? library : containers.combined,
                                                      nominalSkinArea, spacing, options);
  std::vector<Region> parts;
  std::vector<double> partAreas;
  for (const Region& input : partsInput) {
    parts.push_back(transformed(input, frame.scale, -box.min * frame.scale));
    if (!obstacles.empty()) parts.back() = subtract(parts.back(), obstacles);
    normalizeOrientation(parts.back());
    partAreas.push_back(area(parts.back()));
  }
  std::vector<RegionIndex> partIndexes;  // one per container when there are several
  partIndexes.reserve(parts.size());
  std::vector<const RegionIndex*> partIndex;
  std::vector<ContainerSeeding> partSeeding;
  const std::vector<int> partCounts = seedsPerContainer(partAreas, count, 0.5 * nominalSkinArea);
  for (std::size_t c = 0; c < parts.size(); ++c) {
    if (parts.size() > 1) partIndexes.emplace_back(parts[c], std::max(spacing, 5.0));
    partIndex.push_back(parts.size() > 1 ? &partIndexes.back() : &containerIndex);
    partSeeding.push_back({&parts[c], partIndex[c], partCounts[c], containers.typesOf[c]});
  }
  const Vec2 period = isTiled(options.tiling.size) ? options.tiling.size * frame.scale : Vec2{};
  std::vector<Seed> seeds = seedContainers(partSeeding, options.run.seed, period);
  if (seeds.empty()) throw InputError(scene.source, "container too small to seed any element");
  // Preferred orientation: seeded at the angle the torsion will hold (eq. 4.6).
  const OrientationRamp ramp = options.orientation.mode == OrientationMode::Field
                                   ? OrientationRamp::over(options.orientation.field, bounds(container).min, bounds(container).max)
                                   : OrientationRamp{};
  if (options.orientation.mode != OrientationMode::Random)
    for (Seed& s : seeds) s.angle = ramp.active ? ramp.angleAt(s.position) : 0.0;
  // Shape matching (4.7): elements that fit the salient corners take the nearest seeds.
  std::optional<CornerDocking> docking;
  const auto matchingStart = std::chrono::steady_clock::now();
  if (options.shapeMatching.enabled) {
    std::vector<const ElementMesh*> meshes;
    std::vector<const Region*> outlines;
    for (const PreparedElement& t : types) { meshes.push_back(&t.mesh); outlines.push_back(&t.outline); }
    docking.emplace(container, meshes, outlines, options.gap, seeds);
  }
  const double matchingSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - matchingStart).count();

  // Shrink everything alike until the seeded skins cover `initialCoverage` without overlap.
  double seededSkin = 0.0;
  for (const Seed& s : seeds) seededSkin += types[s.type].mesh.skinArea;
  double g0 = std::sqrt(options.initialCoverage * containerArea / seededSkin);
  // A docked seed may have moved to another container's corner: it belongs where it now is.
  auto reassignContainers = [&] {
    if (parts.size() > 1)
      for (Seed& s : seeds)
        for (std::size_t c = 0; c < parts.size(); ++c)
          if (partIndex[c]->query(s.position, false).inside) { s.container = static_cast<int>(c); break; }
  };
  if (docking) { docking->position(g0, containerIndex, seeds); reassignContainers(); }
  for (int attempt = 0; attempt < 30 && !seedingIsClear(types, seeds, g0, partIndex, period); ++attempt) {
    g0 *= 0.9;
    if (docking) { docking->position(g0, containerIndex, seeds); reassignContainers(); }
  }

  const SimulationParameters parameters = resolvedParameters(options, spacing);
  const PackingDomain domain{.occupiedArea = blockedArea, .period = period};

  ThreadPool pool(options.run.threads);
  PackingSimulation sim(containerIndex, containerArea + blockedArea, parameters, pool, domain);
  for (const Seed& s : seeds) sim.meshes()[sim.addMesh(types[s.type].mesh, s.type, s.position, s.angle, g0)].container = s.container;
  // Both passes see the same containers (one boundary each), reflex corners and orientation.
  auto setUpContainers = [&](PackingSimulation& simulation) {
    if (parts.size() > 1) {
      std::vector<PackingSimulation::Corner> corners;
      for (std::size_t c = 0; c < parts.size(); ++c)
        for (PackingSimulation::Corner corner : PackingSimulation::reflexCorners(parts[c])) {
          corner.container = static_cast<int>(c);
          corners.push_back(corner);
        }
      simulation.setContainerCorners(std::move(corners));
      simulation.setContainerParts(partIndex);
    } else {
      simulation.setContainerCorners(PackingSimulation::reflexCorners(container));
    }
    if (ramp.active) simulation.setOrientationField(ramp);
  };
  setUpContainers(sim);
  if (docking) sim.setDocks(docking->docks(sim), options.shapeMatching.dockingStrength);
  Box area = bounds(container);
  Vec2 margin{0.1 * kCanonicalSide, 0.1 * kCanonicalSide};
  area.add(area.min - margin);
  area.add(area.max + margin);
  sim.finalize(area);

  const StopReason reason = simulateUntilStopped(sim, options, options.stop.targetFill, 0, callbacks, [&] {
    return collectPacking(sim, types, frame, scene.container);
  });
  Packing packing = collectPacking(sim, types, frame, scene.container);
  if (!isTiled(options.tiling.size) && !artIsClean(packing, fixedArt) && sim.projectInside() > 0)
    packing = collectPacking(sim, types, frame, scene.container);
  packing.stopReason = reason;
  packing.containers = partsInput;
  if (docking) {
    for (const SalientCorner& c : docking->match().corners) packing.salientCorners.push_back(frame.toInput(c.position));
    packing.dockedElements = docking->dockedCount();
    packing.shapeMatchingSeconds = matchingSeconds;
  }
  packing.tile = isTiled(options.tiling.size) ? options.tiling.size : Vec2{};
  packing.fixedArt = fixedArt;
  packing.passes.push_back({static_cast<int>(sim.meshes().size()), sim.iteration(), reason, secondsSince(passStart),
                            packing.skinFill, artFill(packing)});
  if (secondaryLibrary.empty()) return packing;

  // Secondary elements (4.6): seeds in the pockets the primaries left, small elements shrunk
  // into them, the primaries frozen where they stopped (they repel but neither move nor grow).
  const auto secondaryStart = std::chrono::steady_clock::now();
  const double secondaryArea = nominalSkinArea * options.secondary.scale * options.secondary.scale;
  SecondarySeedingOptions secondarySeeding;
  secondarySeeding.minDistance = options.secondary.minDistance > 0.0 ? options.secondary.minDistance
                                                                    : std::max(options.gap, 0.25 * std::sqrt(secondaryArea));
  secondarySeeding.separation = options.secondary.separation > 0.0 ? options.secondary.separation : std::sqrt(secondaryArea);
  secondarySeeding.resolution = options.secondary.resolution;
  const std::vector<SecondarySeed> pockets =
      secondarySeeds(subtract(container, skinsRegion(sim)), bounds(container), secondarySeeding);
  PackingPass secondPass{static_cast<int>(pockets.size()), 0, StopReason::IterationCap, 0.0, packing.skinFill,
                         packing.passes.front().artFill};
  if (!pockets.empty()) {
    const double secondarySpacing = options.meshSpacing > 0.0 ? options.meshSpacing
                                                              : std::max(0.5 * options.gap, std::sqrt(secondaryArea) / 7.0);
    std::vector<PreparedElement> allTypes = types;
    const int firstSecondary = static_cast<int>(allTypes.size());
    for (PreparedElement& e : prepareLibrary(secondaryLibrary, secondaryArea, secondarySpacing, options))
      allTypes.push_back(std::move(e));
    const int secondaryTypes = static_cast<int>(allTypes.size()) - firstSecondary;

    PackingSimulation second(containerIndex, containerArea + blockedArea, parameters, pool, domain);
    for (const MeshInstance& m : sim.meshes()) {
      const int id = second.addMesh(allTypes[m.type].mesh, m.type, {}, 0.0, m.growth, true);
      second.meshes()[id].container = m.container;
      std::copy(sim.positions().begin() + m.vertexBegin, sim.positions().begin() + m.vertexBegin + m.vertexCount,
                second.positions().begin() + second.meshes()[id].vertexBegin);
    }
    // Random types and angles; each shrunk so its skin fits the pocket's empty disc.
    Rng rng(options.run.seed * 0x9E3779B97F4A7C15ull + 46);
    for (const SecondarySeed& pocket : pockets) {
      const int type = firstSecondary + static_cast<int>(rng.below(static_cast<std::uint64_t>(secondaryTypes)));
      const double angle = rng.uniform(0.0, 2.0 * 3.14159265358979323846);
      const double g = std::min(1.0, 0.9 * pocket.radius / maxRestRadius(allTypes[type].mesh));
      const int id = second.addMesh(allTypes[type].mesh, type, pocket.position, angle, g);
      for (std::size_t c = 0; parts.size() > 1 && c < parts.size(); ++c)
        if (partIndex[c]->query(pocket.position, false).inside) { second.meshes()[id].container = static_cast<int>(c); break; }
    }
    setUpContainers(second);
    second.finalize(area);
    const int primaryIterations = sim.iteration();
    auto collect = [&] {
      Packing p = collectPacking(second, allTypes, frame, scene.container);
      p.iterations += primaryIterations;
      for (PlacedElement& e : p.elements)
        if (e.libraryIndex >= firstSecondary) { e.secondary = true; e.libraryIndex -= firstSecondary; }
      return p;
    };
    // Eq. 4.7 with ε scaled by the pass's nominal area over the primaries' (the free area):
    // a few small elements change the fill far less per iteration than the primaries did, so
    // the unscaled ε would stop them before they grow (see docs/secondary-fixed-rigid.md).
    RepulsionOptions secondOptions = options;
    secondOptions.stop.stallEpsilon *= static_cast<double>(pockets.size()) * secondaryArea / containerArea;
    secondPass.stopReason =
        simulateUntilStopped(second, secondOptions, options.secondary.targetFill, primaryIterations, callbacks, collect);
    secondPass.iterations = second.iteration();
    Packing result = collect();
    if (!artIsClean(result, fixedArt) && second.projectInside() > 0) result = collect();
    packing.elements = std::move(result.elements);
    packing.iterations = result.iterations;
    packing.skinFill = result.skinFill;
    packing.vertexCount = result.vertexCount;
    packing.springCount = result.springCount;
    packing.stopReason = secondPass.stopReason;
    secondPass.skinFill = packing.skinFill;
    secondPass.artFill = artFill(packing);
  }
  secondPass.seconds = secondsSince(secondaryStart);
  packing.passes.push_back(secondPass);
  return packing;
} catch (const InputError& error) {
  throw attributed(error, scene.source);
}

}  // namespace pak
