#include "pak/geom/hairline_cusps.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "pak/geom/clipping.hpp"
#include "pak/geom/closest_point.hpp"
#include "pak/geom/segment_crossing.hpp"
#include "pak/geom/verify.hpp"

namespace pak {

namespace {

// Two parts of a ring this much nearer in the plane than along it fold back on each other: a
// slit, or a spike sharper than about 11° (2 asin(0.1)); sharp tips drawn on purpose are wider.
constexpr double kFoldBack = 0.1;

// The distance between segments ab and cd, and how far along each (0…1) its closest points lie.
struct Closest { double distance, t, u; };
Closest closestBetween(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  if (const auto crossing = properCrossing(a, b, c, d)) return {0.0, crossing->t, crossing->u};
  // Otherwise an end of one is nearest the other.
  Closest best{std::numeric_limits<double>::infinity(), 0.0, 0.0};
  auto offer = [&](Vec2 p, Vec2 from, Vec2 to, bool onSecond, double end) {
    double at = 0.0;
    const double dist = distance(p, closestPointOnSegment(p, from, to, &at));
    if (dist < best.distance) best = onSecond ? Closest{dist, end, at} : Closest{dist, at, end};
  };
  offer(a, c, d, true, 0.0);
  offer(b, c, d, true, 1.0);
  offer(c, a, b, false, 0.0);
  offer(d, a, b, false, 1.0);
  return best;
}

}  // namespace

bool ringHasHairline(const Ring& ring, double width) {
  const std::size_t n = ring.size();
  if (n < 4) return false;
  // Sweep the edges by their smallest x, grown by `width`: only nearby edges are compared.
  // Arclength at each vertex, to tell a fold back from a curve.
  std::vector<double> along(n + 1, 0.0);
  for (std::size_t k = 0; k < n; ++k) along[k + 1] = along[k] + distance(ring[k], ring[(k + 1) % n]);
  const double perimeter = along[n];
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  auto lo = [&](std::size_t e) { return std::min(ring[e].x, ring[(e + 1) % n].x); };
  auto hi = [&](std::size_t e) { return std::max(ring[e].x, ring[(e + 1) % n].x); };
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return lo(a) < lo(b); });
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t e = order[i];
    const Vec2 a = ring[e], b = ring[(e + 1) % n];
    const double minY = std::min(a.y, b.y) - width, maxY = std::max(a.y, b.y) + width, maxX = hi(e) + width;
    for (std::size_t j = i + 1; j < n && lo(order[j]) <= maxX; ++j) {
      const std::size_t f = order[j];
      const Vec2 c = ring[f], d = ring[(f + 1) % n];
      if (std::max(c.y, d.y) < minY || std::min(c.y, d.y) > maxY) continue;
      const Closest near = closestBetween(a, b, c, d);
      if (near.distance >= width) continue;
      // Near in the plane and much nearer than along the ring: a fold back, not a finely
      // sampled curve or a corner.
      const double s = std::abs((along[e] + near.t * (along[e + 1] - along[e])) - (along[f] + near.u * (along[f + 1] - along[f])));
      const double between = std::min(s, perimeter - s), gap = near.distance;
      if (gap < width && gap < kFoldBack * between) return true;
    }
  }
  return false;
}

int removeHairlineCusps(std::vector<Shape>& art, double width) {
  int changed = 0;
  for (Shape& shape : art) {
    if (!shape.fill || shape.stroke) continue;
    // A ring drawn crossing itself (petals drawn as one path) is the artist's; left as drawn.
    if (std::any_of(shape.subpaths.begin(), shape.subpaths.end(), [](const Subpath& s) { return ringSelfIntersects(s.points); }))
      continue;
    const bool hairline = std::any_of(shape.subpaths.begin(), shape.subpaths.end(),
                                      [&](const Subpath& s) { return ringHasHairline(s.points, width); });
    if (!hairline) continue;
    OffsetOptions options;
    options.arcTolerance = width / 100.0;
    options.precision = width / 1000.0;
    const double r = width / 2.0;
    const Region fill = filledRegion(shape);
    // Not simplified afterwards: the art bends with its mesh only at its points, so a long
    // straight edge must keep the points it was drawn with.
    const Region cleaned = offset(offset(offset(offset(fill, r, options), -r, options), -r, options), r, options);
    std::vector<Subpath> subpaths;
    for (const Polygon& polygon : cleaned) {
      subpaths.push_back({polygon.outer, true});
      for (const Ring& hole : polygon.holes) subpaths.push_back({hole, true});
    }
    if (subpaths.empty()) continue;  // nothing but hairlines: leave it as drawn
    shape.subpaths = std::move(subpaths);
    shape.fillRule = FillRule::NonZero;
    ++changed;
  }
  return changed;
}

}  // namespace pak
