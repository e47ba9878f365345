#include "pak/geom/polygon.hpp"

#include <algorithm>
#include <cmath>

namespace pak {

double signedArea(const Ring& ring) {
  const std::size_t n = ring.size();
  if (n < 3) return 0.0;
  // Shoelace relative to the first vertex: the same value, less cancellation far from the origin.
  const Vec2 o = ring[0];
  double twice = 0.0;
  for (std::size_t i = 1; i + 1 < n; ++i) twice += cross(ring[i] - o, ring[i + 1] - o);
  return 0.5 * twice;
}

double area(const Polygon& polygon) {
  double a = std::abs(signedArea(polygon.outer));
  for (const Ring& hole : polygon.holes) a -= std::abs(signedArea(hole));
  return a;
}

double area(const Region& region) {
  double a = 0.0;
  for (const Polygon& p : region) a += area(p);
  return a;
}

bool isCounterClockwise(const Ring& ring) { return signedArea(ring) > 0.0; }

void normalizeOrientation(Polygon& polygon) {
  if (signedArea(polygon.outer) < 0.0) std::reverse(polygon.outer.begin(), polygon.outer.end());
  for (Ring& hole : polygon.holes)
    if (signedArea(hole) > 0.0) std::reverse(hole.begin(), hole.end());
}

void normalizeOrientation(Region& region) {
  for (Polygon& p : region) normalizeOrientation(p);
}

double perimeter(const Ring& ring) {
  const std::size_t n = ring.size();
  if (n < 2) return 0.0;
  double length = 0.0;
  for (std::size_t i = 0; i < n; ++i) length += distance(ring[i], ring[(i + 1) % n]);
  return length;
}

double polylineLength(const Polyline& line) {
  double length = 0.0;
  for (std::size_t i = 1; i < line.size(); ++i) length += distance(line[i - 1], line[i]);
  return length;
}

bool pointInRing(Vec2 p, const Ring& ring) {
  return pointInRingOf(p, ring.size(), [&](std::size_t i) { return ring[i]; });
}

bool pointInPolygon(Vec2 p, const Polygon& polygon) {
  if (!pointInRing(p, polygon.outer)) return false;
  for (const Ring& hole : polygon.holes)
    if (pointInRing(p, hole)) return false;
  return true;
}

bool pointInRegion(Vec2 p, const Region& region) {
  for (const Polygon& polygon : region)
    if (pointInPolygon(p, polygon)) return true;
  return false;
}

Box bounds(const Ring& ring) {
  Box box;
  for (Vec2 p : ring) box.add(p);
  return box;
}

Box bounds(const Polygon& polygon) { return bounds(polygon.outer); }

Box bounds(const Region& region) {
  Box box;
  for (const Polygon& p : region) box.add(bounds(p));
  return box;
}

namespace {

// Twice the signed area and the first moments (times 6) of a ring, about `o`.
struct RingMoments {
  double twiceArea = 0.0;
  Vec2 moment6;  // sum over edges of (a + b) * cross(a, b)
};

RingMoments ringMoments(const Ring& ring, Vec2 o) {
  RingMoments m;
  const std::size_t n = ring.size();
  if (n < 3) return m;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = ring[i] - o, b = ring[(i + 1) % n] - o;
    const double c = cross(a, b);
    m.twiceArea += c;
    m.moment6 += (a + b) * c;
  }
  return m;
}

Vec2 vertexAverage(const Region& region) {
  Vec2 sum;
  std::size_t count = 0;
  for (const Polygon& p : region)
    for (Vec2 v : p.outer) {
      sum += v;
      ++count;
    }
  return count ? sum / static_cast<double>(count) : Vec2{};
}

}  // namespace

Vec2 centroid(const Region& region) {
  // Moments about a vertex of the region keep the sums well conditioned.
  Vec2 o;
  for (const Polygon& p : region)
    if (!p.outer.empty()) {
      o = p.outer[0];
      break;
    }
  double twiceArea = 0.0;
  Vec2 moment6;
  auto accumulate = [&](const Ring& ring, double sign) {
    RingMoments m = ringMoments(ring, o);
    // Orientation-independent: outer rings add, holes subtract.
    const double s = (m.twiceArea >= 0.0 ? 1.0 : -1.0) * sign;
    twiceArea += s * m.twiceArea;
    moment6 += m.moment6 * s;
  };
  for (const Polygon& p : region) {
    accumulate(p.outer, 1.0);
    for (const Ring& hole : p.holes) accumulate(hole, -1.0);
  }
  if (twiceArea == 0.0 || !std::isfinite(twiceArea)) return vertexAverage(region);
  return o + moment6 / (3.0 * twiceArea);
}

Vec2 centroid(const Ring& ring) {
  if (ring.empty()) return {};
  const Vec2 o = ring[0];
  RingMoments m = ringMoments(ring, o);
  if (m.twiceArea == 0.0 || !std::isfinite(m.twiceArea)) {
    Vec2 sum;
    for (Vec2 v : ring) sum += v;
    return sum / static_cast<double>(ring.size());
  }
  return o + m.moment6 / (3.0 * m.twiceArea);
}

Ring cleanRing(const Ring& ring, double epsilon) {
  Ring out;
  out.reserve(ring.size());
  const double eps2 = epsilon * epsilon;
  for (Vec2 p : ring)
    if (out.empty() || lengthSquared(p - out.back()) > eps2) out.push_back(p);
  while (out.size() > 1 && lengthSquared(out.back() - out.front()) <= eps2) out.pop_back();
  return out;
}

Region fillHoles(const Region& region) {
  Region out;
  out.reserve(region.size());
  for (const Polygon& p : region) out.push_back(Polygon{p.outer, {}});
  return out;
}

Ring transformed(const Ring& ring, double scale, Vec2 translate) {
  Ring out;
  out.reserve(ring.size());
  for (Vec2 p : ring) out.push_back(p * scale + translate);
  return out;
}

Region transformed(const Region& region, double scale, Vec2 translate) {
  Region out;
  out.reserve(region.size());
  for (const Polygon& p : region) {
    Polygon q;
    q.outer = transformed(p.outer, scale, translate);
    for (const Ring& hole : p.holes) q.holes.push_back(transformed(hole, scale, translate));
    out.push_back(std::move(q));
  }
  return out;
}

}  // namespace pak
