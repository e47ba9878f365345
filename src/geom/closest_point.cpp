#include "pak/geom/closest_point.hpp"

#include <cmath>
#include <limits>

namespace pak {
namespace {

// Folds segment (a, b), numbered `index`, into the best answer so far.
void consider(Vec2 p, Vec2 a, Vec2 b, std::size_t index, ClosestPoint& best, double& bestSquared) {
  double t = 0.0;
  const Vec2 q = closestPointOnSegment(p, a, b, &t);
  const double d2 = lengthSquared(p - q);
  if (d2 < bestSquared) {
    bestSquared = d2;
    best.point = q;
    best.segment = index;
    best.t = t;
  }
}

ClosestPoint none() {
  ClosestPoint c;
  c.distance = std::numeric_limits<double>::infinity();
  return c;
}

}  // namespace

Vec2 closestPointOnSegment(Vec2 p, Vec2 a, Vec2 b, double* t) {
  const Vec2 ab = b - a;
  const double len2 = lengthSquared(ab);
  double s = len2 > 0.0 ? dot(p - a, ab) / len2 : 0.0;
  s = s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s);
  if (t) *t = s;
  // Exact endpoints at the clamps, so callers can compare against vertices.
  if (s == 0.0) return a;
  if (s == 1.0) return b;
  return a + ab * s;
}

ClosestPoint closestPointOnPolyline(Vec2 p, const Polyline& line) {
  if (line.empty()) return none();
  ClosestPoint best = none();
  double bestSquared = std::numeric_limits<double>::infinity();
  if (line.size() == 1) consider(p, line[0], line[0], 0, best, bestSquared);
  for (std::size_t i = 0; i + 1 < line.size(); ++i) consider(p, line[i], line[i + 1], i, best, bestSquared);
  best.distance = std::sqrt(bestSquared);
  return best;
}

ClosestPoint closestPointOnRing(Vec2 p, const Ring& ring) {
  if (ring.empty()) return none();
  ClosestPoint best = none();
  double bestSquared = std::numeric_limits<double>::infinity();
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) consider(p, ring[i], ring[(i + 1) % n], i, best, bestSquared);
  best.distance = std::sqrt(bestSquared);
  return best;
}

ClosestPoint closestPointOnBoundary(Vec2 p, const Region& region) {
  ClosestPoint best = none();
  double bestSquared = std::numeric_limits<double>::infinity();
  // Segments are numbered across the region: polygon 0's outer ring, its holes, polygon 1 …
  std::size_t base = 0;
  auto scan = [&](const Ring& ring) {
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) consider(p, ring[i], ring[(i + 1) % n], base + i, best, bestSquared);
    base += n;
  };
  for (const Polygon& polygon : region) {
    scan(polygon.outer);
    for (const Ring& hole : polygon.holes) scan(hole);
  }
  if (bestSquared < std::numeric_limits<double>::infinity()) best.distance = std::sqrt(bestSquared);
  return best;
}

}  // namespace pak
