#include "repulsion/packing_simulation.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "pak/geom/best_fit_rotation.hpp"
#include "sim/fold_relaxation.hpp"
#include "sim/forces.hpp"

namespace pak {

namespace {

constexpr std::size_t kVertexGrain = 256;
// A triangle pushes back once squeezed below this share of its rest area (anti-inversion).
constexpr double kInversionShare = 0.25;
// Self-repulsion: skin segments fewer than this many away along the ring are v's own side.
constexpr int kSelfNeighbourhood = 6;
// …and repel only once nearer than this share of their distance at rest.
constexpr double kSelfClearanceShare = 0.5;

inline Vec2 closestOnSegment(Vec2 p, Vec2 a, Vec2 b, double& t) {
  Vec2 ab = b - a;
  double len2 = lengthSquared(ab);
  t = len2 > 0.0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return a + ab * t;
}

}  // namespace

PackingSimulation::PackingSimulation(const RegionIndex& container, double containerArea,
                                     const SimulationParameters& parameters, ThreadPool& pool,
                                     const PackingDomain& domain)
    : container_(container),
      containerArea_(containerArea),
      parameters_(parameters),
      domain_(domain),
      integrator_(parameters.timeStep, parameters.velocityCap, parameters.damping),
      growthRule_(parameters.growthRate, parameters.timeStep),
      pool_(pool) {}

int PackingSimulation::addMesh(const ElementMesh& mesh, int type, Vec2 position, double angle, double growth,
                               bool frozen) {
  assert(!finalized_ && "meshes are added before finalize");
  MeshInstance instance;
  instance.type = type;
  instance.vertexBegin = static_cast<int>(position_.size());
  instance.vertexCount = static_cast<int>(mesh.mesh.vertices.size());
  instance.boundaryCount = mesh.boundaryCount;
  instance.segmentBegin = static_cast<int>(segmentMesh_.size());
  instance.triangleBegin = static_cast<int>(triangles_.size());
  instance.triangleCount = static_cast<int>(mesh.mesh.triangles.size());
  instance.growth = growth;
  instance.frozen = frozen;
  instance.restArea = mesh.skinArea;
  instance.restAngle = angle;
  int id = static_cast<int>(meshes_.size());
  for (Vec2 v : mesh.mesh.vertices) {
    Vec2 offset = rotated(v - mesh.restCentroid, angle);
    position_.push_back(position + offset * growth);
    restDirection_.push_back(offset);
    meshOf_.push_back(id);
  }
  int base = instance.vertexBegin;
  // Self-repulsion's rest clearance: each skin vertex's distance, at growth 1, to the nearest
  // skin segment away from it along the ring (brute force, once per mesh).
  const std::vector<Vec2>& restSkin = mesh.mesh.vertices;
  for (int k = 0; k < mesh.boundaryCount; ++k) {
    double clearance2 = std::numeric_limits<double>::infinity();
    for (int j = 0; j < mesh.boundaryCount; ++j) {
      const int along = std::min(std::abs(j - k), mesh.boundaryCount - std::abs(j - k));
      if (along <= kSelfNeighbourhood) continue;
      double t;
      const Vec2 q = closestOnSegment(restSkin[k], restSkin[j], restSkin[(j + 1) % mesh.boundaryCount], t);
      clearance2 = std::min(clearance2, lengthSquared(restSkin[k] - q));
    }
    restSelfClearance_.push_back(std::sqrt(clearance2));
  }
  for (int k = mesh.boundaryCount; k < instance.vertexCount; ++k) restSelfClearance_.push_back(0.0);
  for (int k = 0; k < mesh.boundaryCount; ++k) {
    segmentEnds_.push_back(base + k);
    segmentEnds_.push_back(base + (k + 1) % mesh.boundaryCount);
    segmentMesh_.push_back(id);
  }
  for (const auto& tri : mesh.mesh.triangles) {
    triangles_.push_back({base + tri[0], base + tri[1], base + tri[2]});
    const std::vector<Vec2>& rest = mesh.mesh.vertices;
    triangleRestArea_.push_back(0.5 * cross(rest[tri[1]] - rest[tri[0]], rest[tri[2]] - rest[tri[0]]));
  }
  for (const Spring& s : mesh.springs) {
    pending_.ends.emplace_back(base + s.a, base + s.b);
    pending_.rest.push_back(s.restLength);
    pending_.stiffness.push_back(s.kind == SpringKind::NegativeSpace ? parameters_.negativeSpaceStrength
                                                                      : parameters_.edgeStrength);
  }
  meshes_.push_back(instance);
  return id;
}

void PackingSimulation::finalize(const Box& area) {
  assert(!finalized_ && "finalize is called once");
  finalized_ = true;
  std::size_t n = position_.size();
  velocity_.assign(n, {});
  force_.assign(n, {});
  insideOther_.assign(n, 0);
  insideDepth2_.assign(n, 0.0);
  outsideDepth_.assign(n, 0.0);
  vertexNormal_.assign(n, {});
  segmentNormal_.assign(segmentMesh_.size(), {});
  segmentCopy_.assign(segmentMesh_.size(), {});
  meshCentre_.assign(meshes_.size(), {});
  meshOnCorner_.assign(meshes_.size(), 0);
  meshTorsionTurn_.assign(meshes_.size(), Vec2{1.0, 0.0});
  vertexCluster_.assign(n, -1);

  // Springs by vertex, in spring order at each end (deterministic sums).
  springsAt_ = buildVertexAdjacency<SpringEnd>(n, [&](auto&& emit) {
    for (std::size_t s = 0; s < pending_.ends.size(); ++s) {
      const auto [a, b] = pending_.ends[s];
      emit(a, SpringEnd{b, pending_.rest[s], pending_.stiffness[s]});
      emit(b, SpringEnd{a, pending_.rest[s], pending_.stiffness[s]});
    }
  });
  pending_ = {};
  trianglesAt_ = buildVertexAdjacency<int>(n, [&](auto&& emit) {
    for (std::size_t t = 0; t < triangles_.size(); ++t)
      for (int v : triangles_[t]) emit(v, static_cast<int>(t));
  });

  grid_.configure(area, parameters_.cellSize, segmentMesh_.size());
  if (periodic()) vertexExtent_ = bounds(position_);
  // Areas and normals for the first `fill()` and the first step.
  grid_.rebuild(position_.data(), segmentEnds_.data(), segmentMesh_.size());
  prepareSkins(0, meshes_.size());
  updateMeshes(0, meshes_.size());
  fill_ = restFill_ = 0.0;
  for (const auto& m : meshes_) {
    fill_ += m.area;
    restFill_ += m.restArea * m.growth * m.growth;
  }
  fill_ = (fill_ + domain_.occupiedArea) / containerArea_;
  restFill_ = (restFill_ + domain_.occupiedArea) / containerArea_;
}

void PackingSimulation::prepareSkins(std::size_t meshBegin, std::size_t meshEnd) {
  for (std::size_t m = meshBegin; m < meshEnd; ++m) {
    const MeshInstance& mesh = meshes_[m];
    Vec2 centre;
    for (int v = mesh.vertexBegin; v < mesh.vertexBegin + mesh.vertexCount; ++v) centre += position_[v];
    meshCentre_[m] = centre / static_cast<double>(mesh.vertexCount);
    if (orientationRamp_.active) {
      const double turn = orientationRamp_.angleAt(meshCentre_[m]) - mesh.restAngle;
      meshTorsionTurn_[m] = {std::cos(turn), std::sin(turn)};
    }
    int nb = mesh.boundaryCount;
    for (int k = 0; k < nb; ++k) {
      Vec2 a = position_[mesh.vertexBegin + k], b = position_[mesh.vertexBegin + (k + 1) % nb];
      segmentNormal_[mesh.segmentBegin + k] = normalized(Vec2{b.y - a.y, a.x - b.x});
      segmentCopy_[mesh.segmentBegin + k] = {a, b, static_cast<int>(m)};
    }
    for (int k = 0; k < nb; ++k)
      vertexNormal_[mesh.vertexBegin + k] =
          normalized(segmentNormal_[mesh.segmentBegin + (k + nb - 1) % nb] + segmentNormal_[mesh.segmentBegin + k]);
  }
}

void PackingSimulation::nearestSkinPoints(Vec2 p, int excludeMesh, SkinHits& hits, OwnSkin* own) const {
  nearestSkinPointsOf(p, Vec2{}, 0, excludeMesh, hits, own);
  if (!periodic()) return;
  // Thesis 4.8: the clones in the 8 neighbouring cells act like their originals. A clone at
  // offset o near p is the original near p - o; skip offsets where p - o is out of reach.
  const double reach = parameters_.cellSize;
  for (int image = 1; image < 9; ++image) {
    Vec2 offset = periodicOffset(image), q = p - offset;
    if (q.x < vertexExtent_.min.x - reach || q.x > vertexExtent_.max.x + reach || q.y < vertexExtent_.min.y - reach ||
        q.y > vertexExtent_.max.y + reach)
      continue;
    nearestSkinPointsOf(q, offset, image, -1, hits, nullptr);  // a mesh's own clones repel it too
  }
}

Vec2 PackingSimulation::periodicOffset(int image) const {
  // Image 0 is the mesh itself; 1…8 the neighbouring cells in a fixed order (determinism).
  static constexpr int kCell[9][2] = {{0, 0}, {-1, -1}, {0, -1}, {1, -1}, {-1, 0}, {1, 0}, {-1, 1}, {0, 1}, {1, 1}};
  return {kCell[image][0] * domain_.period.x, kCell[image][1] * domain_.period.y};
}

void PackingSimulation::nearestSkinPointsOf(Vec2 p, Vec2 offset, int image, int excludeMesh, SkinHits& hits,
                                            OwnSkin* own) const {
  const double cutoff2 = parameters_.cellSize * parameters_.cellSize;
  // v's place on its ring, for telling its own side from the far skin.
  const int ownBegin = own ? meshes_[excludeMesh].segmentBegin : 0, nb = own ? meshes_[excludeMesh].boundaryCount : 0;
  const int k = own ? own->vertex - meshes_[excludeMesh].vertexBegin : 0;
  grid_.forEachNear(p, 1, [&](int s) {
    const SegmentCopy& segment = segmentCopy_[s];
    const int mesh = segment.mesh;
    if (mesh == excludeMesh) {
      if (!own) return;
      const int j = s - ownBegin;
      if (std::min(std::abs(j - k), nb - std::abs(j - k)) <= kSelfNeighbourhood) return;  // v's own side
      double t;
      const Vec2 q = closestOnSegment(p, segment.a, segment.b, t);
      const double d2 = lengthSquared(p - q);
      own->nearest2 = std::min(own->nearest2, d2);
      if (d2 >= own->reach2) return;
      const int a = segmentEnds_[2 * s], b = segmentEnds_[2 * s + 1];
      const Vec2 normal = t <= 0.0 ? vertexNormal_[a] : (t >= 1.0 ? vertexNormal_[b] : segmentNormal_[s]);
      if (dot(p - q, normal) <= 0.0) return;  // across its own body, not a limb coming from outside
      own->reach2 = d2;
      own->closest = q;
      own->approached = true;
      return;
    }
    double t;
    Vec2 q = closestOnSegment(p, segment.a, segment.b, t);
    double d2 = lengthSquared(p - q);
    if (d2 > cutoff2) return;
    const int a = segmentEnds_[2 * s], b = segmentEnds_[2 * s + 1];
    // The side test needs the normal at the closest feature: a vertex's pseudo-normal at the
    // segment's ends, else the segment's own.
    Vec2 normal = t <= 0.0 ? vertexNormal_[a] : (t >= 1.0 ? vertexNormal_[b] : segmentNormal_[s]);
    hits.offer({mesh, s, t, d2, image == 0 ? q : q + offset, normal, image});
  });
}

PackingSimulation::OwnSkin PackingSimulation::ownSkinQuery(int v, const MeshInstance& mesh) const {
  // Only nearer than half its clearance at rest: a drawn notch or a neighbouring ear is not a fold.
  const double reach = std::min(parameters_.cellSize, kSelfClearanceShare * restSelfClearance_[v] * mesh.growth);
  OwnSkin own;
  own.vertex = v;
  own.reach2 = reach * reach;
  return own;
}

Vec2 PackingSimulation::pocketPressure(int v, const MeshInstance& mesh, const SkinHits& near, const OwnSkin& own) const {
  const SimulationParameters& P = parameters_;
  const double clearance = P.pocketClearance, reach = P.cellSize;
  double free2 = reach * reach;
  for (const SkinHit& hit : near) free2 = std::min(free2, hit.d2);
  if (free2 <= clearance * clearance) return {};  // in a channel, the common case
  const Vec2 x = position_[v];
  const int k = v - mesh.vertexBegin, nb = mesh.boundaryCount;
  // Not at a reflex vertex: pushing the two sides of a notch outward folds them over it.
  const Vec2 before = position_[mesh.vertexBegin + (k + nb - 1) % nb], after = position_[mesh.vertexBegin + (k + 1) % nb];
  if (forces::reflexSkinVertex(before, x, after)) return {};
  // A drawn notch (between two ears, say) is not a pocket: the element's own skin away from v
  // along the ring counts as a neighbour.
  free2 = std::min(free2, own.nearest2);
  double free = std::sqrt(free2);
  if (free <= clearance) return {};
  if (!periodic()) {
    const RegionIndex& region = parts_.empty() ? container_ : *parts_[mesh.container];
    if (region.insideDistanceBound(x) < free) {  // the wall may be nearer than the others
      const RegionIndex::Query q = region.query(x, true);
      if (!q.inside) return {};
      free = std::min(free, q.distance);
      if (free <= clearance) return {};
    }
  }
  return forces::pocketPressure(vertexNormal_[v], free, clearance, reach, P.pocketPressure);
}

void PackingSimulation::restoreAround(int m, Vec2 point, double radius, double strength) {
  const MeshInstance& mesh = meshes_[m];
  RestoreCluster cluster{static_cast<int>(clusterVertices_.size()), 0, {}, {}, {1.0, 0.0}, strength};
  for (int v = mesh.vertexBegin; v < mesh.vertexBegin + mesh.vertexCount; ++v) {
    if (lengthSquared(position_[v] - point) > radius * radius) continue;
    if (vertexCluster_[v] >= 0) {
      double& held = clusters_[vertexCluster_[v]].strength;
      held = std::max(held, strength);
      continue;
    }
    vertexCluster_[v] = static_cast<int>(clusters_.size());
    clusterVertices_.push_back(v);
    cluster.restMean += restDirection_[v];
  }
  cluster.end = static_cast<int>(clusterVertices_.size());
  if (cluster.end == cluster.begin) return;
  cluster.restMean = cluster.restMean / static_cast<double>(cluster.end - cluster.begin);
  clusters_.push_back(cluster);
}

void PackingSimulation::fitClusters() {
  for (RestoreCluster& c : clusters_) {
    Vec2 centre;
    for (int k = c.begin; k < c.end; ++k) centre += position_[clusterVertices_[k]];
    c.centre = centre / static_cast<double>(c.end - c.begin);
    BestFitRotation fit;  // of the rest offsets onto the current ones
    for (int k = c.begin; k < c.end; ++k) {
      const int v = clusterVertices_[k];
      fit.add(restDirection_[v] - c.restMean, position_[v] - c.centre);
    }
    c.turn = fit.turn();
  }
}

void PackingSimulation::grow() {
  mode_ = Mode::Grow;
  releaseHolds();
}

void PackingSimulation::holdRestShapes(const std::vector<char>& held, double strength) {
  assert(held.size() == meshes_.size());
  releaseHolds();
  for (std::size_t m = 0; m < meshes_.size(); ++m)
    if (held[m]) {
      restoreAround(static_cast<int>(m), Vec2{}, std::numeric_limits<double>::infinity(), strength);
    } else if (!meshes_[m].frozen) {
      meshes_[m].frozen = true;
      standingStill_.push_back(static_cast<int>(m));
    }
}

void PackingSimulation::releaseHolds() {
  for (int v : clusterVertices_) vertexCluster_[v] = -1;
  clusterVertices_.clear();
  clusters_.clear();
  for (int m : standingStill_) meshes_[m].frozen = false;
  standingStill_.clear();
}

void PackingSimulation::wrapMeshes(std::size_t meshBegin, std::size_t meshEnd) {
  const Vec2 period = domain_.period;
  for (std::size_t m = meshBegin; m < meshEnd; ++m) {
    const MeshInstance& mesh = meshes_[m];
    Vec2 centre;
    for (int v = mesh.vertexBegin; v < mesh.vertexBegin + mesh.vertexCount; ++v) centre += position_[v];
    centre = centre / static_cast<double>(mesh.vertexCount);
    Vec2 shift{-std::floor(centre.x / period.x) * period.x, -std::floor(centre.y / period.y) * period.y};
    if (shift.x == 0.0 && shift.y == 0.0) continue;
    for (int v = mesh.vertexBegin; v < mesh.vertexBegin + mesh.vertexCount; ++v) position_[v] += shift;
  }
}

void PackingSimulation::computeForces(std::size_t vertexBegin, std::size_t vertexEnd) {
  const SimulationParameters& P = parameters_;
  for (std::size_t v = vertexBegin; v < vertexEnd; ++v) {
    const int m = meshOf_[v];
    const MeshInstance& mesh = meshes_[m];
    if (mesh.frozen) { force_[v] = {}; insideOther_[v] = 0; outsideDepth_[v] = 0.0; continue; }
    const Vec2 x = position_[v];
    Vec2 f;

    // Closest skin point of each neighbouring mesh within the cut-off.
    SkinHits near;
    const bool onSkin = static_cast<int>(v) - mesh.vertexBegin < mesh.boundaryCount;
    OwnSkin own;
    if (onSkin && (P.selfRepulsion > 0.0 || P.pocketPressure > 0.0)) own = ownSkinQuery(static_cast<int>(v), mesh);
    nearestSkinPoints(x, m, near, own.vertex >= 0 ? &own : nullptr);
    bool inside = false;
    double depth2 = 0.0;
    for (int k = 0; k < near.size() && !inside; ++k)
      if (near[k].contains(x)) {
        inside = true;
        depth2 = near[k].d2;  // the distance to the skin of the mesh it is in
      }
    if (inside) {
      // Eq. 4.4: no repulsion; every incident triangle pulls the vertex toward its centroid.
      for (int t : trianglesAt_.of(v)) {
        const auto& tri = triangles_[t];
        Vec2 centroid = (position_[tri[0]] + position_[tri[1]] + position_[tri[2]]) / 3.0;
        f += forces::overlap(x, centroid, P.overlapStrength);
      }
    } else {
      for (const SkinHit& hit : near) f += forces::repulsion(x, hit.point, P.repulsionStrength, P.soft);
      if (P.selfRepulsion > 0.0 && own.approached)
        f += forces::repulsion(x, own.closest, P.repulsionStrength * P.selfRepulsion, P.soft);
      // While growing, on the meshes that stopped; after, on all but one pressed deep into
      // another: it would keep it pressed in.
      const bool pressed = mode_ == Mode::Grow ? !canGrow(mesh) : !mesh.deep;
      if (P.pocketPressure > 0.0 && pressed && onSkin)
        f += pocketPressure(static_cast<int>(v), mesh, near, own);
    }
    insideOther_[v] = inside ? 1 : 0;
    insideDepth2_[v] = depth2;

    // Anti-inversion: a triangle squeezed below a share of its rest area pushes this vertex
    // back away from the opposite edge (along the area's gradient) before it folds over.
    if (P.inversionStrength > 0.0) {
      const double g2 = mesh.growth * mesh.growth;
      for (int t : trianglesAt_.of(v)) {
        const auto& tri = triangles_[t];
        const int k = tri[0] == static_cast<int>(v) ? 0 : (tri[1] == static_cast<int>(v) ? 1 : 2);
        const Vec2 a = position_[tri[(k + 1) % 3]], b = position_[tri[(k + 2) % 3]];
        const double rest = triangleRestArea_[t] * g2, now = 0.5 * cross(a - x, b - x);
        if (rest > 0.0 && now < kInversionShare * rest)
          f += Vec2{a.y - b.y, b.x - a.x} * (P.inversionStrength * (kInversionShare * rest - now) / rest);
      }
    }

    // Unfolding: toward the best-fit rest shape, which does not cross itself.
    if (vertexCluster_[v] >= 0) {
      const RestoreCluster& c = clusters_[vertexCluster_[v]];
      const Vec2 target = c.centre + rotated((restDirection_[v] - c.restMean) * mesh.growth, c.turn);
      f += (target - x) * c.strength;
    }

    // Eq. 4.3: springs, rest lengths scaled by the mesh's growth.
    for (const SpringEnd& spring : springsAt_.of(v))
      f += forces::edge(x, position_[spring.other], spring.rest * mesh.growth, spring.stiffness);

    // Eq. 4.5: back into the container (its own one, when there are several). A periodic tile
    // has no walls (thesis 4.8).
    if (periodic()) {
      outsideDepth_[v] = 0.0;
    } else {
      const RegionIndex& region = parts_.empty() ? container_ : *parts_[mesh.container];
      RegionIndex::Query q = region.query(x, false);
      if (!q.inside) {
        if (!q.computed) q = region.query(x, true);
        f += forces::boundary(x, q.closest, P.boundaryStrength);
      }
      // Outside by more than the tolerance: no room to grow (see updateMeshes).
      outsideDepth_[v] = q.inside ? 0.0 : q.distance;
    }

    // Eq. 4.6: optional preferred orientation.
    if (P.torsionStrength > 0.0) {
      Vec2 rest = restDirection_[v];
      if (orientationRamp_.active) rest = rotated(rest, meshTorsionTurn_[m]);  // from the added angle to the field's here
      f += forces::torsion(x, meshCentre_[m], rest, P.torsionStrength);
    }

    force_[v] = f;
  }
}

void PackingSimulation::contractMesh(int m, double factor) {
  const MeshInstance& mesh = meshes_[m];
  Vec2 centre;
  for (int v = mesh.vertexBegin; v < mesh.vertexBegin + mesh.vertexCount; ++v) centre += position_[v];
  centre = centre / static_cast<double>(mesh.vertexCount);
  for (int v = mesh.vertexBegin; v < mesh.vertexBegin + mesh.vertexCount; ++v) {
    position_[v] = centre + (position_[v] - centre) * factor;
    velocity_[v] = Vec2{};
  }
}

void PackingSimulation::restoreRestShape(int m, double keep, Vec2 around, double radius) {
  const MeshInstance& mesh = meshes_[m];
  Vec2* velocity = velocity_.data() + mesh.vertexBegin;
  blendTowardRest(position_.data() + mesh.vertexBegin, restDirection_.data() + mesh.vertexBegin, mesh.vertexCount,
                  mesh.growth, keep, around, radius, [&](int v) { velocity[v] = Vec2{}; });
}

int PackingSimulation::projectInside() {
  assert(finalized_);
  if (periodic()) return 0;
  constexpr double kInsideMargin = 1e-3;  // canonical units
  int moved = 0;
  for (const MeshInstance& mesh : meshes_) {
    if (mesh.frozen) continue;
    const RegionIndex& region = parts_.empty() ? container_ : *parts_[mesh.container];
    for (int v = mesh.vertexBegin; v < mesh.vertexBegin + mesh.vertexCount; ++v) {
      const RegionIndex::Query q = region.query(position_[v], true);
      if (q.inside) continue;
      position_[v] = q.closest + normalized(q.closest - position_[v]) * kInsideMargin;
      velocity_[v] = Vec2{};
      ++moved;
    }
  }
  return moved;
}

std::vector<PackingSimulation::Corner> PackingSimulation::reflexCorners(const Region& input) {
  Region region = input;
  normalizeOrientation(region);  // interior on the left of every ring
  std::vector<Corner> corners;
  auto scan = [&](const Ring& ring) {
    std::size_t n = ring.size();
    for (std::size_t k = 0; k < n; ++k) {
      Vec2 prev = ring[(k + n - 1) % n], here = ring[k], next = ring[(k + 1) % n];
      Vec2 in = here - prev, out = next - here;
      // A right turn with the interior on the left: the corner points into the region.
      if (cross(in, out) >= -1e-12 * length(in) * length(out)) continue;
      Vec2 outwardIn = normalized(Vec2{in.y, -in.x}), outwardOut = normalized(Vec2{out.y, -out.x});
      corners.push_back({here, normalized(-(outwardIn + outwardOut))});
    }
  };
  for (const Polygon& p : region) {
    scan(p.outer);
    for (const Ring& h : p.holes) scan(h);
  }
  return corners;
}

void PackingSimulation::applyCornerForces() {
  std::fill(meshOnCorner_.begin(), meshOnCorner_.end(), 0);
  for (const Corner& corner : corners_) {
    const Vec2 c = corner.position;
    SkinHits hits;
    nearestSkinPoints(c, -1, hits);
    for (const SkinHit& h : hits) {
      if (meshes_[h.mesh].frozen || !h.contains(c)) continue;
      if (corner.container >= 0 && meshes_[h.mesh].container != corner.container) continue;
      int a = segmentEnds_[2 * h.segment], b = segmentEnds_[2 * h.segment + 1];
      // Push the segment past the corner, shared between its ends by proximity.
      Vec2 push = corner.inward * (parameters_.boundaryStrength * std::sqrt(h.d2));
      force_[a] += push * (1.0 - h.t);
      force_[b] += push * h.t;
      meshOnCorner_[h.mesh] = 1;
    }
  }
}

void PackingSimulation::applyDockForces() {
  for (const Dock& dock : docks_)
    if (!meshes_[meshOf_[dock.vertex]].frozen) force_[dock.vertex] += (dock.anchor - position_[dock.vertex]) * dockStrength_;
}

void PackingSimulation::integrate(std::size_t vertexBegin, std::size_t vertexEnd) {
  for (std::size_t v = vertexBegin; v < vertexEnd; ++v)
    if (!meshes_[meshOf_[v]].frozen) integrator_.advance(position_[v], velocity_[v], force_[v]);
}

void PackingSimulation::updateMeshes(std::size_t meshBegin, std::size_t meshEnd) {
  for (std::size_t m = meshBegin; m < meshEnd; ++m) {
    MeshInstance& mesh = meshes_[m];
    bool overlapping = false, deep = false, outside = false;
    for (int v = mesh.vertexBegin; v < mesh.vertexBegin + mesh.vertexCount; ++v) {
      overlapping |= insideOther_[v] != 0;
      deep |= insideDepth2_[v] > settleDepth2_ || outsideDepth_[v] * outsideDepth_[v] > settleDepth2_;
      outside |= outsideDepth_[v] > parameters_.outsideTolerance;
    }
    mesh.overlapping = overlapping;
    mesh.deep = deep || meshOnCorner_[m] != 0;  // a reflex corner inside it may reach its art
    mesh.outside = outside || meshOnCorner_[m] != 0;
    double twiceArea = 0.0;
    int nb = mesh.boundaryCount;
    for (int k = 0; k < nb; ++k) twiceArea += cross(position_[mesh.vertexBegin + k], position_[mesh.vertexBegin + (k + 1) % nb]);
    mesh.area = 0.5 * twiceArea;
  }
}

void PackingSimulation::step() {
  assert(finalized_ && "step only after finalize");
  if (periodic()) {
    pool_.parallelFor(meshes_.size(), 4, [this](std::size_t b, std::size_t e) { wrapMeshes(b, e); });
    vertexExtent_ = bounds(position_);
  }
  grid_.rebuild(position_.data(), segmentEnds_.data(), segmentMesh_.size());
  pool_.parallelFor(meshes_.size(), 4, [this](std::size_t b, std::size_t e) { prepareSkins(b, e); });
  fitClusters();
  pool_.parallelFor(position_.size(), kVertexGrain, [this](std::size_t b, std::size_t e) { computeForces(b, e); });
  applyCornerForces();
  if (!docks_.empty()) applyDockForces();
  pool_.parallelFor(position_.size(), kVertexGrain, [this](std::size_t b, std::size_t e) { integrate(b, e); });
  // Flags come from this step's force pass; areas from the new positions.
  updateMeshes(0, meshes_.size());
  // Growth (4.5.1): only meshes with room, i.e. no vertex inside another mesh (thesis) and
  // none pushed out of the container beyond the tolerance (else a mesh squeezed against the
  // wall keeps growing until its art crosses it).
  double total = 0.0, rest = 0.0;
  for (MeshInstance& mesh : meshes_) {
    if (mode_ == Mode::Grow) mesh.growth = growthRule_.next(mesh.growth, canGrow(mesh));
    else if (mode_ == Mode::Settle && needsSettling(mesh)) mesh.growth = growthRule_.shrunk(mesh.growth);
    total += mesh.area;
    rest += mesh.restArea * mesh.growth * mesh.growth;
  }
  fill_ = (total + domain_.occupiedArea) / containerArea_;
  restFill_ = (rest + domain_.occupiedArea) / containerArea_;
  ++iteration_;
  assert(allFinite(position_.data(), position_.data() + position_.size()) && "a step left a non-finite position");
}

int PackingSimulation::unsettledCount() const {
  int n = 0;
  for (const MeshInstance& mesh : meshes_) n += needsSettling(mesh) ? 1 : 0;
  return n;
}

int PackingSimulation::growingCount() const {
  int n = 0;
  for (const MeshInstance& mesh : meshes_) n += canGrow(mesh) ? 1 : 0;
  return n;
}

}  // namespace pak
