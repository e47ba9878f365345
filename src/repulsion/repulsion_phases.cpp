// RepulsionPak's primary pass, phase by phase (see repulsion_phases.hpp).
#include "repulsion/repulsion_phases.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pak/error.hpp"
#include "pak/limits.hpp"
#include "pak/geom/clipping.hpp"
#include "pak/geom/verify.hpp"
#include "pak/repulsion/tiling.hpp"
#include "repulsion/container_seeding.hpp"
#include "sim/deadline.hpp"
#include "sim/fold_relaxation.hpp"
#include "sim/simulation_loop.hpp"
#include "sim/stall_window.hpp"

namespace pak {
namespace {

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
  if (o.meshSpacing != 0.0 && o.meshSpacing < limits::kMinMeshSpacing)
    throw InputError("--mesh-spacing", "must be 0 (automatic) or at least " + messageNumber(limits::kMinMeshSpacing) +
                                           " canonical unit");
  if (o.count < 0) throw InputError("--count", "must not be negative");
  if (o.count > 100000) throw InputError("--count", std::to_string(o.count) + " is absurdly large");
  positive(o.elementArea, "--element-area");
  positive(o.initialCoverage, "--initial-coverage");
  checkSimulationParameters(o.simulation);
  checkRunOptions(o.run);
  positive(o.stop.targetFill, "--target-fill");
  if (o.stop.stallWindow < 1) throw InputError("--stall-window", "must be at least 1");
  nonNegative(o.stop.stallEpsilon, "--stall-epsilon");
  if (o.stop.maxIterations < 0) throw InputError("--max-iterations", "must not be negative");
  if (o.stop.settleIterations < 0) throw InputError("--settle-iterations", "must not be negative");
  nonNegative(o.stop.timeLimit, "--time-limit");
  if (!(o.secondary.scale > 0.0 && o.secondary.scale <= 10.0)) throw InputError("--secondary-scale", "must be in (0, 10]");
  nonNegative(o.secondary.minDistance, "--secondary-min-distance");
  nonNegative(o.secondary.separation, "--secondary-separation");
  if (o.secondary.resolution < 16 || o.secondary.resolution > 8000)
    throw InputError("--secondary-resolution", "must be between 16 and 8000 cells");
  positive(o.secondary.targetFill, "--secondary-target-fill");
  if (o.secondary.pressIterations < 0) throw InputError("--secondary-press", "must not be negative");
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

// Skins of the seeded meshes at growth g: overlap-free and inside their containers?
bool seedingIsClear(const RepulsionRun& run, const std::vector<Seed>& seeds, double g) {
  std::vector<Region> skins;
  std::vector<Box> boxes;
  const bool tiled = isTiled(run.period);
  for (const Seed& s : seeds) {
    const ElementMesh& mesh = run.types[s.type].mesh;
    Ring ring;
    for (int k = 0; k < mesh.boundaryCount; ++k) {
      Vec2 p = s.position + rotated(mesh.mesh.vertices[k] - mesh.restCentroid, s.angle) * g;
      if (!tiled && !run.setup.partIndex(s.container).query(p, false).inside) return false;  // a tile has no walls
      ring.push_back(p);
    }
    boxes.push_back(bounds(ring));
    skins.push_back(Region{Polygon{std::move(ring), {}}});
  }
  for (std::size_t i = 0; i < skins.size(); ++i)
    for (std::size_t j = i + 1; j < skins.size(); ++j)
      if (boxes[i].overlaps(boxes[j]) && area(intersect(skins[i], skins[j])) > 0.0) return false;
  return !tiled || !clonesOverlap(skins, run.period);
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

RepulsionRun prepareRepulsion(const Scene& scene, const Library& library, const RepulsionOptions& options) {
  checkOptions(options);
  if (library.empty()) throw InputError("--elements", "no elements to pack");
  RepulsionRun run{scene, options, preparePacking(scene, library, {.obstacleMargin = 0.5 * options.gap})};
  run.started = std::chrono::steady_clock::now();
  const PackingSetup& setup = run.setup;
  if (!setup.fixedPainted.empty()) run.fixedArt = intersect(setup.fixedPainted, scene.container, setup.clip);
  run.count = options.count > 0 ? options.count : std::max(1, static_cast<int>(std::lround(1.0 / options.elementArea)));
  run.nominalSkinArea = setup.containerArea / run.count;
  run.spacing = options.meshSpacing > 0.0 ? options.meshSpacing
                                          : std::max(options.gap, std::sqrt(run.nominalSkinArea) / 10.0);
  indexContainers(run.setup, std::max(run.spacing, 5.0));

  // Every library the containers use, scaled alike so the mean skin has the nominal area.
  const Library& types = setup.types(library);
  const double scale = librarySkinScale(types, run.nominalSkinArea, options.gap);
  ElementMeshOptions meshOptions;
  meshOptions.gap = options.gap;
  meshOptions.spacing = run.spacing;
  for (std::size_t i = 0; i < types.size(); ++i) {
    meshOptions.seed = options.run.seed * 7919 + i;
    run.types.push_back(prepareElement(types[i], scale, meshOptions));
  }

  run.period = isTiled(options.tiling.size) ? options.tiling.size * setup.frame.scale : Vec2{};
  if (options.orientation.mode == OrientationMode::Field)
    run.ramp = OrientationRamp::over(options.orientation.field, bounds(setup.container).min, bounds(setup.container).max);
  run.parameters = resolvedParameters(options, run.spacing);
  run.domain = {.occupiedArea = setup.blockedArea, .period = run.period};
  run.simulationArea = bounds(setup.container);
  const Vec2 margin{0.1 * kCanonicalSide, 0.1 * kCanonicalSide};
  run.simulationArea.add(run.simulationArea.min - margin);
  run.simulationArea.add(run.simulationArea.max + margin);
  return run;
}

Seeding seedPrimaries(const RepulsionRun& run) {
  const PackingSetup& setup = run.setup;
  std::vector<ContainerSeeding> partSeeding;
  const std::vector<int> partCounts = seedsPerContainer(setup.partAreas, run.count, 0.5 * run.nominalSkinArea);
  for (std::size_t c = 0; c < setup.parts.size(); ++c)
    partSeeding.push_back({&setup.parts[c], &setup.partIndex(c), partCounts[c], setup.containers.typesOf[c]});
  Seeding seeding;
  seeding.seeds = seedContainers(partSeeding, run.options.run.seed, run.period);
  if (seeding.seeds.empty()) throw InputError(run.scene.source, "container too small to seed any element");
  // Preferred orientation: seeded at the angle the torsion will hold (eq. 4.6).
  if (run.options.orientation.mode != OrientationMode::Random)
    for (Seed& s : seeding.seeds) s.angle = run.ramp.active ? run.ramp.angleAt(s.position) : 0.0;
  // Shape matching (4.7): elements that fit the salient corners take the nearest seeds.
  if (run.options.shapeMatching.enabled) {
    const auto start = std::chrono::steady_clock::now();
    std::vector<const ElementMesh*> meshes;
    std::vector<const Region*> outlines;
    for (const PreparedElement& t : run.types) {
      meshes.push_back(&t.mesh);
      outlines.push_back(&t.outline);
    }
    seeding.docking.emplace(setup.container, meshes, outlines, run.options.gap, seeding.seeds);
    seeding.matchingSeconds = secondsSince(start);
  }
  return seeding;
}

void shrinkSeeds(const RepulsionRun& run, Seeding& seeding) {
  std::vector<Seed>& seeds = seeding.seeds;
  double seededSkin = 0.0;
  for (const Seed& s : seeds) seededSkin += run.types[s.type].mesh.skinArea;
  double g = std::sqrt(run.options.initialCoverage * run.setup.containerArea / seededSkin);
  // A docked seed may have moved to another container's corner: it belongs where it now is.
  auto dock = [&] {
    if (!seeding.docking) return;
    seeding.docking->position(g, run.setup.containerIndex, seeds);
    if (run.setup.severalParts())
      for (Seed& s : seeds)
        if (const int c = run.setup.partAt(s.position); c >= 0) s.container = c;
  };
  dock();
  for (int attempt = 0; attempt < 30 && !seedingIsClear(run, seeds, g); ++attempt) {
    g *= 0.9;
    dock();
  }
  seeding.growth = g;
}

void setUpContainers(const RepulsionRun& run, PackingSimulation& sim) {
  const PackingSetup& setup = run.setup;
  if (setup.severalParts()) {
    std::vector<PackingSimulation::Corner> corners;
    for (std::size_t c = 0; c < setup.parts.size(); ++c)
      for (PackingSimulation::Corner corner : PackingSimulation::reflexCorners(setup.parts[c])) {
        corner.container = static_cast<int>(c);
        corners.push_back(corner);
      }
    sim.setContainerCorners(std::move(corners));
    sim.setContainerParts(setup.partIndexPointers());
  } else {
    sim.setContainerCorners(PackingSimulation::reflexCorners(setup.container));
  }
  if (run.ramp.active) sim.setOrientationField(run.ramp);
}

PackingSimulation primarySimulation(const RepulsionRun& run, const Seeding& seeding, ThreadPool& pool) {
  PackingSimulation sim(run.setup.containerIndex, run.setup.containerArea + run.setup.blockedArea, run.parameters, pool,
                        run.domain);
  for (const Seed& s : seeding.seeds)
    sim.meshes()[sim.addMesh(run.types[s.type].mesh, s.type, s.position, s.angle, seeding.growth)].container = s.container;
  setUpContainers(run, sim);
  if (seeding.docking) sim.setDocks(seeding.docking->docks(sim), run.options.shapeMatching.dockingStrength);
  sim.finalize(run.simulationArea);
  return sim;
}

StopReason simulate(PackingSimulation& sim, const RepulsionRun& run, const RepulsionStopRule& stop, double targetFill,
                    int iterationOffset, const RepulsionCallbacks& callbacks,
                    const std::function<Packing()>& snapshot) {
  // Eq. 4.7 over a window of the last w + 1 area fractions. The fraction is the meshes' rest
  // area (see restFill): the measured skin area jitters by more than ε from step to step.
  StallWindow window(stop.stallWindow);
  const Deadline deadline(run.started, stop.timeLimit, run.options.run.stopRequest);
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
      sim, stop.maxIterations, window, [&] { return stop.stallOnMeasuredArea ? sim.fill() : sim.restFill(); },
      [&](int iteration) {
        const int total = iterationOffset + iteration;
        if (callbacks.onProgress && callbacks.progressEvery > 0 && total % callbacks.progressEvery == 0) report();
        if (callbacks.onSnapshot && callbacks.snapshotEvery > 0 && total % callbacks.snapshotEvery == 0)
          callbacks.onSnapshot(snapshot());
      },
      [&](const StallWindow& w) -> std::optional<StopReason> {
        if (sim.fill() >= targetFill) return StopReason::TargetFill;
        if (w.full() && w.rms() < stop.stallEpsilon) return StopReason::Stalled;
        if (deadline.passed()) return deadline.requested() ? StopReason::Interrupted : StopReason::TimeLimit;
        return std::nullopt;
      });
  report();
  return reason.value_or(StopReason::IterationCap);
}

std::vector<Fold> foldedMeshes(const PackingSimulation& sim, const std::vector<PreparedElement>& types) {
  std::vector<Fold> folds;
  std::vector<Vec2> crossings, artPoints;
  Ring ring;
  for (std::size_t m = 0; m < sim.meshes().size(); ++m) {
    const MeshInstance& mesh = sim.meshes()[m];
    if (mesh.frozen) continue;
    crossings.clear();
    appendArtFolds(types[mesh.type], sim.positions().data() + mesh.vertexBegin, crossings, artPoints, ring);
    for (Vec2 at : crossings) folds.push_back({static_cast<int>(m), at});
  }
  return folds;
}

namespace {
// Skins are the art offset by half the gap: a vertex less than a quarter of the gap inside
// another skin leaves the two arts at least three quarters of the gap apart.
constexpr double kSettleDepthShare = 0.25;
}  // namespace

int press(PackingSimulation& sim, const RepulsionRun& run, const RepulsionStopRule& stop, int iterations) {
  const int start = sim.iteration();
  const Deadline deadline(run.started, stop.timeLimit, run.options.run.stopRequest);
  sim.press(kSettleDepthShare * run.options.gap);
  while (sim.iteration() - start < iterations && !deadline.passed()) sim.step();
  sim.grow();
  return sim.iteration() - start;
}

int settle(PackingSimulation& sim, const RepulsionRun& run, const RepulsionStopRule& stop,
           const std::vector<PreparedElement>& types) {
  // …but none shrinks below this share of its growth unless its art overlaps or leaves the
  // container: a skin pressed into another by pocket pressure is usually harmless.
  constexpr double kSettleFloor = 0.95;
  // Unfolding rounds, each this long: the mesh around each crossing of an art outline is pulled
  // toward its rest shape, twice as hard each round.
  constexpr int kArtRounds = 4, kArtRoundIterations = 100;
  constexpr double kUnfoldRadius = 1.5;  // × the neighbour cell: the mesh around a crossing
  const int start = sim.iteration();
  // A tile has no clean-up of its art (cleanArt), so its elements shrink until clear.
  const bool tiled = isTiled(run.period);
  sim.settle(kSettleDepthShare * run.options.gap, tiled ? 0.0 : kSettleFloor);
  // Not cut short by the time limit or a stop request: a run they stop is cleaned up too (a
  // clean packing costs only the checks), within the clean-up's own iterations.
  auto left = [&] { return stop.settleIterations - (sim.iteration() - start); };
  auto shrink = [&] {
    while (left() > 0 && sim.unsettledCount() > 0) sim.step();
  };
  shrink();
  if (!tiled) {
    for (std::size_t e : artOffenders(run, sim, types)) sim.meshes()[e].settleFloor = 0.0;
    shrink();
  }
  if (sim.parameters().unfoldStrength > 0.0)
    for (int round = 0; round < kArtRounds && left() > 0; ++round) {
      const std::vector<Fold> folds = foldedMeshes(sim, types);
      if (folds.empty()) break;
      // Gently first: a fold still there a round later is held twice as hard.
      const double strength = std::ldexp(sim.parameters().unfoldStrength, round);
      for (const Fold& fold : folds)
        sim.restoreAround(fold.mesh, fold.at, kUnfoldRadius * sim.parameters().cellSize, strength);
      for (int i = 0; i < kArtRoundIterations && left() > 0; ++i) sim.step();
      shrink();
    }
  // A fold the rounds left: the element is relaxed toward its rest shape until it no longer
  // folds, then held in that shape as a whole while the forces move it clear and it shrinks
  // if still deep. The others stand still meanwhile, so that only it gives way.
  if (sim.parameters().unfoldStrength > 0.0 && left() > 0) {
    const std::vector<char> relaxed = relaxFolds(sim, types);
    if (std::any_of(relaxed.begin(), relaxed.end(), [](char r) { return r != 0; })) {
      sim.holdRestShapes(relaxed, std::ldexp(sim.parameters().unfoldStrength, kArtRounds));
      for (int i = 0; i < kArtRoundIterations && left() > 0; ++i) sim.step();
      shrink();
    }
  }
  sim.grow();
  return sim.iteration() - start;
}

namespace {

// One mesh's art, replayed on its vertices, in input coordinates (strokes at its growth): with
// the thesis's linear map, or `smooth`ed (replayDrawnArt).
std::vector<Shape> placedArt(const RepulsionRun& run, const PackingSimulation& sim,
                             const std::vector<PreparedElement>& types, const MeshInstance& mesh,
                             std::vector<Vec2>& artPoints, bool smooth = false) {
  const CanonicalFrame& frame = run.setup.frame;
  const PreparedElement& type = types[mesh.type];
  replayDrawnArt(type.mesh, sim.positions().data() + mesh.vertexBegin, !smooth, artPoints);
  std::vector<Shape> art = type.art;
  std::size_t k = 0;
  for (Shape& shape : art) {
    scaleStroke(shape, mesh.growth / frame.scale);
    for (Subpath& sub : shape.subpaths)
      for (Vec2& p : sub.points) p = frame.toInput(artPoints[k++]);
  }
  return art;
}

// The outlines that overlap another's, or the fixed art, or leave the container, by more than
// verifyPacking's tolerance (as `pak pack` checks it).
std::vector<std::size_t> offendingOutlines(std::vector<Region> outlines, const Region& container, const Region& fixedArt) {
  const std::size_t elements = outlines.size();
  if (!fixedArt.empty()) outlines.push_back(fixedArt);
  PackingCheckOptions options;
  options.areaTolerance = 1e-6 * area(container);
  std::vector<std::size_t> offending = verifyPacking(outlines, container, options).offending;
  std::erase_if(offending, [&](std::size_t e) { return e >= elements; });  // the fixed art
  return offending;
}

// The smoothed art of each element, where it is as clean as the linear art the clean-up
// checked: an element whose smoothed art overlaps another's, leaves the container or crosses
// itself where its linear art does not is drawn with the linear art instead, round after round
// (a reverted element can uncover another), so the packing is never less clean than the
// thesis's map makes it. Returns how many were reverted.
int smoothWhereClean(Packing& packing, const std::vector<std::vector<Shape>>& linearArt) {
  constexpr int kRounds = 4;  // then every element left smooth is reverted too
  std::vector<char> linear(packing.elements.size(), 0);
  std::vector<std::vector<Ring>> straight;  // the linear art's rings, the same every round
  for (const std::vector<Shape>& art : linearArt) straight.push_back(artRings(art));
  for (int round = 0; round <= kRounds; ++round) {
    std::vector<std::size_t> revert = artOffenders(packing);
    for (std::size_t e = 0; e < packing.elements.size(); ++e) {
      if (linear[e]) continue;
      const std::vector<Ring> drawn = artRings(packing.elements[e].art);
      for (std::size_t r = 0; r < drawn.size() && r < straight[e].size(); ++r)
        if (ringSelfIntersects(drawn[r]) && !ringSelfIntersects(straight[e][r])) {
          revert.push_back(e);
          break;
        }
    }
    std::erase_if(revert, [&](std::size_t e) { return linear[e] != 0; });
    if (revert.empty()) break;
    if (round == kRounds)
      for (std::size_t e = 0; e < linear.size(); ++e) revert.push_back(e);
    for (std::size_t e : revert)
      if (!linear[e]) {
        linear[e] = 1;
        packing.elements[e].art = linearArt[e];
      }
  }
  return static_cast<int>(std::count(linear.begin(), linear.end(), 1));
}

}  // namespace

Packing collectPacking(const RepulsionRun& run, const PackingSimulation& sim, const std::vector<PreparedElement>& types) {
  const CanonicalFrame& frame = run.setup.frame;
  Packing packing;
  packing.container = run.scene.container;
  packing.canonicalScale = frame.scale;
  packing.iterations = sim.iteration();
  packing.skinFill = sim.fill();
  packing.vertexCount = static_cast<int>(sim.positions().size());
  packing.springCount = static_cast<int>(sim.springCount());
  std::vector<Vec2> artPoints;
  // A tile's elements cross its edges by design: the clean check below does not apply there.
  const bool smooth = !run.options.linearArt && !isTiled(run.period);
  std::vector<std::vector<Shape>> linearArt;  // what the clean-up checked, when drawing smoothed
  for (const MeshInstance& mesh : sim.meshes()) {
    const PreparedElement& type = types[mesh.type];
    const Vec2* vertices = sim.positions().data() + mesh.vertexBegin;
    PlacedElement placed;
    placed.libraryIndex = mesh.type;
    placed.source = type.source;
    placed.growth = mesh.growth;
    placed.container = mesh.container;
    placed.art = placedArt(run, sim, types, mesh, artPoints, smooth);
    if (smooth) linearArt.push_back(placedArt(run, sim, types, mesh, artPoints));
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
  packing.fixedArt = run.fixedArt;
  if (smooth) packing.linearArtFallbacks = smoothWhereClean(packing, linearArt);
  return packing;
}

std::vector<std::size_t> artOffenders(const Packing& packing) {
  return offendingOutlines(artOutlines(packing), packing.container, packing.fixedArt);
}

std::vector<std::size_t> artOffenders(const RepulsionRun& run, const PackingSimulation& sim,
                                      const std::vector<PreparedElement>& types) {
  std::vector<Region> outlines;
  std::vector<Vec2> artPoints;
  for (const MeshInstance& mesh : sim.meshes()) outlines.push_back(artOutline(placedArt(run, sim, types, mesh, artPoints)));
  return offendingOutlines(std::move(outlines), run.scene.container, run.fixedArt);
}

std::vector<char> relaxFolds(PackingSimulation& sim, const std::vector<PreparedElement>& types) {
  std::vector<char> relaxed(sim.meshes().size(), 0);
  std::vector<Vec2> crossings, artPoints;
  Ring ring;
  for (std::size_t m = 0; m < sim.meshes().size(); ++m) {
    const MeshInstance& mesh = sim.meshes()[m];
    if (mesh.frozen) continue;
    auto firstFold = [&]() -> std::optional<Vec2> {
      crossings.clear();
      appendArtFolds(types[mesh.type], sim.positions().data() + mesh.vertexBegin, crossings, artPoints, ring);
      if (crossings.empty()) return std::nullopt;
      return crossings.front();
    };
    auto restore = [&](double keep, Vec2 at, double radius) { sim.restoreRestShape(static_cast<int>(m), keep, at, radius); };
    relaxed[m] = relaxFold(sim.parameters().cellSize, firstFold, restore) ? 1 : 0;
  }
  return relaxed;
}

Packing cleanArt(const RepulsionRun& run, PackingSimulation& sim, const std::vector<PreparedElement>& types) {
  // Each round contracts every offending element by half a percent about its centre, six
  // times (what is left across the wall or a neighbour between two mesh vertices), then by 2 %
  // (an element relaxed toward its rest shape below, or one the clean-up ran out of
  // iterations for), at most 40 % in all, until it is clear.
  constexpr int kGentleRounds = 6, kRounds = 31;
  constexpr double kGentle = 0.995, kFirm = 0.98;
  if (isTiled(run.period)) return collectPacking(run, sim, types);
  if (!artOffenders(run, sim, types).empty()) sim.projectInside();  // may fold an element pressed onto the wall
  const std::vector<char> restored = relaxFolds(sim, types);
  for (int round = 0; round < kRounds; ++round) {
    bool moved = false;
    for (std::size_t e : artOffenders(run, sim, types)) {
      if (sim.meshes()[e].frozen) continue;
      sim.contractMesh(static_cast<int>(e), restored[e] || round >= kGentleRounds ? kFirm : kGentle);
      moved = true;
    }
    if (!moved) break;
  }
  return collectPacking(run, sim, types);
}

bool artIsClean(const Packing& packing) { return artOffenders(packing).empty(); }

Packing collectPrimary(const RepulsionRun& run, PackingSimulation& sim, const Seeding& seeding, StopReason reason) {
  Packing packing = cleanArt(run, sim, run.types);
  packing.stopReason = reason;
  packing.containers = run.setup.containers.regions;
  if (seeding.docking) {
    for (const SalientCorner& c : seeding.docking->match().corners)
      packing.salientCorners.push_back(run.setup.frame.toInput(c.position));
    packing.dockedElements = seeding.docking->dockedCount();
    packing.shapeMatchingSeconds = seeding.matchingSeconds;
  }
  packing.tile = isTiled(run.options.tiling.size) ? run.options.tiling.size : Vec2{};
  packing.passes.push_back({static_cast<int>(sim.meshes().size()), sim.iteration(), reason, secondsSince(run.started),
                            packing.skinFill, artFill(packing)});
  return packing;
}

}  // namespace pak
