// Overlap function O(r) (thesis 6.3.3): the area inside the container covered by two or more
// element outlines grown by r, over the container area.
#include <algorithm>
#include <cmath>

#include "metrics/metrics_internal.hpp"
#include "pak/geom/closest_point.hpp"

namespace pak {
namespace metrics_internal {
namespace {

Box grownBox(const Region& e, double r) {
  Box b = bounds(e);
  b.min = b.min - Vec2{r, r};
  b.max = b.max + Vec2{r, r};
  return b;
}

double cross(Vec2 a, Vec2 b, Vec2 c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

double segmentDistance(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const double d1 = cross(a, b, c), d2 = cross(a, b, d), d3 = cross(c, d, a), d4 = cross(c, d, b);
  if (((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0))) return 0.0;
  return std::min({length(a - closestPointOnSegment(a, c, d)), length(b - closestPointOnSegment(b, c, d)),
                   length(c - closestPointOnSegment(c, a, b)), length(d - closestPointOnSegment(d, a, b))});
}

struct Edge {
  Vec2 a, b;
  Box box;
};

// The edges of `region` whose boxes meet `within`.
std::vector<Edge> edgesNear(const Region& region, const Box& within) {
  std::vector<Edge> out;
  auto add = [&](const Ring& ring) {
    for (std::size_t k = 0; k < ring.size(); ++k) {
      Edge e{ring[k], ring[(k + 1) % ring.size()], {}};
      e.box.add(e.a);
      e.box.add(e.b);
      if (e.box.overlaps(within)) out.push_back(e);
    }
  };
  for (const Polygon& p : region) {
    add(p.outer);
    for (const Ring& h : p.holes) add(h);
  }
  return out;
}

double boxGap(const Box& p, const Box& q) {
  const double dx = std::max({0.0, q.min.x - p.max.x, p.min.x - q.max.x});
  const double dy = std::max({0.0, q.min.y - p.max.y, p.min.y - q.max.y});
  return std::hypot(dx, dy);
}

// Distance between two outlines, exact up to `reach` (beyond it, anything above reach):
// 0 when their boundaries cross or one holds the other.
double outlineDistance(const Region& a, const Region& b, double reach) {
  if (!a.empty() && !a[0].outer.empty() && pointInRegion(a[0].outer[0], b)) return 0.0;
  if (!b.empty() && !b[0].outer.empty() && pointInRegion(b[0].outer[0], a)) return 0.0;
  const std::vector<Edge> ea = edgesNear(a, grownBox(b, reach)), eb = edgesNear(b, grownBox(a, reach));
  double best = INFINITY;
  for (const Edge& p : ea)
    for (const Edge& q : eb)
      if (boxGap(p.box, q.box) < best) best = std::min(best, segmentDistance(p.a, p.b, q.a, q.b));
  return best;
}

}  // namespace

std::vector<ElementPair> nearPairs(const PackingGeometry& packing, double maxRadius,
                                   bool measureDistance) {
  std::vector<Box> boxes;
  for (const Region& e : packing.elements) boxes.push_back(grownBox(e, maxRadius));
  std::vector<ElementPair> pairs;
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (std::size_t j = i + 1; j < boxes.size(); ++j)
      if (boxes[i].overlaps(boxes[j]))
        pairs.push_back({static_cast<int>(i), static_cast<int>(j),
                         measureDistance ? outlineDistance(packing.elements[i], packing.elements[j],
                                                           2.0 * maxRadius)
                                         : 0.0});
  return pairs;
}

double overlapRatio(const PackingGeometry& packing, const std::vector<ElementPair>& pairs,
                    double r, const Frame& frame) {
  // Grow lazily: only elements of a pair that overlaps at r are ever offset.
  std::vector<Region> outline(packing.elements.size());
  std::vector<bool> ready(packing.elements.size(), false);
  auto get = [&](int i) -> const Region& {
    if (!ready[i]) {
      outline[i] = r > 0.0 ? offset(packing.elements[i], r, frame.offset) : packing.elements[i];
      ready[i] = true;
    }
    return outline[i];
  };
  std::vector<Region> pieces;
  for (const ElementPair& pair : pairs) {
    if (!(2.0 * r > pair.distance) && pair.distance > 0.0) continue;
    Region piece = intersect(get(pair.i), get(pair.j), frame.clip);
    if (!piece.empty()) pieces.push_back(std::move(piece));
  }
  if (pieces.empty()) return 0.0;
  return area(intersect(packing.container, unionOperand(std::move(pieces), frame), frame.clip)) /
         frame.containerArea;
}

Curve overlapCurve(const PackingGeometry& packing, const std::vector<ElementPair>& pairs,
                   const Frame& frame, double maxRadius, int count) {
  Curve o;
  o.r.resize(count);
  o.value.resize(count);
  for (int k = 0; k < count; ++k) o.r[k] = count > 1 ? maxRadius * k / (count - 1) : 0.0;
  parallelFor(count, [&](int k) { o.value[k] = overlapRatio(packing, pairs, o.r[k], frame); });
  return o;
}

}  // namespace metrics_internal

double overlapFunction(const PackingGeometry& packing, double r, double arcTolerance) {
  using namespace metrics_internal;
  const Frame frame = makeFrame(packing, arcTolerance);
  const PackingGeometry simplified = simplifiedForOffsets(packing, frame);
  return overlapRatio(simplified, nearPairs(simplified, r, false), r, frame);
}

}  // namespace pak
