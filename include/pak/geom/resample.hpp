#pragma once
// Uniform resampling of rings and polylines by arclength.
#include "pak/geom/polygon.hpp"

namespace pak {

// Returns max(3, round(perimeter / spacing)) points evenly spaced along the closed ring,
// starting at its first vertex.
Ring resampleRing(const Ring& ring, double spacing);
// Evenly spaced points from the first to the last vertex (both kept), at most `spacing` apart.
Polyline resamplePolyline(const Polyline& line, double spacing);
// The point at arclength s along the closed ring (s wraps around).
Vec2 pointAtArclength(const Ring& ring, double s);

}  // namespace pak
