#pragma once
// AnimationPak's phases (thesis 5.4–5.6), in the order packAnimation runs them:
//
//   prepare → seed (guided elements on their targets, the others on blue noise, all shrunk
//   to fit: 5.4 finds the seed spacing and the shrink together) → simulate → collect
//
// Each is a function of what the earlier ones made, so a test can run them one by one.
#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "animation/spacetime_simulation.hpp"
#include "pak/animation/animation.hpp"
#include "pak/flow/vector_field.hpp"
#include "sim/packing_setup.hpp"
#include "sim/parallel.hpp"
#include "sim/prepared_element.hpp"

namespace pak {

// One script element: the mesh it copies and its animated rest shape in every slice.
struct AnimatedType {
  const AnimatedElementSpec* spec = nullptr;
  std::string source;
  int mesh = 0;                             // into AnimationRun::meshes (one per SVG file)
  std::vector<std::vector<Vec2>> shapes;    // per slice, centred (canonical, growth 1)
  double radius = 0.0;                      // largest |vertex| over all slices
};

// What every phase reads: set by prepareAnimation, then constant. The simulation keeps
// references into it, so it stays where it was made.
struct AnimationRun {
  const Scene& scene;
  const AnimationScript& script;
  AnimationOptions options;
  int slices = 0;
  PackingSetup setup;
  std::vector<PreparedElement> meshes;  // one per SVG file, so loops may join copies of different entries
  std::vector<AnimatedType> types;      // one per script element
  std::chrono::steady_clock::time_point started;
  Region fixedArt;                      // input: what the fixed elements paint inside the container
  // FLOWPAK's vector field from the scene's guides (input units), when an element takes its
  // orientation from it ("orientation": "field").
  std::optional<VectorField> field;
};

// Checks the options and the script, sets up the container and prepares the meshes and the
// animated shapes. Throws InputError for bad options or inputs.
AnimationRun prepareAnimation(const Scene& scene, const Library& library, const AnimationScript& script,
                              const AnimationOptions& options);

// One element of the packing and its reference slices at growth 1.
struct AnimatedInstance {
  int type = 0;
  int copy = 0;
  std::vector<Vec2> reference;           // slices × vertices
  std::vector<Vec2> centre;              // per slice
  std::vector<SpacetimeElementSetup::Target> targets;
};

struct AnimationSeeding {
  std::vector<AnimatedInstance> instances;  // the guided ones first
  std::vector<int> guidedInstance;          // per type: its guided instance, or -1
  double growth = 1.0;                      // g every slice starts with
};

// The initial configuration (5.4).
AnimationSeeding seedAnimation(const AnimationRun& run);

// The spacetime simulation with every element and loop added, finalized, and restored from
// `resumeFrom` when given.
SpacetimeSimulation spacetimeSimulation(const AnimationRun& run, const AnimationSeeding& seeding, ThreadPool& pool,
                                        const AnimationState* resumeFrom);

// Steps until every slice touches, the growth cap, the stall rule, the time limit or the
// iteration cap (5.5.3); the stall window resumes from `resumeFrom` when given. Projects the
// vertices left outside back in at the end.
AnimationStop simulateAnimation(SpacetimeSimulation& sim, const AnimationRun& run, const AnimationCallbacks& callbacks,
                                const AnimationState* resumeFrom);

// The slices in input coordinates, with the run's statistics.
AnimatedPacking collectAnimation(const AnimationRun& run, const AnimationSeeding& seeding, const SpacetimeSimulation& sim,
                                 AnimationStop stop, ThreadPool& pool);

}  // namespace pak
