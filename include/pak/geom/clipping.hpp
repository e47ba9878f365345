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

// Stroke geometry for strokeOutline: caps of open polylines and joins (SVG's linecap/linejoin).
enum class StrokeCap { Butt, Round, Square };
enum class StrokeJoin { Miter, Round, Bevel };
struct StrokeStyle {
  StrokeCap cap = StrokeCap::Round;
  StrokeJoin join = StrokeJoin::Round;
  double miterLimit = 4.0;  // SVG's stroke-miterlimit: miter length / stroke width
};
// The band of half-width `delta` around a polyline, open or `closed`, with the given caps and
// joins. A polyline of one point (or all points equal) gives a round or square dot, nothing
// for butt caps.
Region strokeOutline(const Polyline& line, bool closed, double delta, const StrokeStyle& style,
                     const OffsetOptions& = {});

}  // namespace pak
