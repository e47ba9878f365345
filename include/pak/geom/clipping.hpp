#pragma once
// Boolean operations and offsets on regions (Clipper underneath, integer coordinates
// scaled so that `precision` units are resolved exactly).
#include <vector>

#include "pak/geom/polygon.hpp"

namespace pak {

enum class FillRule { NonZero, EvenOdd };

struct ClipOptions {
  // Smallest distance the integer grid resolves, in the input's units.
  double precision = 1e-4;
};

// Turns a set of possibly self-intersecting rings into a clean Region under a fill rule.
Region regionFromRings(const std::vector<Ring>& rings, FillRule rule, const ClipOptions& = {});
Region unite(const Region& a, const Region& b, const ClipOptions& = {});
Region unite(const std::vector<Region>& regions, const ClipOptions& = {});
Region subtract(const Region& a, const Region& b, const ClipOptions& = {});
Region intersect(const Region& a, const Region& b, const ClipOptions& = {});

struct OffsetOptions {
  // Maximum distance between the true round arc and its polygonal approximation.
  double arcTolerance = 0.25;
  double precision = 1e-4;
};
// Grows (delta > 0) or shrinks (delta < 0) a region with round joins.
Region offset(const Region& region, double delta, const OffsetOptions& = {});
// Grows a polyline into a band of half-width `delta` (round caps and joins).
Region offsetPolyline(const Polyline& line, double delta, const OffsetOptions& = {});

}  // namespace pak
