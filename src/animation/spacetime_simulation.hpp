#pragma once
// The AnimationPak simulation (thesis 5.5): spacetime elements — stacks of mesh slices joined
// by time springs — repel, deform and grow in (x, y, t) inside the container extruded along t.
// It is RepulsionPak's mass-spring scheme in one more dimension, on the same core (src/sim):
// the same force laws (sim/forces.hpp), the same explicit Euler step with damping and a
// velocity cap (sim/explicit_euler.hpp), the same growth rule, hit list and adjacency tables,
// forces from a frozen snapshot in parallel (results do not depend on the thread count), and
// no allocation inside `step` once its buffers have grown. What is new: the envelope
// triangles' neighbour search (5.5.1, SpacetimeNeighbours), the temporal force, target-point
// springs, the slice constraints (5.5.2) and per-slice growth (5.5.3).
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "pak/animation/spacetime_parameters.hpp"
#include "pak/geom/vec3.hpp"
#include "pak/sim/element_mesh.hpp"
#include "pak/sim/simulation_parameters.hpp"
#include "animation/spacetime_neighbours.hpp"
#include "sim/explicit_euler.hpp"
#include "sim/growth_rule.hpp"
#include "sim/parallel.hpp"
#include "sim/region_index.hpp"
#include "sim/vertex_adjacency.hpp"

namespace pak {

// One spacetime element as the simulation receives it. `reference` holds, slice-major, every
// slice's vertex positions at growth 1 (animated, rotated and moved: the "reference element"
// of thesis 5.5.3); growth g scales a slice's reference about `referenceCentre[slice]`.
struct SpacetimeElementSetup {
  const ElementMesh* mesh = nullptr;    // the slice mesh (triangles, springs, skin ring)
  std::vector<Vec2> reference;          // slices × mesh vertices
  std::vector<Vec2> referenceCentre;    // one per slice
  double initialGrowth = 0.1;
  // > 0: each slice keeps its reference's orientation (k_tor), which includes the scripted
  // rotation at that slice, so an element turns in place as scripted (Fig. 5.16).
  double torsionStrength = 0.0;
  struct Target { int slice; int vertex; Vec2 position; };
  std::vector<Target> targets;          // target-point springs (guided elements, 5.4)
  // No boundary force: the element may leave the container (a travelling bird, Fig. 5.17). A
  // slice partly outside does not grow by the common rule, only up to the guided floor
  // (SpacetimeParameters::guidedGrowth), and counts as touching the wall.
  bool leavesContainer = false;
};

class SpacetimeSimulation {
 public:
  // `parameters` as resolved by the packer: a positive cell size, the exact repulsion reach.
  SpacetimeSimulation(const RegionIndex& container, double containerArea, int slices,
                      const SimulationParameters& parameters, const SpacetimeParameters& spacetime, ThreadPool& pool);

  int addElement(const SpacetimeElementSetup& setup);
  // Loop constraint (5.5.2): `from`'s last slice joins `to`'s first slice (same mesh). The
  // thesis moves corresponding vertices to their mean; here the slices must agree up to the
  // scripted turn and scale between them, `turn` = (s cos θ, s sin θ) (see loopTurn), so a star
  // that turns by 72° over the loop is joined to itself without being squeezed. With no turn,
  // (1, 0), this is the thesis's rule exactly. `shift` (canonical x, y): the last slice joins
  // the first one moved by it, so an element can leave on one side and come back on the other
  // (a composition that tiles). `partner` (empty: the identity) pairs the last slice's vertex
  // i with the first slice's vertex partner[i]: in a mesh with the turn's symmetry
  // (ElementMeshOptions::symmetry), the one at the same place once turned, so that the two
  // slices are joined point for point in the container, as the thesis joins an unturned loop,
  // and what is left of `turn` is its scale.
  void addLoop(int from, int to, Vec2 turn, Vec2 shift = {}, std::vector<int> partner = {});
  // The similarity (s cos θ, s sin θ) that best maps the centred points `first` (taken as
  // first[partner[i]] when `partner` is given) onto `last`.
  static Vec2 loopTurn(const Vec2* first, const Vec2* last, int count, const int* partner = nullptr);
  // For a mesh with the turn's symmetry, the partner of each of `last`'s points: the one of
  // `first` at its place up to the loop's scale and the centres, within a millionth of the
  // points' extent. Empty when some point has no such partner or all are their own.
  static std::vector<int> loopPartners(const Vec2* first, const Vec2* last, int count);
  // Moves every vertex left outside the container onto its boundary, a hair inside (the
  // boundary force is a penalty, so pressed vertices rest slightly outside), except those of
  // elements that may leave the container. Returns how many.
  int projectInside();
  // Builds the spring tables, the envelope and the grid over `area` (canonical x, y).
  void finalize(const Box& area);

  void step();
  // From now on nothing grows and the overlap force has this strength (the settle after the
  // stop, AnimationStopRule::settleIterations).
  void beginSettle(double overlapStrength);
  int settleSteps() const { return settleFrom_ < 0 ? 0 : iteration_ - settleFrom_; }

  // --- state (what a checkpoint saves; everything else is rebuilt from the inputs)
  int iteration() const { return iteration_; }
  const std::vector<Vec3>& positions() const { return position_; }
  const std::vector<Vec3>& velocities() const { return velocity_; }
  const std::vector<double>& growth() const { return growth_; }  // per slice
  // Each slice's g before the last step's growth: one that did not grow feels the pocket
  // pressure in the next step.
  const std::vector<double>& previousGrowth() const { return previousGrowth_; }
  // Where the vertices were when the neighbour lists were last built (SpacetimeNeighbours).
  const std::vector<Vec3>& neighbourOrigin() const { return neighbours_->origin(); }
  void restoreState(int iteration, std::vector<Vec3> positions, std::vector<Vec3> velocities, std::vector<double> growth,
                    std::vector<double> previousGrowth, const std::vector<Vec3>& neighbourOrigin);

  // --- layout and measurements
  int slices() const { return slices_; }
  int elementCount() const { return static_cast<int>(elements_.size()); }
  int vertexBegin(int element) const { return elements_[element].vertexBegin; }
  int verticesPerSlice(int element) const { return elements_[element].verticesPerSlice; }
  std::size_t vertexCount() const { return position_.size(); }
  std::size_t springCount() const { return springsAt_.entries.size() / 2; }
  std::size_t envelopeTriangleCount() const { return neighbours_->triangleCount(); }
  // Mean over slices of the skins' area over the container area.
  double fill() const { return fill_; }
  // Slices still allowed to grow, and slices overlapping another element after the last step.
  int growingSlices() const { return growingSlices_; }
  int overlappingSlices() const { return overlappingSlices_; }
  // Largest over slices of the slice's distance to its nearest neighbour or wall (5.5.3).
  double largestSliceGap() const { return largestSliceGap_; }
  double minGrowth() const;
  bool sliceOverlapping(int globalSlice) const { return sliceOverlapping_[globalSlice] != 0; }

 private:
  struct ElementRecord {
    const ElementMesh* mesh;
    int vertexBegin, verticesPerSlice, sliceBegin;
    double torsionStrength;
    bool guided;  // has target points
    bool leavesContainer;
    GrowthRule growth;  // its slices' growth: the common rate, or slower for a large element
  };
  void computeReferencePoints(std::size_t begin, std::size_t end);
  // The cross-sections insideElementAt last interpolated. The skin vertices of one slice share
  // their time, so consecutive queries ask for the same few: each is interpolated once.
  struct CrossSections {
    static constexpr int kEntries = 4, kMaxRing = 256;
    struct Entry { int element = -1; double t = 0.0; bool within = false; };
    std::array<Entry, kEntries> entries;
    std::array<std::array<Vec2, kMaxRing>, kEntries> rings;
    int next = 0;
  };
  bool insideElementAt(int element, Vec3 x, CrossSections& cache) const;
  void computeForces(std::size_t begin, std::size_t end);
  void integrate(std::size_t begin, std::size_t end);
  void applySliceConstraints(std::size_t elementBegin, std::size_t elementEnd);
  void applyLoopConstraints();
  void updateSlices(std::size_t begin, std::size_t end);
  void computeSliceCentres();
  // SpacetimeParameters::guidedGrowth: after the common growth rule, a guided slice below the
  // share of its slice index's median unguided g grows a step regardless of contacts.
  void keepGuidedUp();
  bool sliceOutside(std::size_t s) const;

  const RegionIndex& container_;
  double containerArea_;
  int slices_;
  SimulationParameters parameters_;
  SpacetimeParameters spacetime_;
  ExplicitEuler integrator_;
  int settleFrom_ = -1;  // the iteration of beginSettle (growth frozen from then), or -1
  ThreadPool& pool_;
  bool finalized_ = false;
  int iteration_ = 0;
  double fill_ = 0.0, largestSliceGap_ = 0.0;
  int growingSlices_ = 0, overlappingSlices_ = 0;

  std::vector<ElementRecord> elements_;
  // Per vertex.
  std::vector<Vec3> position_, velocity_, force_, referencePoint_;
  std::vector<Vec2> reference_;            // at growth 1
  std::vector<int> sliceOf_;               // global slice index
  std::vector<std::uint8_t> isBoundary_, insideOther_;
  std::vector<double> outsideDepth_;  // how far past the wall (0: inside; kFar: out where an element may leave)
  std::vector<double> nearestGap_;         // distance to the nearest other element or wall
  std::vector<Vec2> targetPull_;           // target-point spring anchor, per vertex (NaN: none)
  // Springs by vertex (each spring appears at both ends). There are a few stiffnesses (edge,
  // negative-space and time springs), so an end names its kind: half the bytes to read a step.
  struct SpringEnd { int other, kind; };
  VertexAdjacency<SpringEnd> springsAt_;
  std::vector<double> springStiffness_;  // by kind
  std::vector<double> springRest_;  // per spring end: its rest length, as last computed
  // Incident in-slice triangles by vertex (their corners), for the overlap force.
  VertexAdjacency<std::array<int, 3>> trianglesAt_;
  // Per global slice.
  std::vector<int> sliceElement_, sliceVertexBegin_;
  std::vector<double> growth_, previousGrowth_, sliceTime_, restTime_;
  // Per slice, whether its growth changed since the last step (then its springs' kept rest
  // lengths are computed again), and whether none is kept yet (before the first step, after a
  // restore).
  std::vector<std::uint8_t> growthChanged_;
  bool restLengthsStale_ = true;
  std::vector<double> unguidedGrowth_;  // scratch for keepGuidedUp, one per element
  std::vector<Vec2> referenceCentre_, sliceCentre_;
  std::vector<std::uint8_t> sliceOverlapping_;
  std::vector<double> sliceGap_, sliceArea_, sliceOutsideDepth_;
  // Envelope triangles (5.5.1), until finalize hands them to the neighbour search.
  std::vector<std::array<int, 3>> envelope_;
  std::vector<int> envelopeElement_;
  std::optional<SpacetimeNeighbours> neighbours_;
  // Loops.
  struct Loop { int from, to; Vec2 turn, shift; std::vector<int> partner; };
  std::vector<Loop> loops_;
  // Build-time only.
  struct PendingSpring { int a, b; double stiffness; };
  std::vector<PendingSpring> pending_;
  std::vector<SpacetimeElementSetup::Target> pendingTargets_;
};

}  // namespace pak
