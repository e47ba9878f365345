#pragma once
// RepulsionPak's phases (thesis 4.4–4.6), in the order packRepulsion runs them:
//
//   prepare → seed → shrink → simulate (primary) → collect → secondary pass
//
// Each is a function of what the earlier ones made, so a test can run them one by one.
#include <chrono>
#include <functional>
#include <optional>
#include <vector>

#include "pak/repulsion/orientation.hpp"
#include "pak/repulsion/repulsion.hpp"
#include "repulsion/corner_docking.hpp"
#include "repulsion/packing_simulation.hpp"
#include "repulsion/seeding.hpp"
#include "sim/packing_setup.hpp"
#include "sim/parallel.hpp"
#include "sim/prepared_element.hpp"

namespace pak {

// What every phase reads: set by prepareRepulsion, then constant. The simulations keep
// references into it, so it stays where it was made.
struct RepulsionRun {
  const Scene& scene;
  RepulsionOptions options;
  PackingSetup setup;
  Region fixedArt;                // input: what the fixed elements paint inside the container
  int count = 0;                  // primaries to seed
  double nominalSkinArea = 0.0;   // of an average primary at growth 1 (canonical units²)
  double spacing = 0.0;           // mesh sample spacing (canonical units)
  std::vector<PreparedElement> types;
  OrientationRamp ramp;           // the preferred angle per position, when oriented by a field
  Vec2 period;                    // the tile in canonical units; 0: not tiled
  SimulationParameters parameters;  // as resolved for this run
  PackingDomain domain;
  Box simulationArea;             // what the neighbour grid covers
  std::chrono::steady_clock::time_point started;
};

// Checks the options, sets up the containers and prepares the primary library. Throws
// InputError for bad options, an empty library or a container without room.
RepulsionRun prepareRepulsion(const Scene& scene, const Library& library, const RepulsionOptions& options);

struct Seeding {
  std::vector<Seed> seeds;
  std::optional<CornerDocking> docking;  // shape matching (4.7)
  double matchingSeconds = 0.0;
  double growth = 1.0;                   // g every seed starts with
};

// Evenly spread seeds per container, at their preferred angles when oriented, with the
// shape-matched elements taking the seeds nearest the salient corners (4.4, 4.7).
Seeding seedPrimaries(const RepulsionRun& run);
// Shrinks every seed alike until the skins cover the initial coverage without overlap.
void shrinkSeeds(const RepulsionRun& run, Seeding& seeding);

// The containers as a simulation sees them: one boundary per part, reflex corners, orientation.
void setUpContainers(const RepulsionRun& run, PackingSimulation& sim);
// The primary simulation with the seeded meshes, finalized.
PackingSimulation primarySimulation(const RepulsionRun& run, const Seeding& seeding, ThreadPool& pool);

// Pressing after a pass and before its clean-up: `iterations` steps (or until the time limit)
// in which nothing grows or shrinks and every mesh not pressed deeper than a quarter of the
// gap into another bulges into the pockets next to it (PackingSimulation::press). Returns the
// iterations it took.
int press(PackingSimulation& sim, const RepulsionRun& run, const RepulsionStopRule& stop, int iterations);
// The clean-up after a pass, at most RepulsionStopRule::settleIterations steps with nothing
// growing: each element deeper than a quarter of the gap inside another or pushed out of the
// container shrinks until none is; then, while some element's art crosses itself, a few rounds
// that pull the mesh around each crossing toward its rest shape
// (SimulationParameters::unfoldStrength) and shrink again what that pushed in. Returns the
// iterations it took.
int settle(PackingSimulation& sim, const RepulsionRun& run, const RepulsionStopRule& stop,
           const std::vector<PreparedElement>& types);
// Each filled art ring of a non-frozen mesh that crosses itself, replayed, where it is not drawn so.
struct Fold { int mesh; Vec2 at; };
std::vector<Fold> foldedMeshes(const PackingSimulation& sim, const std::vector<PreparedElement>& types);
// Each folded mesh is moved back toward its best-fit rest shape while it still folds: the
// mesh around the crossing in widening patches, then the whole mesh, at last all the way.
// Returns, per mesh, whether it was moved (non-zero).
std::vector<char> relaxFolds(PackingSimulation& sim, const std::vector<PreparedElement>& types);

// Steps until `targetFill`, eq. 4.7 under `stop`, the time limit or the iteration cap
// (4.5.2). Progress and snapshots count iterations on from `iterationOffset`.
StopReason simulate(PackingSimulation& sim, const RepulsionRun& run, const RepulsionStopRule& stop, double targetFill,
                    int iterationOffset, const RepulsionCallbacks& callbacks,
                    const std::function<Packing()>& snapshot);

// The simulation's meshes as placed elements with their art replayed, in input coordinates.
Packing collectPacking(const RepulsionRun& run, const PackingSimulation& sim, const std::vector<PreparedElement>& types);
// Whether no element's art overlaps another's or the fixed art, or leaves the container, by
// more than verifyPacking's tolerance (as `pak pack` checks it).
bool artIsClean(const Packing& packing);
// The elements whose art overlaps another's or the fixed art, or leaves the container, by
// more than verifyPacking's tolerance.
std::vector<std::size_t> artOffenders(const Packing& packing);
// The same, as the simulation stands, building only the art (not the whole packing).
std::vector<std::size_t> artOffenders(const RepulsionRun& run, const PackingSimulation& sim,
                                      const std::vector<PreparedElement>& types);
// The packing after the art clean-up: vertices left outside projected in, then what still
// overlaps or leaves the container contracted a little (PackingSimulation::contractMesh).
Packing cleanArt(const RepulsionRun& run, PackingSimulation& sim, const std::vector<PreparedElement>& types);
// The primary pass's packing: art clean (vertices left outside projected in), statistics set.
Packing collectPrimary(const RepulsionRun& run, PackingSimulation& sim, const Seeding& seeding, StopReason reason);

// Secondary elements (4.6) in the pockets the primaries left, the primaries frozen. Adds
// the pass to `packing` (and its elements, when any pocket was found).
void secondaryPass(const RepulsionRun& run, const PackingSimulation& primary, const Library& secondaryLibrary,
                   ThreadPool& pool, const RepulsionCallbacks& callbacks, Packing& packing);

}  // namespace pak
