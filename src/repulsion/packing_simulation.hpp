#pragma once
// The RepulsionPak mass-spring simulation (thesis 4.5): all meshes' vertices in contiguous
// arrays, forces computed from a frozen snapshot of positions (Jacobi) in parallel, then the
// shared explicit Euler step (sim/explicit_euler.hpp), then growth (sim/growth_rule.hpp).
// Nothing is allocated inside `step`.
#include <algorithm>
#include <array>
#include <cassert>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "pak/repulsion/orientation.hpp"
#include "pak/sim/element_mesh.hpp"
#include "pak/sim/simulation_parameters.hpp"
#include "sim/explicit_euler.hpp"
#include "sim/growth_rule.hpp"
#include "sim/nearest_hits.hpp"
#include "sim/parallel.hpp"
#include "sim/region_index.hpp"
#include "sim/segment_grid.hpp"
#include "sim/vertex_adjacency.hpp"

namespace pak {

// What the simulation needs beyond the user's constants, from the packing it runs.
struct PackingDomain {
  double occupiedArea = 0.0;  // container area taken by obstacles (fixed elements), counted in fill
  // Tile W × H (thesis 4.8): a periodic domain [0, W] × [0, H]; every mesh also acts through
  // its clones at offsets (k W, l H), k, l ∈ {-1, 0, 1}, and there are no walls. 0: off.
  Vec2 period{};
};

struct MeshInstance {
  int type = 0;                 // which prepared mesh it copies
  int vertexBegin = 0, vertexCount = 0, boundaryCount = 0;
  int segmentBegin = 0;         // its skin segments in the global segment list
  int triangleBegin = 0, triangleCount = 0;
  double growth = 1.0;          // g: rest lengths are restLength × g
  bool frozen = false;          // frozen meshes repel others but do not move or grow
  bool overlapping = false;     // some vertex is inside another mesh
  // Some vertex is deeper than the settle depth inside another mesh or out of the container,
  // or a reflex container corner is inside it: what the clean-up shrinks.
  bool deep = false;
  bool outside = false;         // some vertex is outside the container
  double area = 0.0;            // area enclosed by its skin, updated every step
  double restArea = 0.0;        // skin area at growth 1
  int container = 0;            // which of setContainerParts' regions holds it
  double restAngle = 0.0;       // the angle it was added with (radians)
  double settleFloor = -1.0;    // the clean-up shrinks it no smaller than this growth (< 0: not set yet)
};

class PackingSimulation {
 public:
  // `parameters` as resolved by the packer: a positive cell size.
  PackingSimulation(const RegionIndex& container, double containerArea, const SimulationParameters& parameters,
                    ThreadPool& pool, const PackingDomain& domain = {});

  // Places a copy of `mesh` scaled by `growth`, rotated by `angle` (radians) and centred at
  // `position`. Call `finalize` after the last one, and `step` only after `finalize`.
  int addMesh(const ElementMesh& mesh, int type, Vec2 position, double angle, double growth, bool frozen = false);
  // Builds the adjacency tables and sizes the neighbour grid over `area`.
  void finalize(const Box& area);
  // Reflex (inward-pointing) corners of the container: the boundary force acts on vertices
  // only, so such a corner could poke into a mesh between two of its vertices. A corner found
  // inside a mesh pushes the mesh's nearest skin segment off it along `inward` and blocks the
  // mesh's growth. Computed by `reflexCorners`.
  struct Corner { Vec2 position; Vec2 inward; int container = -1; };  // -1: acts on every mesh
  void setContainerCorners(std::vector<Corner> corners) { corners_ = std::move(corners); }
  static std::vector<Corner> reflexCorners(const Region& container);
  // Several separate containers: each mesh is kept inside parts[mesh.container] (and out of
  // its holes) instead of the constructor's region. The indexes must outlive the simulation.
  void setContainerParts(std::vector<const RegionIndex*> parts) { parts_ = std::move(parts); }
  // Torsion (eq. 4.6) toward the field's angle at each mesh's current centre instead of the
  // angle it was added with. Call before `finalize`.
  void setOrientationField(const OrientationRamp& ramp) {
    assert(!finalized_);
    orientationRamp_ = ramp;
  }
  // Docking springs (shape matching, thesis 4.7): each pulls one vertex toward its anchor with
  // force strength × (anchor − x), holding a matched element at its container corner.
  struct Dock { int vertex; Vec2 anchor; };
  void setDocks(std::vector<Dock> docks, double strength) { docks_ = std::move(docks); dockStrength_ = strength; }

  // Growth: Grow (thesis 4.5.1: meshes with room grow; the pocket pressure acts on those that
  // stopped), Press or Settle. In both of these nothing grows, and the pocket pressure acts on
  // every mesh but one with a vertex deeper than `depth` inside another (it would keep it in).
  // Press: nothing shrinks either.
  // Settle (the clean-up after a pass): a mesh with a vertex deeper than `depth` inside another
  // one, or pushed out of the container, shrinks a growth step, to no less than floorShare ×
  // its growth now, or the floor it already has (settleFloor ≥ 0).
  void grow();
  void press(double depth) {
    mode_ = Mode::Press;
    settleDepth2_ = depth * depth;
  }
  void settle(double depth, double floorShare) {
    mode_ = Mode::Settle;
    settleDepth2_ = depth * depth;
    for (MeshInstance& m : meshes_)
      if (m.settleFloor < 0.0) m.settleFloor = m.growth * floorShare;
  }
  // Meshes the clean-up still shrinks: not frozen, with a vertex deeper than the settle depth
  // inside another mesh or beyond the tolerance outside the container.
  static bool needsSettling(const MeshInstance& m) { return !m.frozen && m.deep && m.growth > m.settleFloor; }
  // The clean-up's unfolding: until `grow`, the vertices of `mesh` within `radius` of `point`
  // are also pulled toward their rest shape, rotated and scaled to fit them best, with
  // `strength` per unit of distance. Vertices already so held stay in their group, which is
  // held at least as strongly from then on. An infinite radius holds the whole mesh.
  void restoreAround(int mesh, Vec2 point, double radius, double strength);

  int unsettledCount() const;

  void step();
  // Moves every vertex left outside its container onto the container's boundary, a hair
  // inside (the boundary force is a penalty, so a pressed vertex rests slightly outside).
  // Frozen meshes and periodic runs are left alone. Returns how many vertices moved.
  int projectInside();
  // Scales the mesh's vertex positions about their mean by `factor` (the last resort of the
  // art clean-up: a tip left across the wall, or a sliver of overlap, between two vertices).
  void contractMesh(int mesh, double factor);
  // The last resort for a fold the clean-up could not undo: the vertices within `radius` of
  // `around` move toward the mesh's rest shape (at its growth, rotated and placed to fit them
  // best), to `keep` of the way from it at `around` and less farther out. An infinite radius
  // moves the whole mesh, and keep 0 then gives the rest shape, which does not fold.
  void restoreRestShape(int mesh, double keep, Vec2 around, double radius);
  // Holds each marked mesh whole in its best-fit rest shape (restoreAround with an infinite
  // radius) and stands every other one still, so that only the held ones give way.
  void holdRestShapes(const std::vector<char>& held, double strength);
  // Ends every restoreAround hold, and the standing still of holdRestShapes (grow does too).
  void releaseHolds();

  // Skin area of all meshes over the container area.
  double fill() const { return fill_; }
  // Rest area of all meshes (skin area at rest × g²) over the container area: changes only
  // through growth, so it measures progress without the jitter of the vertices.
  double restFill() const { return restFill_; }
  int growingCount() const;
  int iteration() const { return iteration_; }
  const std::vector<MeshInstance>& meshes() const { return meshes_; }
  std::vector<MeshInstance>& meshes() { return meshes_; }
  const std::vector<Vec2>& positions() const { return position_; }
  std::vector<Vec2>& positions() { return position_; }
  const std::vector<Vec2>& velocities() const { return velocity_; }
  const std::vector<Vec2>& forces() const { return force_; }
  static bool canGrow(const MeshInstance& m) { return !m.frozen && !m.overlapping && !m.outside; }
  bool vertexInsideOther(int v) const { return insideOther_[v] != 0; }
  bool vertexOutsideContainer(int v) const { return outsideDepth_[v] > parameters_.outsideTolerance; }
  std::size_t springCount() const { return springsAt_.entries.size() / 2; }
  const SimulationParameters& parameters() const { return parameters_; }

 private:
  void prepareSkins(std::size_t meshBegin, std::size_t meshEnd);
  void computeForces(std::size_t vertexBegin, std::size_t vertexEnd);
  void integrate(std::size_t vertexBegin, std::size_t vertexEnd);
  void updateMeshes(std::size_t meshBegin, std::size_t meshEnd);
  void applyCornerForces();
  void applyDockForces();

  // The closest skin point of each mesh (other than `excludeMesh`) within the cut-off of p.
  static constexpr int kMaxNeighbours = 24;
  struct SkinHit {
    int mesh, segment;
    double t, d2;
    Vec2 point, normal;  // outward normal at the closest feature
    int image = 0;       // which periodic clone of `mesh` (0: the mesh itself); see periodicOffset
    bool contains(Vec2 p) const { return dot(p - point, normal) < 0.0; }
    std::pair<int, int> key() const { return {mesh, image}; }  // each clone is a neighbour of its own
    bool nearerThan(const SkinHit& other) const { return d2 < other.d2; }
  };
  using SkinHits = NearestHitList<SkinHit, kMaxNeighbours>;
  // What the same grid traversal finds of a boundary vertex v's own skin, away from v along the
  // ring (other than the kSelfNeighbourhood segments next to it), in the 3 × 3 cells around it.
  struct OwnSkin {
    int vertex = -1;        // v; -1: not looked for (an interior vertex, or a periodic clone)
    double reach2 = 0.0;    // self-repulsion's reach, squared (see ownSkinQuery)
    double nearest2 = std::numeric_limits<double>::infinity();  // nearest far own segment: a drawn notch is not a pocket
    // Self-repulsion: the nearest far own point within the reach that v approaches from
    // outside (a limb bending onto its own body); valid when `approached`.
    Vec2 closest;
    bool approached = false;
  };
  // The hits of p (other meshes than excludeMesh) and, when own.vertex ≥ 0, its own skin.
  void nearestSkinPoints(Vec2 p, int excludeMesh, SkinHits& hits, OwnSkin* own = nullptr) const;
  // The OwnSkin query of boundary vertex v: the reach is the cut-off, or half the distance
  // between v and the far skin at rest when that is nearer.
  OwnSkin ownSkinQuery(int v, const MeshInstance& mesh) const;
  // Outward push on a skin vertex bordering a pocket (SimulationParameters::pocketPressure).
  Vec2 pocketPressure(int v, const MeshInstance& mesh, const SkinHits& near, const OwnSkin& own) const;
  // Periodic domain (tile mode): the hits of p - offset, reported at the clone `image`.
  void nearestSkinPointsOf(Vec2 p, Vec2 offset, int image, int excludeMesh, SkinHits& hits, OwnSkin* own) const;
  bool periodic() const { return domain_.period.x > 0.0 && domain_.period.y > 0.0; }
  Vec2 periodicOffset(int image) const;
  // A mesh whose centre left the tile moves whole by ±W / ±H (never single vertices).
  void wrapMeshes(std::size_t meshBegin, std::size_t meshEnd);

  const RegionIndex& container_;
  double containerArea_;
  SimulationParameters parameters_;
  PackingDomain domain_;
  ExplicitEuler integrator_;
  GrowthRule growthRule_;  // no cap: a mesh grows while it has room
  ThreadPool& pool_;
  bool finalized_ = false;
  enum class Mode { Grow, Press, Settle };
  Mode mode_ = Mode::Grow;
  double settleDepth2_ = 0.0;
  int iteration_ = 0;
  double fill_ = 0.0;
  double restFill_ = 0.0;

  std::vector<MeshInstance> meshes_;
  // Per vertex (hot).
  std::vector<Vec2> position_, velocity_, force_;
  std::vector<int> meshOf_;
  std::vector<std::uint8_t> insideOther_;
  std::vector<double> insideDepth2_;  // squared depth inside the other mesh (0: not inside)
  std::vector<double> outsideDepth_;  // distance outside the container (0: inside); past outsideTolerance it blocks growth
  std::vector<double> triangleRestArea_;  // signed, at growth 1
  std::vector<double> restSelfClearance_;  // per vertex, at growth 1 (see ownSkinQuery)
  std::vector<Vec2> restDirection_;  // rest offset from the mesh centre, for torsion
  std::vector<Vec2> vertexNormal_;   // outward pseudo-normal (boundary vertices)
  // Springs by vertex; each spring appears once at each end.
  struct SpringEnd { int other; double rest, stiffness; };
  VertexAdjacency<SpringEnd> springsAt_;
  // Incident triangles by vertex (indices into triangles_), and the triangles themselves.
  VertexAdjacency<int> trianglesAt_;
  std::vector<std::array<int, 3>> triangles_;
  // Skin segments: ends and owning mesh; outward normals updated every step.
  std::vector<int> segmentEnds_, segmentMesh_;
  // Each skin segment's ends and mesh, copied side by side once a step: the neighbour search
  // reads them for every segment in the 3 × 3 cells, and one load is cheaper than three.
  struct SegmentCopy {
    Vec2 a, b;
    int mesh = -1;
  };
  std::vector<SegmentCopy> segmentCopy_;
  std::vector<Vec2> segmentNormal_;
  std::vector<Vec2> meshCentre_;
  std::vector<std::uint8_t> meshOnCorner_;  // a container corner is inside this mesh
  std::vector<Corner> corners_;
  std::vector<const RegionIndex*> parts_;  // empty: every mesh in `container_`
  OrientationRamp orientationRamp_;
  std::vector<Vec2> meshTorsionTurn_;      // (cos, sin) from the added angle to the field's
  // Unfolding (restoreAround): groups of vertices held to their best-fit rest shape.
  struct RestoreCluster {
    int begin, end;     // its vertices in clusterVertices_
    Vec2 restMean;      // mean rest offset of its vertices
    Vec2 centre, turn;  // this step: mean position and (cos, sin) of the best-fit rotation
    double strength;
  };
  std::vector<RestoreCluster> clusters_;
  std::vector<int> standingStill_;  // meshes holdRestShapes froze, to thaw on releaseHolds
  std::vector<int> clusterVertices_;
  std::vector<int> vertexCluster_;  // -1: none
  void fitClusters();
  std::vector<Dock> docks_;
  double dockStrength_ = 0.0;
  SegmentGrid grid_;
  Box vertexExtent_;  // periodic domain: bounds of all vertices, to skip far clones

  // Build-time only.
  struct PendingSprings { std::vector<std::pair<int, int>> ends; std::vector<double> rest, stiffness; } pending_;
};

}  // namespace pak
