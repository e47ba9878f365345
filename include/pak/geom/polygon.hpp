#pragma once
// Polygons with holes and multi-polygon regions, and their basic measures.
//
// Conventions: a Ring is a closed loop of vertices without the first vertex repeated.
// A Polygon's outer ring is counter-clockwise (positive signed area, y up) and its holes
// clockwise; `normalizeOrientation` enforces that. A Region is a set of disjoint polygons.
#include <cstddef>
#include <vector>

#include "pak/geom/box.hpp"
#include "pak/geom/vec2.hpp"

namespace pak {

using Ring = std::vector<Vec2>;
using Polyline = std::vector<Vec2>;

struct Polygon {
  Ring outer;
  std::vector<Ring> holes;
};

using Region = std::vector<Polygon>;

// Shoelace signed area: positive for counter-clockwise rings in a y-up frame.
double signedArea(const Ring& ring);
// Area of the outer ring minus the holes.
double area(const Polygon& polygon);
double area(const Region& region);
bool isCounterClockwise(const Ring& ring);
// Outer rings counter-clockwise, holes clockwise.
void normalizeOrientation(Polygon& polygon);
void normalizeOrientation(Region& region);
// Perimeter of a closed ring / a polyline.
double perimeter(const Ring& ring);
double polylineLength(const Polyline& line);
// Even-odd point-in-ring test (points exactly on an edge may go either way).
bool pointInRing(Vec2 p, const Ring& ring);
// The same test over the n points pointAt(0) … pointAt(n − 1), for a ring that is not stored
// (interpolated as it is read, say).
template <class PointAt>
bool pointInRingOf(Vec2 p, std::size_t n, PointAt&& pointAt) {
  if (n < 3) return false;
  bool inside = false;
  Vec2 b = pointAt(n - 1);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = pointAt(i);
    // Half-open rule on y so a vertex on the ray is counted once.
    if ((a.y > p.y) != (b.y > p.y)) {
      const double x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
      if (p.x < x) inside = !inside;
    }
    b = a;
  }
  return inside;
}
// Inside the outer ring and outside every hole.
bool pointInPolygon(Vec2 p, const Polygon& polygon);
bool pointInRegion(Vec2 p, const Region& region);
Box bounds(const Ring& ring);
Box bounds(const Polygon& polygon);
Box bounds(const Region& region);
// Area-weighted centroid of the region.
Vec2 centroid(const Region& region);
Vec2 centroid(const Ring& ring);
// Drops consecutive duplicates and a repeated closing vertex.
Ring cleanRing(const Ring& ring, double epsilon = 0.0);
// Outer rings only (holes filled).
Region fillHoles(const Region& region);
// Affine map helpers used to move regions between frames.
Ring transformed(const Ring& ring, double scale, Vec2 translate);
Region transformed(const Region& region, double scale, Vec2 translate);

}  // namespace pak
