#pragma once
// Closest points on segments, polylines, rings and region boundaries.
#include <cstddef>

#include "pak/geom/polygon.hpp"

namespace pak {

// Empty input gives distance = +infinity.
struct ClosestPoint {
  Vec2 point;
  double distance = 0.0;
  // Index of the segment (from vertex `segment` to the next one) holding `point`.
  std::size_t segment = 0;
  // Parameter along that segment, in [0, 1].
  double t = 0.0;
};

Vec2 closestPointOnSegment(Vec2 p, Vec2 a, Vec2 b, double* t = nullptr);
ClosestPoint closestPointOnPolyline(Vec2 p, const Polyline& line);
ClosestPoint closestPointOnRing(Vec2 p, const Ring& ring);
// Closest point on any outer ring or hole of the region. `segment` counts the segments of
// all rings in order (polygon 0's outer ring, its holes, polygon 1's outer ring …).
ClosestPoint closestPointOnBoundary(Vec2 p, const Region& region);

}  // namespace pak
