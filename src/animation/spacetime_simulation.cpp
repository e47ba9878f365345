#include "animation/spacetime_simulation.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <utility>

#include "pak/geom/polygon.hpp"
#include "sim/forces.hpp"

namespace pak {

namespace {

Vec2 meanOf(const Vec2* points, int count) {
  Vec2 sum;
  for (int i = 0; i < count; ++i) sum += points[i];
  return sum / static_cast<double>(count);
}

constexpr double kNoTarget = std::numeric_limits<double>::quiet_NaN();
constexpr double kFar = std::numeric_limits<double>::infinity();
// How far (canonical units) a neighbour may come closer than the nearest one was when the
// neighbour lists were built, before they are built again (SpacetimeNeighbours): at the
// velocity cap, every 10 steps or so.
constexpr double kNeighbourMargin = 4.0;
}  // namespace

SpacetimeSimulation::SpacetimeSimulation(const RegionIndex& container, double containerArea, int slices,
                                         const SimulationParameters& parameters, const SpacetimeParameters& spacetime,
                                         ThreadPool& pool)
    : container_(container),
      containerArea_(containerArea),
      slices_(slices),
      parameters_(parameters),
      spacetime_(spacetime),
      integrator_(parameters.timeStep, parameters.velocityCap, parameters.damping),
      pool_(pool) {
  assert(slices >= 2);
}

int SpacetimeSimulation::addElement(const SpacetimeElementSetup& setup) {
  assert(!finalized_ && "elements are added before finalize");
  const ElementMesh& mesh = *setup.mesh;
  const int n = static_cast<int>(mesh.mesh.vertices.size());
  assert(static_cast<int>(setup.reference.size()) == n * slices_);
  assert(static_cast<int>(setup.referenceCentre.size()) == slices_);
  const int element = static_cast<int>(elements_.size());
  const int vertexBegin = static_cast<int>(position_.size());
  const int sliceBegin = static_cast<int>(growth_.size());
  // A step of growth moves the first slice's skin by the rate × Δt × its mean distance from
  // the centre; SpacetimeParameters::growthSpeedCap bounds that by velocity-cap steps.
  double growthRate = parameters_.growthRate;
  if (spacetime_.growthSpeedCap > 0.0 && mesh.boundaryCount > 0) {
    double radius = 0.0;
    for (int v = 0; v < mesh.boundaryCount; ++v) radius += length(setup.reference[v] - setup.referenceCentre[0]);
    radius /= mesh.boundaryCount;
    if (radius > 0.0) growthRate = std::min(growthRate, spacetime_.growthSpeedCap * parameters_.velocityCap / radius);
  }
  elements_.push_back({&mesh, vertexBegin, n, sliceBegin, setup.torsionStrength, !setup.targets.empty(),
                       setup.leavesContainer, GrowthRule(growthRate, parameters_.timeStep, spacetime_.maxGrowth)});

  const double dt = spacetime_.timeLength / (slices_ - 1);
  for (int s = 0; s < slices_; ++s) {
    const int slice = sliceBegin + s;
    const double t = s * dt;
    sliceElement_.push_back(element);
    sliceVertexBegin_.push_back(vertexBegin + s * n);
    growth_.push_back(setup.initialGrowth);
    sliceTime_.push_back(t);
    restTime_.push_back(t);
    referenceCentre_.push_back(setup.referenceCentre[s]);
    for (int v = 0; v < n; ++v) {
      const Vec2 r = setup.reference[s * n + v];
      const Vec2 c = setup.referenceCentre[s];
      const Vec2 p = c + (r - c) * setup.initialGrowth;
      reference_.push_back(r);
      position_.push_back({p.x, p.y, t});
      sliceOf_.push_back(slice);
      isBoundary_.push_back(v < mesh.boundaryCount ? 1 : 0);
    }
  }

  // In-slice springs, then time springs between consecutive slice boundaries (5.3.1): for
  // the boundary edge AB of slice s and CD of slice s + 1, the edges AC, AD and BC.
  for (int s = 0; s < slices_; ++s) {
    const int base = vertexBegin + s * n;
    for (const Spring& spring : mesh.springs) {
      double k = spring.kind == SpringKind::NegativeSpace ? parameters_.negativeSpaceStrength : parameters_.edgeStrength;
      pending_.push_back({base + spring.a, base + spring.b, k});
    }
  }
  const int nb = mesh.boundaryCount;
  for (int s = 0; s + 1 < slices_; ++s) {
    const int lower = vertexBegin + s * n, upper = lower + n;
    for (int k = 0; k < nb; ++k) {
      const int a = lower + k, b = lower + (k + 1) % nb, c = upper + k, d = upper + (k + 1) % nb;
      pending_.push_back({a, c, spacetime_.timeStrength});
      pending_.push_back({a, d, spacetime_.timeStrength});
      pending_.push_back({b, c, spacetime_.timeStrength});
      envelope_.push_back({a, b, c});  // outward normal (b − a) × (c − a) for a ring that
      envelope_.push_back({a, d, c});  // turns counter-clockwise seen from +t
      envelopeElement_.push_back(element);
      envelopeElement_.push_back(element);
    }
  }
  for (const SpacetimeElementSetup::Target& target : setup.targets)
    pendingTargets_.push_back({target.slice, vertexBegin + target.slice * n + target.vertex, target.position});
  return element;
}

void SpacetimeSimulation::addLoop(int from, int to, Vec2 turn, Vec2 shift, std::vector<int> partner) {
  assert(!finalized_ && "loops are added before finalize");
  assert(elements_[from].mesh == elements_[to].mesh && lengthSquared(turn) > 0.0);
  assert(partner.empty() || static_cast<int>(partner.size()) == elements_[from].verticesPerSlice);
  loops_.push_back({from, to, turn, shift, std::move(partner)});
}

Vec2 SpacetimeSimulation::loopTurn(const Vec2* first, const Vec2* last, int count, const int* partner) {
  const Vec2 cf = meanOf(first, count), cl = meanOf(last, count);
  double norm = 0.0, c = 0.0, s = 0.0;
  for (int i = 0; i < count; ++i) {
    const Vec2 p = first[partner ? partner[i] : i] - cf, q = last[i] - cl;
    norm += lengthSquared(p), c += dot(p, q), s += cross(p, q);
  }
  return norm > 0.0 ? Vec2{c / norm, s / norm} : Vec2{1.0, 0.0};
}

std::vector<int> SpacetimeSimulation::loopPartners(const Vec2* first, const Vec2* last, int count) {
  const Vec2 cf = meanOf(first, count), cl = meanOf(last, count);
  const double scale = length(loopTurn(first, last, count));
  double extent = 0.0;
  for (int i = 0; i < count; ++i) extent = std::max(extent, length(first[i] - cf));
  const double tolerance = 1e-6 * extent * scale;
  std::vector<int> partner(count, -1), taken(count, 0);
  bool moved = false;
  for (int i = 0; i < count; ++i) {
    const Vec2 q = last[i] - cl;
    int best = -1;
    double best2 = tolerance * tolerance;
    for (int j = 0; j < count; ++j) {
      const double d2 = lengthSquared((first[j] - cf) * scale - q);
      if (d2 <= best2) best = j, best2 = d2;
    }
    if (best < 0 || taken[best]) return {};
    partner[i] = best, taken[best] = 1, moved = moved || best != i;
  }
  return moved ? partner : std::vector<int>{};
}

int SpacetimeSimulation::projectInside() {
  assert(finalized_);
  constexpr double kInsideMargin = 1e-3;  // canonical units
  int moved = 0;
  for (const ElementRecord& e : elements_) {
    if (e.leavesContainer) continue;
    const auto begin = position_.begin() + e.vertexBegin;
    for (auto x = begin; x != begin + static_cast<std::ptrdiff_t>(e.verticesPerSlice) * slices_; ++x) {
      RegionIndex::Query q = container_.query(spatial(*x), false);
      if (q.inside) continue;
      if (!q.computed) q = container_.query(spatial(*x), true);
      const Vec2 p = q.closest + normalized(q.closest - spatial(*x)) * kInsideMargin;
      x->x = p.x, x->y = p.y;
      ++moved;
    }
  }
  return moved;
}

void SpacetimeSimulation::finalize(const Box& area) {
  assert(!finalized_ && "finalize is called once");
  finalized_ = true;
  const std::size_t nv = position_.size();
  velocity_.assign(nv, {});
  force_.assign(nv, {});
  referencePoint_.assign(nv, {});
  insideOther_.assign(nv, 0);
  outsideDepth_.assign(nv, 0.0);
  nearestGap_.assign(nv, kFar);
  targetPull_.assign(nv, {kNoTarget, kNoTarget});
  for (const auto& target : pendingTargets_) targetPull_[target.vertex] = target.position;

  // Springs by vertex, in spring order at each end (deterministic sums).
  springStiffness_.clear();
  auto kindOf = [&](double k) {
    const auto known = std::find(springStiffness_.begin(), springStiffness_.end(), k);
    if (known != springStiffness_.end()) return static_cast<int>(known - springStiffness_.begin());
    springStiffness_.push_back(k);
    return static_cast<int>(springStiffness_.size()) - 1;
  };
  springsAt_ = buildVertexAdjacency<SpringEnd>(nv, [&](auto&& emit) {
    for (const PendingSpring& s : pending_) {
      const int kind = kindOf(s.stiffness);
      emit(s.a, SpringEnd{s.b, kind});
      emit(s.b, SpringEnd{s.a, kind});
    }
  });
  springRest_.assign(springsAt_.entries.size(), 0.0);
  pending_.clear();
  pending_.shrink_to_fit();

  // In-slice triangles incident to each vertex.
  trianglesAt_ = buildVertexAdjacency<std::array<int, 3>>(nv, [&](auto&& emit) {
    for (const ElementRecord& e : elements_)
      for (int s = 0; s < slices_; ++s) {
        const int base = e.vertexBegin + s * e.verticesPerSlice;
        for (const auto& tri : e.mesh->mesh.triangles) {
          const std::array<int, 3> global{base + tri[0], base + tri[1], base + tri[2]};
          for (int corner : global) emit(corner, global);
        }
      }
  });

  const std::size_t ns = growth_.size();
  sliceCentre_.assign(ns, {});
  sliceOverlapping_.assign(ns, 0);
  sliceGap_.assign(ns, kFar);
  sliceOutsideDepth_.assign(ns, 0.0);
  sliceArea_.assign(ns, 0.0);
  previousGrowth_.assign(ns, 0.0);
  growthChanged_.assign(ns, 1);
  restLengthsStale_ = true;
  unguidedGrowth_.assign(elements_.size(), 0.0);

  // The neighbour search over the container's box × [0, timeLength].
  SpacetimeNeighbours::Layout layout;
  layout.triangles = std::move(envelope_);
  layout.triangleElement = std::move(envelopeElement_);
  layout.vertexElement.resize(nv);
  for (std::size_t v = 0; v < nv; ++v) layout.vertexElement[v] = sliceElement_[sliceOf_[v]];
  layout.isSkin = isBoundary_;
  layout.area.add(Vec3{area.min.x, area.min.y, 0.0});
  layout.area.add(Vec3{area.max.x, area.max.y, spacetime_.timeLength});
  layout.cellSize = parameters_.cellSize;
  layout.shellReach = 2.5 * parameters_.cellSize;
  layout.margin = kNeighbourMargin;
  neighbours_.emplace(std::move(layout), pool_);
  computeReferencePoints(0, nv);
  computeSliceCentres();
  neighbours_->rebuild(position_);
}

// Where each vertex would be if its slice had its reference shape at its current growth:
// the rest lengths of all springs are distances between these points (5.5.3).
void SpacetimeSimulation::computeReferencePoints(std::size_t begin, std::size_t end) {
  for (std::size_t v = begin; v < end; ++v) {
    const int s = sliceOf_[v];
    const Vec2 c = referenceCentre_[s];
    const Vec2 p = c + (reference_[v] - c) * growth_[s];
    referencePoint_[v] = {p.x, p.y, restTime_[s]};
  }
}

// Whether x lies inside `element`'s cross-section at time x.t: the skin rings of the two
// slices around x.t, interpolated as the renderer does (5.6).
bool SpacetimeSimulation::insideElementAt(int element, Vec3 x, CrossSections& cache) const {
  const ElementRecord& e = elements_[element];
  const int nb = e.mesh->boundaryCount;
  const Vec2 p = spatial(x);
  for (int slot = 0; slot < CrossSections::kEntries; ++slot)
    if (const CrossSections::Entry& entry = cache.entries[slot]; entry.element == element && entry.t == x.t) {
      const Vec2* ring = cache.rings[slot].data();
      return entry.within && pointInRingOf(p, nb, [&](std::size_t k) { return ring[k]; });
    }
  const double* times = &sliceTime_[e.sliceBegin];
  const bool within = x.t >= times[0] && x.t <= times[slices_ - 1];
  const bool kept = nb <= CrossSections::kMaxRing;  // a longer ring is interpolated as it is read
  Vec2* ring = nullptr;
  if (kept) {
    const int slot = cache.next;
    cache.next = (slot + 1) % CrossSections::kEntries;
    cache.entries[slot] = {element, x.t, within};
    ring = cache.rings[slot].data();
  }
  if (!within) return false;
  const int s = std::clamp(static_cast<int>(std::upper_bound(times, times + slices_, x.t) - times) - 1, 0, slices_ - 2);
  const double span = times[s + 1] - times[s];
  const double w = span > 0.0 ? std::clamp((x.t - times[s]) / span, 0.0, 1.0) : 0.0;
  const int lower = e.vertexBegin + s * e.verticesPerSlice, upper = lower + e.verticesPerSlice;
  auto ringPoint = [&](std::size_t k) {
    const Vec3 a = position_[lower + k], b = position_[upper + k];
    return Vec2{a.x + (b.x - a.x) * w, a.y + (b.y - a.y) * w};
  };
  if (!kept) return pointInRingOf(p, nb, ringPoint);
  for (int k = 0; k < nb; ++k) ring[k] = ringPoint(k);
  return pointInRingOf(p, nb, [&](std::size_t k) { return ring[k]; });
}

void SpacetimeSimulation::computeForces(std::size_t begin, std::size_t end) {
  const SimulationParameters& P = parameters_;
  CrossSections crossSections;
  for (std::size_t v = begin; v < end; ++v) {
    const int slice = sliceOf_[v];
    const ElementRecord& element = elements_[sliceElement_[slice]];
    const Vec3 x = position_[v];
    Vec3 f;

    // Repulsion and overlap act on the envelope: the skin vertices of each slice.
    bool inside = false;
    double gap = kFar;
    if (isBoundary_[v]) {
      SpacetimeNeighbours::Hits hits;
      neighbours_->gather(static_cast<int>(v), position_, hits);
      for (int k = 0; k < hits.size() && !inside; ++k)
        if (hits[k].exact) inside = insideElementAt(hits[k].element, x, crossSections);
      if (inside) {
        // Eq. 4.4 in the slice: every incident triangle pulls the vertex toward its centroid.
        for (const std::array<int, 3>& tri : trianglesAt_.of(v)) {
          const Vec3 centroid = (position_[tri[0]] + position_[tri[1]] + position_[tri[2]]) / 3.0;
          f += forces::overlap(x, Vec3{centroid.x, centroid.y, x.t}, P.overlapStrength);
        }
        gap = 0.0;
      } else {
        for (const SpacetimeNeighbours::Hit& hit : hits) {
          f += forces::repulsion(x, hit.point, P.repulsionStrength, P.soft);
          if (hit.exact) gap = std::min(gap, std::sqrt(hit.d2));
        }
      }
    }
    insideOther_[v] = inside ? 1 : 0;

    // Eq. 4.3: springs, rest lengths from the reference shapes at the current growth (kept
    // while neither end's slice grows).
    const Vec3 r = referencePoint_[v];
    const std::span<const SpringEnd> ends = springsAt_.of(v);
    double* rest = springRest_.data() + springsAt_.start[v];
    for (std::size_t k = 0; k < ends.size(); ++k) {
      const SpringEnd& spring = ends[k];
      if (growthChanged_[slice] || growthChanged_[sliceOf_[spring.other]])
        rest[k] = distance(r, referencePoint_[spring.other]);
      f += forces::edge(x, position_[spring.other], rest[k], springStiffness_[spring.kind]);
    }

    // Eq. 4.5 in (x, y): the container is extruded along t.
    const Vec2 xy = spatial(x);
    RegionIndex::Query q = container_.query(xy, false);
    if (!q.inside && element.leavesContainer) {
      gap = 0.0;  // no container space out here: as if against the wall
    } else if (!q.inside) {
      if (!q.computed) q = container_.query(xy, true);
      const Vec2 pull = forces::boundary(xy, q.closest, P.boundaryStrength);
      f += Vec3{pull.x, pull.y, 0.0};
    }
    outsideDepth_[v] = q.inside ? 0.0 : q.computed ? q.distance : kFar;
    if (isBoundary_[v] && q.computed) gap = std::min(gap, q.distance);
    nearestGap_[v] = gap;

    // Pocket pressure, as in RepulsionPak: a skin vertex of a slice that stopped growing,
    // with room around it, bulges into the pocket.
    if (P.pocketPressure > 0.0 && isBoundary_[v] && !inside && growth_[slice] <= previousGrowth_[slice]) {
      double free = std::min(gap, P.cellSize);
      if (free > P.pocketClearance && !q.computed && container_.insideDistanceBound(xy) < free)
        free = std::min(free, container_.query(xy, true).distance);  // the wall may be nearer
      const int base = sliceVertexBegin_[slice], nb = element.mesh->boundaryCount, k = static_cast<int>(v) - base;
      const Vec2 before = spatial(position_[base + (k + nb - 1) % nb]), after = spatial(position_[base + (k + 1) % nb]);
      if (free > P.pocketClearance && !forces::reflexSkinVertex(before, xy, after)) {
        const Vec2 normal = normalized(Vec2{xy.y - before.y, before.x - xy.x} + Vec2{after.y - xy.y, xy.x - after.x});
        const Vec2 push = forces::pocketPressure(normal, free, P.pocketClearance, P.cellSize, P.pocketPressure);
        f += Vec3{push.x, push.y, 0.0};
      }
    }

    // Eq. 4.6: the slice turns back toward its reference orientation.
    if (element.torsionStrength > 0.0) {
      const Vec2 restDirection = reference_[v] - referenceCentre_[slice];
      const Vec2 turn = forces::torsion(xy, sliceCentre_[slice], restDirection, element.torsionStrength);
      f += Vec3{turn.x, turn.y, 0.0};
    }
    // Eq. 5.2: the temporal force keeps the vertex near its slice's time.
    f.t += spacetime_.temporalStrength * (restTime_[slice] - x.t);
    // Target-point spring of a guided element (5.4).
    if (const Vec2 target = targetPull_[v]; !std::isnan(target.x)) {
      const Vec2 pull = (target - xy) * spacetime_.targetStrength;
      f += Vec3{pull.x, pull.y, 0.0};
    }
    force_[v] = f;
  }
}

void SpacetimeSimulation::integrate(std::size_t begin, std::size_t end) {
  for (std::size_t v = begin; v < end; ++v) integrator_.advance(position_[v], velocity_[v], force_[v]);
}

// 5.5.2, constraints 1 and 2: the first and last slices sit at t = 0 and t = T, and every
// other slice's vertices share their mean t.
void SpacetimeSimulation::applySliceConstraints(std::size_t elementBegin, std::size_t elementEnd) {
  for (std::size_t e = elementBegin; e < elementEnd; ++e) {
    const ElementRecord& element = elements_[e];
    const int n = element.verticesPerSlice;
    for (int s = 0; s < slices_; ++s) {
      const int base = element.vertexBegin + s * n;
      double t;
      if (s == 0) {
        t = 0.0;
      } else if (s == slices_ - 1) {
        t = spacetime_.timeLength;
      } else {
        t = 0.0;
        for (int v = base; v < base + n; ++v) t += position_[v].t;
        t /= n;
      }
      for (int v = base; v < base + n; ++v) position_[v].t = t;
      sliceTime_[element.sliceBegin + s] = t;
    }
  }
}

// 5.5.2, constraint 3: the last slice A of `from` and the first slice B of `to` meet. Their
// centres move to the mean centre; each vertex's offset b from B's centre becomes the mean
// of b and M⁻¹a (a: the offset in A of the vertex paired with it, the same vertex unless the
// loop has partners; M: what is left of the scripted turn), and A's vertex takes M b.
// With M = identity every vertex pair moves to its mean, the thesis's rule. A loop with a
// shift joins A to B moved by it: A's centre is the mean centre plus the shift.
void SpacetimeSimulation::applyLoopConstraints() {
  for (const Loop& loop : loops_) {
    const ElementRecord& from = elements_[loop.from];
    const ElementRecord& to = elements_[loop.to];
    const int n = from.verticesPerSlice;
    Vec3* a = &position_[from.vertexBegin + (slices_ - 1) * n];
    Vec3* b = &position_[to.vertexBegin];
    Vec2 ca, cb;
    for (int i = 0; i < n; ++i) ca += spatial(a[i]), cb += spatial(b[i]);
    ca = ca / static_cast<double>(n), cb = cb / static_cast<double>(n);
    const Vec2 centre = (ca - loop.shift + cb) * 0.5;
    const Vec2 m = loop.turn;
    const double inv = 1.0 / lengthSquared(m);
    const int* partner = loop.partner.empty() ? nullptr : loop.partner.data();
    for (int i = 0; i < n; ++i) {
      Vec3& bp = b[partner ? partner[i] : i];
      const Vec2 ai = spatial(a[i]) - ca, bi = spatial(bp) - cb;
      const Vec2 back{(m.x * ai.x + m.y * ai.y) * inv, (-m.y * ai.x + m.x * ai.y) * inv};  // M⁻¹ a
      const Vec2 joined = (bi + back) * 0.5;
      const Vec2 ahead{m.x * joined.x - m.y * joined.y, m.y * joined.x + m.x * joined.y};  // M b
      bp.x = centre.x + joined.x, bp.y = centre.y + joined.y;
      a[i].x = centre.x + loop.shift.x + ahead.x, a[i].y = centre.y + loop.shift.y + ahead.y;
    }
  }
}

// Out at all, for an element that may leave (no container space out there); else pressed past
// the tolerance.
bool SpacetimeSimulation::sliceOutside(std::size_t s) const {
  const double tolerance = elements_[sliceElement_[s]].leavesContainer ? 0.0 : parameters_.outsideTolerance;
  return sliceOutsideDepth_[s] > tolerance;
}

// Per slice: centre, area, overlap flag, depth past the wall, nearest gap; then growth (5.5.3).
void SpacetimeSimulation::updateSlices(std::size_t begin, std::size_t end) {
  for (std::size_t s = begin; s < end; ++s) {
    const ElementRecord& element = elements_[sliceElement_[s]];
    const int base = sliceVertexBegin_[s], n = element.verticesPerSlice, nb = element.mesh->boundaryCount;
    Vec2 centre;
    bool overlapping = false;
    double gap = kFar, depth = 0.0;
    for (int v = base; v < base + n; ++v) {
      centre += spatial(position_[v]);
      overlapping = overlapping || insideOther_[v];
      depth = std::max(depth, outsideDepth_[v]);
      gap = std::min(gap, nearestGap_[v]);
    }
    sliceCentre_[s] = centre / static_cast<double>(n);
    double doubledArea = 0.0;
    for (int k = 0; k < nb; ++k) {
      const Vec3 a = position_[base + k], b = position_[base + (k + 1) % nb];
      doubledArea += a.x * b.y - b.x * a.y;
    }
    sliceArea_[s] = 0.5 * doubledArea;
    sliceOverlapping_[s] = overlapping ? 1 : 0;
    sliceOutsideDepth_[s] = depth;
    sliceGap_[s] = gap;
    const double grown = element.growth.grown(growth_[s]);
    bool smooth = true;
    if (spacetime_.growthSpread > 0.0) {  // neighbours in t as they were before this step
      const int first = element.sliceBegin, last = first + slices_ - 1;
      const int k = static_cast<int>(s);
      if (k > first) smooth = smooth && grown <= previousGrowth_[k - 1] + spacetime_.growthSpread;
      if (k < last) smooth = smooth && grown <= previousGrowth_[k + 1] + spacetime_.growthSpread;
    }
    if (settleFrom_ < 0 && !overlapping && !sliceOutside(s) && smooth) growth_[s] = grown;
  }
}

void SpacetimeSimulation::keepGuidedUp() {
  for (int k = 0; k < slices_; ++k) {
    std::size_t count = 0;
    for (const ElementRecord& e : elements_)
      if (!e.guided) unguidedGrowth_[count++] = growth_[e.sliceBegin + k];
    if (count == 0) return;
    const auto begin = unguidedGrowth_.begin(), mid = begin + static_cast<std::ptrdiff_t>(count / 2);
    std::nth_element(begin, mid, begin + static_cast<std::ptrdiff_t>(count));
    double median = *mid;
    if (count % 2 == 0) median = 0.5 * (median + *std::max_element(begin, mid));
    const double floor = spacetime_.guidedGrowth * median;
    for (const ElementRecord& e : elements_) {
      const int s = e.sliceBegin + k;
      // Behind or level (so the ratio never ends a rounding short of the share), not grown this
      // step by the common rule, and inside, pressed no further than the give past the wall, or
      // free to be outside: one growth step.
      if (e.guided && growth_[s] <= floor && growth_[s] == previousGrowth_[s] &&
          (e.leavesContainer || sliceOutsideDepth_[s] <= spacetime_.guidedWallGive))
        growth_[s] = e.growth.grown(growth_[s]);
    }
  }
}

void SpacetimeSimulation::step() {
  assert(finalized_ && "step only after finalize");
  const std::size_t nv = position_.size(), ns = growth_.size();
  pool_.parallelFor(nv, 2048, [&](std::size_t b, std::size_t e) { computeReferencePoints(b, e); });
  // previousGrowth_ is the growth the last step's rest lengths were computed at.
  for (std::size_t s = 0; s < ns; ++s) growthChanged_[s] = restLengthsStale_ || growth_[s] != previousGrowth_[s] ? 1 : 0;
  restLengthsStale_ = false;
  if (neighbours_->track(position_)) neighbours_->rebuild(position_);
  pool_.parallelFor(nv, 256, [&](std::size_t b, std::size_t e) { computeForces(b, e); });
  pool_.parallelFor(nv, 4096, [&](std::size_t b, std::size_t e) { integrate(b, e); });
  pool_.parallelFor(elements_.size(), 1, [&](std::size_t b, std::size_t e) { applySliceConstraints(b, e); });
  applyLoopConstraints();
  std::copy(growth_.begin(), growth_.end(), previousGrowth_.begin());
  pool_.parallelFor(ns, 256, [&](std::size_t b, std::size_t e) { updateSlices(b, e); });
  if (spacetime_.guidedGrowth > 0.0 && settleFrom_ < 0) keepGuidedUp();

  // Reductions in a fixed order, so they do not depend on the thread count.
  double area = 0.0, largestGap = 0.0;
  int growing = 0, overlapping = 0;
  for (std::size_t s = 0; s < ns; ++s) {
    area += sliceArea_[s];
    largestGap = std::max(largestGap, sliceGap_[s]);
    growing += (!sliceOverlapping_[s] && !sliceOutside(s) && elements_[sliceElement_[s]].growth.belowCap(growth_[s])) ? 1 : 0;
    overlapping += sliceOverlapping_[s];
  }
  fill_ = ns > 0 ? area / (containerArea_ * slices_) : 0.0;
  largestSliceGap_ = largestGap;
  growingSlices_ = growing;
  overlappingSlices_ = overlapping;
  ++iteration_;
  assert(allFinite(position_.data(), position_.data() + position_.size()) && "a step left a non-finite position");
}

void SpacetimeSimulation::beginSettle(double overlapStrength) {
  settleFrom_ = iteration_;
  parameters_.overlapStrength = overlapStrength;
}

double SpacetimeSimulation::minGrowth() const {
  return growth_.empty() ? 0.0 : *std::min_element(growth_.begin(), growth_.end());
}

void SpacetimeSimulation::restoreState(int iteration, std::vector<Vec3> positions, std::vector<Vec3> velocities,
                                       std::vector<double> growth, std::vector<double> previousGrowth,
                                       const std::vector<Vec3>& neighbourOrigin) {
  assert(finalized_ && "state is restored after finalize");
  assert(positions.size() == position_.size() && velocities.size() == velocity_.size() && growth.size() == growth_.size());
  assert(neighbourOrigin.size() == position_.size());
  iteration_ = iteration;
  position_ = std::move(positions);
  velocity_ = std::move(velocities);
  growth_ = std::move(growth);
  assert(previousGrowth.size() == growth_.size());
  previousGrowth_ = std::move(previousGrowth);
  restLengthsStale_ = true;  // none kept for this state
  for (const ElementRecord& e : elements_)
    for (int s = 0; s < slices_; ++s) sliceTime_[e.sliceBegin + s] = position_[e.vertexBegin + s * e.verticesPerSlice].t;
  computeSliceCentres();
  // The lists the uninterrupted run would have now: built where it built them.
  neighbours_->rebuild(neighbourOrigin);
}

void SpacetimeSimulation::computeSliceCentres() {
  for (std::size_t s = 0; s < growth_.size(); ++s) {
    const int base = sliceVertexBegin_[s], n = elements_[sliceElement_[s]].verticesPerSlice;
    Vec2 centre;
    for (int v = base; v < base + n; ++v) centre += spatial(position_[v]);
    sliceCentre_[s] = centre / static_cast<double>(n);
  }
}

}  // namespace pak
