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

const char* toString(StopReason reason) {
  switch (reason) {
    case StopReason::TargetFill: return "target-fill";
    case StopReason::Stalled: return "stalled";
    case StopReason::IterationCap: return "iteration-cap";
  }
  return "?";
}

namespace {

// A library element scaled into canonical units, centred on its outline's centroid.
struct PreparedElement {
  std::vector<Shape> art;
  Region outline;
  ElementMesh mesh;
  std::string source;
};

void checkOptions(const RepulsionOptions& o) {
  auto positive = [](double v, const char* name) {
    if (!(v > 0.0) || !std::isfinite(v)) throw InputError("", std::string(name) + " must be a positive number");
  };
  positive(o.gap, "gap");
  positive(o.elementArea, "element area");
  positive(o.initialCoverage, "initial coverage");
  positive(o.timeStep, "time step");
  positive(o.velocityCap, "velocity cap");
  positive(o.targetFill, "target fill");
  if (!(o.outsideTolerance >= 0.0)) throw InputError("", "outside tolerance must not be negative");
  if (!(o.damping >= 0.0 && o.damping < 1.0)) throw InputError("", "damping must be in [0, 1)");
  if (o.meshSpacing < 0.0 || o.count < 0 || o.maxIterations < 0 || o.stallWindow < 1 || o.cellSize < 0.0)
    throw InputError("", "mesh spacing, count, cell size, max iterations and stall window must not be negative");
  if (!(o.dockingStrength >= 0.0) || !std::isfinite(o.dockingStrength))
    throw InputError("", "docking strength must be a non-negative number");
  if (o.tile != Vec2{} && !isTiled(o.tile)) throw InputError("", "tile size must be two positive numbers W,H");
  if (o.shapeMatching && isTiled(o.tile)) throw InputError("", "shape matching needs container corners; a tile has none");
  if (o.count > 100000) throw InputError("", "count " + std::to_string(o.count) + " is absurdly large");
  if (!(o.secondaryScale > 0.0 && o.secondaryScale <= 10.0)) throw InputError("", "secondary scale must be in (0, 10]");
  if (!(o.secondaryMinDistance >= 0.0) || !(o.secondarySeparation >= 0.0) || !std::isfinite(o.secondaryMinDistance) ||
      !std::isfinite(o.secondarySeparation))
    throw InputError("", "secondary minimum distance and separation must be non-negative numbers");
  if (o.secondaryResolution < 16 || o.secondaryResolution > 8000)
    throw InputError("", "secondary resolution must be between 16 and 8000 cells");
  positive(o.secondaryTargetFill, "secondary target fill");
  if (o.orientationField.axis != 'x' && o.orientationField.axis != 'y')
    throw InputError("", "orientation field axis must be x or y");
  if (!std::isfinite(o.orientationField.fromDegrees) || !std::isfinite(o.orientationField.toDegrees))
    throw InputError("", "orientation field angles must be finite");
  if (!(o.orientationTorsion >= 0.0) || !std::isfinite(o.orientationTorsion))
    throw InputError("", "orientation torsion must be a non-negative number");
  for (double k : {o.repulsionStrength, o.overlapStrength, o.boundaryStrength, o.edgeStrength,
                   o.negativeSpaceStrength, o.torsionStrength, o.soft, o.growthRate, o.stallEpsilon})
    if (!(k >= 0.0) || !std::isfinite(k)) throw InputError("", "force strengths and rates must be non-negative numbers");
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
    meshOptions.seed = options.seed * 7919 + i;
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
      shape.id.clear();  // copies of one element must not repeat its SVG ids
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
  StallWindow window(options.stallWindow);
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
      sim, options.maxIterations, window,
      [&] { return options.stallOnMeasuredArea ? sim.fill() : sim.restFill(); },
      [&](int iteration) {
        const int total = iterationOffset + iteration;
        if (callbacks.onProgress && callbacks.progressEvery > 0 && total % callbacks.progressEvery == 0) report();
        if (callbacks.onSnapshot && callbacks.snapshotEvery > 0 && total % callbacks.snapshotEvery == 0)
          callbacks.onSnapshot(snapshot());
      },
      [&](const StallWindow& w) -> std::optional<StopReason> {
        if (sim.fill() >= targetFill) return StopReason::TargetFill;
        if (w.full() && w.rms() < options.stallEpsilon) return StopReason::Stalled;
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
                      const RepulsionOptions& options, const RepulsionCallbacks& callbacks) {
  const auto passStart = std::chrono::steady_clock::now();
  checkOptions(options);
  // Tile mode packs the rectangle [0, W] × [0, H] in place of the scene's container.
  if (isTiled(options.tile) && !secondaryLibrary.empty())
    throw InputError("", "secondary elements are not supported in tile mode yet");
  if (isTiled(options.tile) && !isTileScene(scene, options.tile))
    return packRepulsion(tileScene(options.tile), library, options, callbacks);
  if (library.empty()) throw InputError("", "no elements to pack");
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
  const Vec2 period = isTiled(options.tile) ? options.tile * frame.scale : Vec2{};
  std::vector<Seed> seeds = seedContainers(partSeeding, options.seed, period);
  if (seeds.empty()) throw InputError(scene.source, "container too small to seed any element");
  // Preferred orientation: seeded at the angle the torsion will hold (eq. 4.6).
  const OrientationRamp ramp = options.orientation == OrientationMode::Field
                                   ? OrientationRamp::over(options.orientationField, bounds(container).min, bounds(container).max)
                                   : OrientationRamp{};
  if (options.orientation != OrientationMode::Random)
    for (Seed& s : seeds) s.angle = ramp.active ? ramp.angleAt(s.position) : 0.0;
  // Shape matching (4.7): elements that fit the salient corners take the nearest seeds.
  std::optional<CornerDocking> docking;
  const auto matchingStart = std::chrono::steady_clock::now();
  if (options.shapeMatching) {
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

  SimulationParameters parameters;
  parameters.repulsionStrength = options.repulsionStrength;
  parameters.overlapStrength = options.overlapStrength;
  parameters.boundaryStrength = options.boundaryStrength;
  parameters.edgeStrength = options.edgeStrength;
  parameters.negativeSpaceStrength = options.negativeSpaceStrength;
  parameters.torsionStrength = options.torsionStrength;
  if (options.orientation != OrientationMode::Random && options.torsionStrength == 0.0)
    parameters.torsionStrength = options.orientationTorsion;
  parameters.soft = options.soft;
  parameters.timeStep = options.timeStep;
  parameters.velocityCap = options.velocityCap;
  parameters.damping = options.damping;
  parameters.growthRate = options.growthRate;
  parameters.outsideTolerance = options.outsideTolerance;
  parameters.cellSize = options.cellSize > 0.0 ? options.cellSize : 2.0 * spacing;
  parameters.occupiedArea = blockedArea;
  parameters.period = period;

  ThreadPool pool(options.threads);
  PackingSimulation sim(containerIndex, containerArea + blockedArea, parameters, pool);
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
  if (docking) sim.setDocks(docking->docks(sim), options.dockingStrength);
  Box area = bounds(container);
  Vec2 margin{0.1 * kCanonicalSide, 0.1 * kCanonicalSide};
  area.add(area.min - margin);
  area.add(area.max + margin);
  sim.finalize(area);

  const StopReason reason = simulateUntilStopped(sim, options, options.targetFill, 0, callbacks, [&] {
    return collectPacking(sim, types, frame, scene.container);
  });
  Packing packing = collectPacking(sim, types, frame, scene.container);
  if (!isTiled(options.tile) && !artIsClean(packing, fixedArt) && sim.projectInside() > 0)
    packing = collectPacking(sim, types, frame, scene.container);
  packing.stopReason = reason;
  packing.containers = partsInput;
  if (docking) {
    for (const SalientCorner& c : docking->match().corners) packing.salientCorners.push_back(frame.toInput(c.position));
    packing.dockedElements = docking->dockedCount();
    packing.shapeMatchingSeconds = matchingSeconds;
  }
  packing.tile = isTiled(options.tile) ? options.tile : Vec2{};
  packing.fixedArt = fixedArt;
  packing.passes.push_back({static_cast<int>(sim.meshes().size()), sim.iteration(), reason, secondsSince(passStart),
                            packing.skinFill, artFill(packing)});
  if (secondaryLibrary.empty()) return packing;

  // Secondary elements (4.6): seeds in the pockets the primaries left, small elements shrunk
  // into them, the primaries frozen where they stopped (they repel but neither move nor grow).
  const auto secondaryStart = std::chrono::steady_clock::now();
  const double secondaryArea = nominalSkinArea * options.secondaryScale * options.secondaryScale;
  SecondarySeedingOptions secondarySeeding;
  secondarySeeding.minDistance = options.secondaryMinDistance > 0.0 ? options.secondaryMinDistance
                                                                    : std::max(options.gap, 0.25 * std::sqrt(secondaryArea));
  secondarySeeding.separation = options.secondarySeparation > 0.0 ? options.secondarySeparation : std::sqrt(secondaryArea);
  secondarySeeding.resolution = options.secondaryResolution;
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

    PackingSimulation second(containerIndex, containerArea + blockedArea, parameters, pool);
    for (const MeshInstance& m : sim.meshes()) {
      const int id = second.addMesh(allTypes[m.type].mesh, m.type, {}, 0.0, m.growth, true);
      second.meshes()[id].container = m.container;
      std::copy(sim.positions().begin() + m.vertexBegin, sim.positions().begin() + m.vertexBegin + m.vertexCount,
                second.positions().begin() + second.meshes()[id].vertexBegin);
    }
    // Random types and angles; each shrunk so its skin fits the pocket's empty disc.
    Rng rng(options.seed * 0x9E3779B97F4A7C15ull + 46);
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
    secondOptions.stallEpsilon *= static_cast<double>(pockets.size()) * secondaryArea / containerArea;
    secondPass.stopReason =
        simulateUntilStopped(second, secondOptions, options.secondaryTargetFill, primaryIterations, callbacks, collect);
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
}

std::vector<Region> artOutlines(const Packing& packing) {
  std::vector<Region> outlines;
  for (const PlacedElement& e : packing.elements) {
    std::vector<Region> painted;
    for (const Shape& s : e.art) painted.push_back(paintedRegion(s));
    outlines.push_back(unite(painted));
  }
  return outlines;
}

double artFill(const Packing& packing) {
  double total = area(packing.fixedArt);
  for (const Region& r : artOutlines(packing)) total += area(r);
  double a = area(packing.container);
  return a > 0.0 ? total / a : 0.0;
}

}  // namespace pak
