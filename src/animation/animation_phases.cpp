// AnimationPak, phase by phase (see animation_phases.hpp).
#include "animation/animation_phases.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <numbers>
#include <optional>
#include <utility>

#include "animation/element_animator.hpp"
#include "pak/error.hpp"
#include "pak/limits.hpp"
#include "pak/sim/canonical_units.hpp"
#include "pak/geom/blue_noise.hpp"
#include "pak/geom/rng.hpp"
#include "sim/canonical_frame.hpp"
#include "sim/deadline.hpp"
#include "sim/fold_relaxation.hpp"
#include "sim/simulation_loop.hpp"
#include "sim/stall_window.hpp"

namespace pak {
namespace {

// Each error names the option as `pak animate` spells it (the flag is also the --config key).
void checkOptions(const AnimationOptions& o, int slices) {
  auto positive = [](double v, const char* option) {
    if (!(v > 0.0) || !std::isfinite(v)) throw InputError(option, "must be a positive number");
  };
  auto nonNegative = [](double v, const char* option) {
    if (!(v >= 0.0) || !std::isfinite(v)) throw InputError(option, "must be a non-negative number");
  };
  if (slices < 2 || slices > limits::kMaxSlices)
    throw InputError("--slices", "must be between 2 and " + std::to_string(limits::kMaxSlices));
  if (!(o.elementArea >= 0.0 && o.elementArea <= 1.0)) throw InputError("--element-area", "must be in [0, 1]");
  positive(o.gap, "--gap");
  nonNegative(o.meshSpacing, "--mesh-spacing");
  if (!(o.initialScale > 0.0 && o.initialScale <= 1.0)) throw InputError("--initial-scale", "must be in (0, 1]");
  if (o.meshSpacing != 0.0 && o.meshSpacing < limits::kMinMeshSpacing)
    throw InputError("--mesh-spacing", "must be 0 (automatic) or at least " + messageNumber(limits::kMinMeshSpacing) +
                                           " canonical units");
  checkSimulationParameters(o.simulation);
  checkRunOptions(o.run);
  positive(o.simulation.cellSize, "--cell-size");  // the exact repulsion reach: no packer default
  const SpacetimeParameters& p = o.spacetime;
  nonNegative(p.timeStrength, "--time-springs");
  nonNegative(p.targetStrength, "--target");
  nonNegative(p.temporalStrength, "--temporal");
  positive(p.maxGrowth, "--max-growth");
  nonNegative(p.growthSpread, "--growth-spread");
  nonNegative(p.guidedGrowth, "--guided-growth");
  nonNegative(p.growthSpeedCap, "--growth-speed-cap");
  nonNegative(p.guidedWallGive, "--guided-wall-give");
  positive(p.timeLength, "--time-length");
  if (p.timeLength > limits::kMaxTimeLength)
    throw InputError("--time-length", "must be at most " + messageNumber(limits::kMaxTimeLength));
  // The spacetime grid spans the 1000-wide frame and the time axis, one cell per reach.
  const double cell = o.simulation.cellSize;
  const double cells = std::pow(kCanonicalSide / cell + 2.0, 2) * (p.timeLength / cell + 2.0);
  if (cells > limits::kMaxSpacetimeCells)
    throw InputError("--cell-size", messageNumber(cell) + " is too fine: the spacetime grid would have " +
                                        messageNumber(cells) + " cells (at most " +
                                        messageNumber(limits::kMaxSpacetimeCells) + ")");
  nonNegative(o.stop.closeness, "--closeness");
  nonNegative(o.stop.stallGrowth, "--stall-growth");
  if (o.stop.stallWindow < 1) throw InputError("--stall-window", "must be at least 1");
  if (o.stop.maxIterations < 0) throw InputError("--max-iterations", "must not be negative");
  nonNegative(o.stop.timeLimit, "--time-limit");
  if (o.stop.settleIterations < 0) throw InputError("--settle-iterations", "must not be negative");
  nonNegative(o.stop.settleOverlapStrength, "--settle-k-overlap");
  const FrameSeparationOptions& f = o.frameSeparation;
  if (f.rounds < 0 || f.rounds > 100) throw InputError("--frame-separation", "must be between 0 and 100 rounds");
  if (!(f.step > 0.0 && f.step < 1.0)) throw InputError("--frame-separation", "the step must be in (0, 1)");
  nonNegative(f.areaTolerance, "--frame-separation");
  if (f.samples < 0 || f.samples > 100000) throw InputError("--frame-separation-samples", "must be between 0 and 100000");
  if (!(f.ramp >= 0.0 && f.ramp <= 0.5)) throw InputError("--frame-separation-ramp", "must be in [0, 0.5]");
}

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

// Linear interpolation of the guided targets at t (5.4): position, and scale and rotation
// where targets give them.
struct GuidePose { Vec2 position; double scale = 1.0; double rotation = 0.0; };
GuidePose guidePose(const std::vector<GuideTarget>& targets, const CanonicalFrame& frame, double t) {
  std::size_t k = 1;
  while (k + 1 < targets.size() && targets[k].t < t) ++k;
  const GuideTarget& a = targets[k - 1];
  const GuideTarget& b = targets[k];
  const double w = b.t > a.t ? std::clamp((t - a.t) / (b.t - a.t), 0.0, 1.0) : 0.0;
  auto channel = [&](auto get, double fallback) {
    // The nearest targets that give the value, on each side.
    double before = fallback, after = fallback, tb = 0.0, ta = 1.0;
    bool haveBefore = false, haveAfter = false;
    for (const GuideTarget& g : targets) {
      std::optional<double> v = get(g);
      if (!v) continue;
      if (g.t <= t) before = *v, tb = g.t, haveBefore = true;
      if (g.t >= t && !haveAfter) after = *v, ta = g.t, haveAfter = true;
    }
    if (!haveBefore) return haveAfter ? after : fallback;
    if (!haveAfter || ta <= tb) return before;
    return before + (after - before) * (t - tb) / (ta - tb);
  };
  GuidePose pose;
  pose.position = frame.toCanonical(a.position + (b.position - a.position) * w);
  pose.scale = channel([](const GuideTarget& g) { return g.scale; }, 1.0);
  pose.rotation = channel([](const GuideTarget& g) { return g.rotation; }, 0.0);
  return pose;
}

Vec2 rotate(Vec2 p, double angle) { return rotated(p, angle); }

// The spec a guided element loops to (itself unless `loop_to` names another).
const AnimatedElementSpec& loopPartner(const AnimationScript& script, const AnimatedElementSpec& spec) {
  if (!spec.loopTo.empty())
    for (const AnimatedElementSpec& other : script.elements)
      if (other.id == spec.loopTo) return other;
  return spec;
}

// A guided element's loop joins its t = 1 slice to the t = 0 slice of the element it loops to:
// what separates its last target from that one's first is the loop's shift (input units).
// Zero for unguided elements and for loops that come back to where they started.
Vec2 loopShift(const AnimatedElementSpec& spec, const AnimatedElementSpec& partner) {
  if (spec.targets.empty() || partner.targets.empty()) return {};
  return spec.targets.back().position - partner.targets.front().position;
}

// The least k ≤ 12 for which k times the turn from `first` to `last` (centred shapes) is a
// whole number of turns: 1 for no turn, 0 for none such.
int loopTurnOrder(const std::vector<Vec2>& first, const std::vector<Vec2>& last) {
  constexpr int kMostOrder = 12;
  constexpr double kTolerance = 1e-4;  // radians, per turn
  const Vec2 turn = SpacetimeSimulation::loopTurn(first.data(), last.data(), static_cast<int>(first.size()));
  const double angle = std::atan2(turn.y, turn.x);
  for (int k = 1; k <= kMostOrder; ++k)
    if (std::abs(std::remainder(k * angle, 2.0 * std::numbers::pi)) < kTolerance * k) return k;
  return 0;
}

// Guided elements stay in the container unless they may leave it; one that travels (its loop
// moves it, AnimatedElement::loopShift) must move far enough that its copies one shift away
// never enter the container, which the simulation does not see.
void checkGuidedPaths(const AnimationRun& run) {
  const AnimationScript& script = run.script;
  const Box box = bounds(run.scene.container);
  for (std::size_t i = 0; i < script.elements.size(); ++i) {
    const AnimatedElementSpec& spec = script.elements[i];
    if (spec.targets.empty()) continue;
    const std::string at = "elements[" + std::to_string(i) + "]";
    if (!spec.leavesContainer)
      for (std::size_t k = 0; k < spec.targets.size(); ++k)
        if (!pointInRegion(spec.targets[k].position, run.scene.container))
          throw InputError(script.source, at + ".targets[" + std::to_string(k) +
                                              "]: lies outside the container; a guided element may leave it only "
                                              "with \"leaves_container\": true");
    if (!script.loop) continue;
    const Vec2 shift = loopShift(spec, loopPartner(script, spec));
    if (shift.x == 0.0 && shift.y == 0.0) continue;
    if (!spec.leavesContainer)
      throw InputError(script.source, at + ".targets: the loop moves the element (its last target is not where it "
                                           "starts); only an element with \"leaves_container\": true may travel");
    const double reach = 2.0 * run.types[i].radius / run.setup.frame.scale;  // its diameter, input units
    if (std::abs(shift.x) < box.width() + reach && std::abs(shift.y) < box.height() + reach)
      throw InputError(script.source, at + ".targets: the loop moves the element by less than the container's extent "
                                           "and its diameter, so its copy one loop away would enter the container");
  }
}

}  // namespace

AnimationRun prepareAnimation(const Scene& scene, const Library& library, const AnimationScript& script,
                              const AnimationOptions& options) {
  const int slices = options.slices > 0 ? options.slices : script.slices;
  checkOptions(options, slices);
  if (script.elements.empty()) throw InputError(script.source, "the animation has no elements");
  if (library.size() != script.elements.size())
    throw InputError(script.source, "one element art per animation element is needed");
  // Fixed elements are obstacles, as in pak pack: their art grown by half the gap leaves the
  // container. The gap follows the nominal size, which follows the area they leave free, so a
  // scene with fixed elements is set up twice: with the art cut out exactly, then with the gap.
  int total = 0;
  for (const AnimatedElementSpec& spec : script.elements) total += spec.count;
  auto nominalAreaIn = [&](double freeArea) {
    return (options.elementArea > 0.0 ? options.elementArea : 1.0 / total) * freeArea;
  };
  PackingSetupOptions setupOptions;
  if (!scene.fixed.empty()) {
    setupOptions.obstacleMargin = 0.0;
    const double freeArea = preparePacking(scene, library, setupOptions).containerArea;
    setupOptions.obstacleMargin = 0.5 * options.gap * std::sqrt(nominalAreaIn(freeArea));
  }
  AnimationRun run{scene, script, options, slices, preparePacking(scene, library, setupOptions)};
  run.started = std::chrono::steady_clock::now();
  indexContainers(run.setup, 10.0);
  const double containerArea = run.setup.containerArea;
  if (!run.setup.fixedPainted.empty())
    run.fixedArt = intersect(run.setup.fixedPainted, scene.container, run.setup.clip);

  const double nominalArea = nominalAreaIn(containerArea);
  const double nominalSize = std::sqrt(nominalArea);
  const double gap = options.gap * nominalSize;
  const double spacing = options.meshSpacing > 0.0 ? options.meshSpacing : nominalSize / 4.0;
  const double scale = librarySkinScale(library, nominalArea, gap);

  std::map<std::string, int> meshOfSource;
  std::vector<ElementMeshOptions> meshOptionsOf;  // per mesh
  std::vector<std::size_t> meshArt;               // per mesh: its library entry
  run.types.resize(script.elements.size());
  const double dtSlice = 1.0 / (slices - 1);
  auto animate = [&](std::size_t i) {
    const ElementArt& art = library[i];
    AnimatedType& type = run.types[i];
    try {
      ElementAnimator animator(run.meshes[type.mesh].mesh.mesh, art.handles, type.spec->animation, centroid(art.outline),
                               scale, script.loop);
      type.shapes.assign(slices, {});
      type.radius = 0.0;
      for (int s = 0; s < slices; ++s) {
        animator.shapeAt(s * dtSlice, type.shapes[s]);
        for (Vec2 p : type.shapes[s]) type.radius = std::max(type.radius, length(p));
      }
    } catch (const InputError& error) {
      throw InputError(art.source, std::string("element '") + type.spec->id + "': " + error.what());
    }
  };
  for (std::size_t i = 0; i < script.elements.size(); ++i) {
    const ElementArt& art = library[i];
    AnimatedType& type = run.types[i];
    type.spec = &script.elements[i];
    type.source = art.source;
    auto [it, fresh] = meshOfSource.try_emplace(art.source, static_cast<int>(run.meshes.size()));
    if (fresh) {
      ElementMeshOptions meshOptions;
      meshOptions.gap = gap;
      meshOptions.spacing = spacing;
      meshOptions.seed = options.run.seed * 7919 + run.meshes.size();
      run.meshes.push_back(prepareElement(art, scale, meshOptions));
      meshOptionsOf.push_back(meshOptions);
      meshArt.push_back(i);
    }
    type.mesh = it->second;
    animate(i);
  }
  // A loop that turns an element by a part of a full turn joins its last slice to the first
  // one turned. When the element's skin has the turn's symmetry, its mesh is made with it too,
  // so that each vertex can join the one at its place (SpacetimeSimulation::addLoop).
  if (script.loop)
    for (std::size_t m = 0; m < run.meshes.size(); ++m) {
      int order = 1;
      for (const AnimatedType& type : run.types)
        if (type.mesh == static_cast<int>(m)) order = std::lcm(order, loopTurnOrder(type.shapes.front(), type.shapes.back()));
      if (order <= 1) continue;
      ElementMeshOptions meshOptions = meshOptionsOf[m];
      meshOptions.symmetry = order;
      PreparedElement symmetric = prepareElement(library[meshArt[m]], scale, meshOptions);
      if (symmetric.mesh.symmetry != order) continue;
      run.meshes[m] = std::move(symmetric);
      for (std::size_t i = 0; i < run.types.size(); ++i)
        if (run.types[i].mesh == static_cast<int>(m)) animate(i);
    }
  checkGuidedPaths(run);
  // Orientations along the guides (Fig. 5.18): FLOWPAK's field, sampled every 5 canonical units
  // along the strokes as `pak flow` does (thesis: 0.005 of the canvas).
  if (std::any_of(script.elements.begin(), script.elements.end(),
                  [](const AnimatedElementSpec& s) { return s.orientationFromField; })) {
    if (scene.guides.empty())
      throw InputError(script.source, "an element's orientation is \"field\", but the container SVG has no direction "
                                      "guides: draw strokes on a `guides` layer");
    VectorFieldOptions fieldOptions;
    fieldOptions.sampleSpacing = 5.0 / run.setup.frame.scale;
    run.field = buildVectorField(scene.container, scene.guides, fieldOptions);
  }
  return run;
}

AnimationSeeding seedAnimation(const AnimationRun& run) {
  const AnimationOptions& options = run.options;
  const CanonicalFrame& frame = run.setup.frame;
  const std::vector<AnimatedType>& types = run.types;
  const int slices = run.slices;
  const double dtSlice = 1.0 / (slices - 1);
  AnimationSeeding seeding;
  std::vector<AnimatedInstance>& instances = seeding.instances;
  seeding.guidedInstance.assign(types.size(), -1);

  // Guided elements along their targets, then blue-noise seeds for the others, away from the
  // guided tubes; everything shrunk to fit.
  Rng rng(options.run.seed);
  double largestRadius = 0.0;
  for (const AnimatedType& type : types) largestRadius = std::max(largestRadius, type.radius);
  for (std::size_t i = 0; i < types.size(); ++i) {
    const AnimatedType& type = types[i];
    if (type.spec->targets.empty()) continue;
    const ElementMesh& mesh = run.meshes[type.mesh].mesh;
    int anchor = 0;  // the vertex nearest the centroid (the mesh is centred on it)
    for (std::size_t v = 1; v < mesh.mesh.vertices.size(); ++v)
      if (length(mesh.mesh.vertices[v]) < length(mesh.mesh.vertices[anchor])) anchor = static_cast<int>(v);
    AnimatedInstance instance;
    instance.type = static_cast<int>(i);
    for (int s = 0; s < slices; ++s) {
      const GuidePose pose = guidePose(type.spec->targets, frame, s * dtSlice);
      const std::vector<Vec2>& shape = type.shapes[s];
      Vec2 sum;
      for (Vec2 p : shape) {
        const Vec2 q = pose.position + rotate(p - shape[anchor], -radians(pose.rotation)) * pose.scale;
        instance.reference.push_back(q);
        sum += q;
      }
      instance.centre.push_back(sum / static_cast<double>(shape.size()));
    }
    for (const GuideTarget& target : type.spec->targets) {
      const int s = static_cast<int>(std::lround(target.t * (slices - 1)));
      instance.targets.push_back({s, anchor, frame.toCanonical(target.position)});
    }
    seeding.guidedInstance[i] = static_cast<int>(instances.size());
    instances.push_back(std::move(instance));
  }
  const int guidedCount = static_cast<int>(instances.size());

  std::vector<int> unguided;  // type of each unguided copy, in a random order
  for (std::size_t i = 0; i < types.size(); ++i)
    if (types[i].spec->targets.empty())
      for (int c = 0; c < types[i].spec->count; ++c) unguided.push_back(static_cast<int>(i));
  for (std::size_t k = unguided.size(); k > 1; --k) std::swap(unguided[k - 1], unguided[rng.below(k)]);

  // Seeds r apart hold elements of radius ≤ 0.45 r without overlap; shrink r until enough
  // seeds clear the guided tubes.
  seeding.growth = options.initialScale;
  std::vector<Vec2> seeds;
  if (!unguided.empty()) {
    double r = std::sqrt(run.setup.containerArea / (0.866 * unguided.size()));
    for (int attempt = 0; attempt < 40; ++attempt, r *= 0.9) {
      BlueNoiseOptions noise;
      noise.radius = r;
      noise.boundaryMargin = 0.5 * r;
      noise.seed = options.run.seed * 31 + attempt;
      const double g = std::min(options.initialScale, 0.45 * r / largestRadius);
      seeds.clear();
      for (Vec2 p : blueNoiseSample(run.setup.container, noise)) {
        bool clear = true;
        for (int gi = 0; gi < guidedCount && clear; ++gi) {
          const AnimatedInstance& guided = instances[gi];
          const double reach = (types[guided.type].radius + largestRadius) * g * 1.2;
          for (int s = 0; s < slices && clear; ++s) clear = distance(p, guided.centre[s]) > reach;
        }
        if (clear) seeds.push_back(p);
      }
      if (seeds.size() >= unguided.size()) {
        seeding.growth = g;
        break;
      }
    }
    if (seeds.size() < unguided.size())
      throw InputError(run.scene.source, "the container has no room to seed " + std::to_string(unguided.size()) + " elements");
    for (std::size_t k = seeds.size(); k > 1; --k) std::swap(seeds[k - 1], seeds[rng.below(k)]);
  }
  std::vector<int> copies(types.size(), 0);
  for (std::size_t k = 0; k < unguided.size(); ++k) {
    const AnimatedType& type = types[unguided[k]];
    AnimatedInstance instance;
    instance.type = unguided[k];
    instance.copy = copies[unguided[k]]++;
    double angle;
    if (type.spec->orientation) {
      angle = -radians(*type.spec->orientation);
    } else if (type.spec->orientationFromField) {  // drawn facing +x: turned to face the field
      const Vec2 along = run.field->at(frame.toInput(seeds[k]));
      angle = std::atan2(along.y, along.x);
    } else {
      angle = rng.uniform(0.0, 2.0 * std::numbers::pi);
    }
    for (int s = 0; s < slices; ++s) {
      Vec2 sum;
      for (Vec2 p : type.shapes[s]) {
        const Vec2 q = seeds[k] + rotate(p, angle);
        instance.reference.push_back(q);
        sum += q;
      }
      instance.centre.push_back(sum / static_cast<double>(type.shapes[s].size()));
    }
    instances.push_back(std::move(instance));
  }
  return seeding;
}

SpacetimeSimulation spacetimeSimulation(const AnimationRun& run, const AnimationSeeding& seeding, ThreadPool& pool,
                                        const AnimationState* resumeFrom) {
  const AnimationOptions& options = run.options;
  const std::vector<AnimatedType>& types = run.types;
  const std::vector<AnimatedInstance>& instances = seeding.instances;
  const AnimationScript& script = run.script;
  const int slices = run.slices;
  SpacetimeSimulation sim(run.setup.containerIndex, run.setup.containerArea, slices, options.simulation, options.spacetime,
                          pool);
  for (const AnimatedInstance& instance : instances) {
    const AnimatedType& type = types[instance.type];
    SpacetimeElementSetup setup;
    setup.mesh = &run.meshes[type.mesh].mesh;
    setup.reference = instance.reference;
    setup.referenceCentre = instance.centre;
    setup.initialGrowth = seeding.growth;
    // Torsion toward each slice's reference: the seeded orientation turned by the rotation
    // track at that slice (instance.reference), so a full turn over the loop stays scripted.
    const bool oriented = type.spec->orientation || type.spec->orientationFromField;
    setup.torsionStrength = oriented ? options.simulation.torsionStrength : 0.0;
    setup.targets = instance.targets;
    setup.leavesContainer = type.spec->leavesContainer;
    sim.addElement(setup);
  }
  if (script.loop) {
    for (std::size_t e = 0; e < instances.size(); ++e) {
      const AnimatedType& type = types[instances[e].type];
      int to = static_cast<int>(e);
      if (!type.spec->loopTo.empty()) {
        bool found = false;
        for (std::size_t i = 0; i < types.size(); ++i)
          if (types[i].spec->id == type.spec->loopTo && seeding.guidedInstance[i] >= 0)
            to = seeding.guidedInstance[i], found = true;
        if (!found)
          throw InputError(script.source, "element '" + type.spec->id + "' loops to '" + type.spec->loopTo +
                                              "', which is not a guided element; loop_to joins guided elements");
      }
      const AnimatedType& toType = types[instances[to].type];
      if (toType.mesh != type.mesh)
        throw InputError(script.source, "element '" + type.spec->id + "' loops to '" + toType.spec->id +
                                            "', drawn from another SVG; a loop joins copies of one drawing");
      const ElementMesh& mesh = run.meshes[type.mesh].mesh;
      const int n = static_cast<int>(mesh.mesh.vertices.size());
      const Vec2* first = instances[to].reference.data();
      const Vec2* last = instances[e].reference.data() + (slices - 1) * n;
      std::vector<int> partner;
      if (mesh.symmetry > 1) partner = SpacetimeSimulation::loopPartners(first, last, n);
      const Vec2 turn = SpacetimeSimulation::loopTurn(first, last, n, partner.empty() ? nullptr : partner.data());
      sim.addLoop(static_cast<int>(e), to, turn, loopShift(*type.spec, *toType.spec) * run.setup.frame.scale,
                  std::move(partner));
    }
  }
  // The grid covers the container, and the path of any element that leaves it.
  Box area{{0.0, 0.0}, {kCanonicalSide, kCanonicalSide}};
  for (const AnimatedInstance& instance : instances)
    if (types[instance.type].spec->leavesContainer) {
      const double margin = types[instance.type].radius * options.spacetime.maxGrowth;
      for (Vec2 p : instance.reference) area.add(Box{p - Vec2{margin, margin}, p + Vec2{margin, margin}});
    }
  sim.finalize(area);
  if (resumeFrom) {
    if (resumeFrom->positions.size() != sim.vertexCount() || resumeFrom->growth.size() != sim.growth().size() ||
        resumeFrom->previousGrowth.size() != sim.growth().size() ||
        resumeFrom->neighbourOrigin.size() != sim.vertexCount() ||
        resumeFrom->velocities.size() != sim.vertexCount())
      throw InputError("--resume", "the checkpoint was made for other inputs or options (its sizes do not match)");
    sim.restoreState(resumeFrom->iteration, resumeFrom->positions, resumeFrom->velocities, resumeFrom->growth,
                     resumeFrom->previousGrowth, resumeFrom->neighbourOrigin);
  }
  return sim;
}

AnimationStop simulateAnimation(SpacetimeSimulation& sim, const AnimationRun& run, const AnimationCallbacks& callbacks,
                                const AnimationState* resumeFrom) {
  const AnimationOptions& options = run.options;
  // Mean growth of the last stallWindow + 1 iterations, by iteration number; checkpoints keep
  // it, so a resumed run stops where the uninterrupted one does.
  StallWindow meanGrowth(options.stop.stallWindow);
  if (resumeFrom && !resumeFrom->recentMeanGrowth.empty()) {
    if (resumeFrom->recentMeanGrowth.size() != meanGrowth.values().size())
      throw InputError("--resume", "the checkpoint was made with another --stall-window");
    if (resumeFrom->recorded > resumeFrom->iteration)
      throw InputError("--resume", "the checkpoint is damaged (it recorded more iterations than it ran)");
    meanGrowth.restore(resumeFrom->recentMeanGrowth, resumeFrom->recorded, resumeFrom->iteration);
  }
  auto progress = [&] {
    AnimationProgress p;
    p.iteration = sim.iteration();
    p.fill = sim.fill();
    p.growingSlices = sim.growingSlices();
    p.overlappingSlices = sim.overlappingSlices();
    p.slices = static_cast<int>(sim.growth().size());
    p.largestSliceGap = sim.largestSliceGap();
    p.minGrowth = sim.minGrowth();
    p.growthRise = meanGrowth.full() ? meanGrowth.rise() : std::numeric_limits<double>::infinity();
    if (sim.settleSteps() > 0) p.settleLeft = options.stop.settleIterations - sim.settleSteps();
    return p;
  };
  auto state = [&] {
    return AnimationState{sim.iteration(), sim.positions(), sim.velocities(), sim.growth(), sim.previousGrowth(),
                          sim.neighbourOrigin(),
                          meanGrowth.values(), meanGrowth.recorded()};
  };
  const Deadline deadline(run.started, options.stop.timeLimit, options.run.stopRequest);
  const std::optional<AnimationStop> stop = runUntilStopped<AnimationStop>(
      sim, options.stop.maxIterations, meanGrowth,
      [&] {
        double mean = 0.0;
        for (double g : sim.growth()) mean += g;
        return mean / static_cast<double>(sim.growth().size());
      },
      [&](int it) {
        if (callbacks.onCheckpoint && callbacks.checkpointEvery > 0 && it % callbacks.checkpointEvery == 0)
          callbacks.onCheckpoint(state());
        if (callbacks.onProgress && callbacks.progressEvery > 0 && it % callbacks.progressEvery == 0)
          callbacks.onProgress(progress());
      },
      [&](const StallWindow& window) -> std::optional<AnimationStop> {
        if (sim.largestSliceGap() < options.stop.closeness) return AnimationStop::AllTouching;  // 0: never
        if (sim.minGrowth() >= options.spacetime.maxGrowth) return AnimationStop::GrowthCap;
        if (window.full() && window.rise() < options.stop.stallGrowth) return AnimationStop::Stalled;
        if (deadline.passed()) return deadline.requested() ? AnimationStop::Interrupted : AnimationStop::TimeLimit;
        return std::nullopt;
      });
  // The settle: after every checkpoint, so a resumed run settles the same state. The time
  // limit and a stop request skip it or end it (its steps are in the report).
  if (options.stop.settleIterations > 0) {
    sim.beginSettle(options.stop.settleOverlapStrength);
    for (int k = 1; k <= options.stop.settleIterations && !deadline.passed(); ++k) {
      sim.step();
      if (callbacks.onProgress && callbacks.progressEvery > 0 && k % callbacks.progressEvery == 0 &&
          k < options.stop.settleIterations)  // the last one is printed below
        callbacks.onProgress(progress());
    }
  }
  if (callbacks.onProgress) callbacks.onProgress(progress());
  sim.projectInside();  // after any checkpoint: a resumed run projects the same state
  return stop.value_or(AnimationStop::IterationCap);
}

AnimatedPacking collectAnimation(const AnimationRun& run, const AnimationSeeding& seeding, const SpacetimeSimulation& sim,
                                 AnimationStop stop, ThreadPool& pool) {
  const CanonicalFrame& frame = run.setup.frame;
  const int slices = run.slices;
  AnimatedPacking result;
  result.stopReason = stop;
  for (std::size_t e = 0; e < seeding.instances.size(); ++e) {
    const AnimatedType& type = run.types[seeding.instances[e].type];
    const PreparedElement& shared = run.meshes[type.mesh];
    AnimatedElement out;
    out.id = type.spec->id;
    out.source = type.source;
    out.copy = seeding.instances[e].copy;
    out.guided = !type.spec->targets.empty();
    out.leavesContainer = type.spec->leavesContainer;
    if (run.script.loop) out.loopShift = loopShift(*type.spec, loopPartner(run.script, *type.spec));
    out.mesh = shared.mesh;
    out.art = shared.art;
    out.restSkinArea = shared.mesh.skinArea;
    const int n = sim.verticesPerSlice(static_cast<int>(e));
    const int begin = sim.vertexBegin(static_cast<int>(e));
    out.slices.resize(slices);
    for (int s = 0; s < slices; ++s) {
      std::vector<Vec2>& vertices = out.slices[s];
      vertices.resize(n);
      for (int v = 0; v < n; ++v) vertices[v] = spatial(sim.positions()[begin + s * n + v]);
      out.sliceTimes.push_back(sim.positions()[begin + s * n].t / run.options.spacetime.timeLength);
      out.sliceGrowth.push_back(sim.growth()[e * slices + s]);
    }
    result.elements.push_back(std::move(out));
  }
  // A slice whose art folds over itself (a limb pressed across the body; the spacetime forces
  // do not see the art) is relaxed toward its animated rest shape, as RepulsionPak's clean-up
  // does; then a pair of slices whose interpolation folds between them (seen at 32nds of the
  // way: eighths missed a fold that a 500-frame render of 100 slices met at a fifth) is relaxed
  // together, pass after pass while one changes, so no rendered frame folds. Elements are
  // independent: in parallel.
  constexpr int kBetween = 32, kPasses = 3;
  std::vector<int> unfolded(result.elements.size(), 0);
  pool.parallelFor(result.elements.size(), 1, [&](std::size_t elementBegin, std::size_t elementEnd) {
    std::vector<Vec2> crossings, artPoints, between;
    Ring ring;
    for (std::size_t e = elementBegin; e < elementEnd; ++e) {
      const AnimatedInstance& instance = seeding.instances[e];
      const PreparedElement& element = run.meshes[run.types[instance.type].mesh];
      AnimatedElement& out = result.elements[e];
      const int n = static_cast<int>(out.slices[0].size());
      auto foldOf = [&](const std::vector<Vec2>& vertices) -> std::optional<Vec2> {
        crossings.clear();
        appendArtFolds(element, vertices.data(), crossings, artPoints, ring);
        if (crossings.empty()) return std::nullopt;
        return crossings.front();
      };
      auto restore = [&](int s, double keep, Vec2 at, double radius) {
        blendTowardRest(out.slices[s].data(), instance.reference.data() + static_cast<std::ptrdiff_t>(s) * n, n,
                        out.sliceGrowth[s], keep, at, radius, [](int) {});
      };
      const double cell = run.options.simulation.cellSize;
      for (int s = 0; s < slices; ++s)
        if (relaxFold(cell, [&] { return foldOf(out.slices[s]); },
                      [&](double keep, Vec2 at, double radius) { restore(s, keep, at, radius); }))
          ++unfolded[e];
      auto unfoldPair = [&](int s) {  // whether slices s and s + 1 had to be relaxed
        const std::vector<Vec2>&a = out.slices[s], &b = out.slices[s + 1];
        auto foldBetween = [&]() -> std::optional<Vec2> {
          between.resize(a.size());
          for (int k = 1; k < kBetween; ++k) {
            const double w = static_cast<double>(k) / kBetween;
            for (std::size_t v = 0; v < a.size(); ++v) between[v] = a[v] + (b[v] - a[v]) * w;
            if (const std::optional<Vec2> at = foldOf(between)) return at;
          }
          return std::nullopt;
        };
        auto restoreBoth = [&](double keep, Vec2 at, double radius) {
          restore(s, keep, at, radius);
          restore(s + 1, keep, at, radius);
        };
        return relaxFold(cell, foldBetween, restoreBoth);
      };
      // Relaxing a pair moves a slice of the pairs beside it: another pass checks them again.
      for (int pass = 0, changed = 1; pass < kPasses && changed; ++pass) {
        changed = 0;
        for (int s = 0; s + 1 < slices; ++s)
          if (unfoldPair(s)) unfolded[e] += 2, changed = 1;
      }
      for (std::vector<Vec2>& vertices : out.slices)
        for (Vec2& p : vertices) p = frame.toInput(p);
    }
  });
  for (int count : unfolded) result.unfoldedSlices += count;
  result.container = run.scene.container;
  result.fixedArt = run.fixedArt;
  result.canonicalScale = frame.scale;
  result.iterations = sim.iteration();
  result.settleIterations = sim.settleSteps();
  result.fill = sim.fill();
  result.overlappingSlices = sim.overlappingSlices();
  result.vertices = sim.vertexCount();
  result.springs = sim.springCount();
  result.envelopeTriangles = sim.envelopeTriangleCount();
  result.slices = slices;
  result.threads = pool.threadCount();
  result.seed = run.options.run.seed;
  return result;
}

}  // namespace pak
