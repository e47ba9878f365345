#pragma once
// Fitting a polyline with a chain of cubic Bézier curves (Schneider's algorithm [Sch90]),
// and flattening them back.
#include <array>
#include <vector>

#include "pak/geom/polygon.hpp"

namespace pak {

using CubicBezier = std::array<Vec2, 4>;

// Where one curve ends and the next begins. Schneider splits a span that does not fit at its
// worst point; Pak by default lets each curve reach as far along the points as one cubic can,
// which takes about a fifth fewer curves on smooth data (docs/repulsionpak.md, "Smooth art").
enum class FitSpans { Longest, SplitAtWorst };

// Curves joined end to end, from the line's first point to its last; every input point is
// within `tolerance` of the chain, and the chain within `tolerance` of the polyline. Corners
// sharper than `cornerAngle` (radians) are kept.
std::vector<CubicBezier> fitCubicBeziers(const Polyline& line, double tolerance, double cornerAngle = 1.0,
                                         FitSpans spans = FitSpans::Longest);
// Closed rings: the chain starts and ends at the ring's first vertex.
std::vector<CubicBezier> fitCubicBeziersClosed(const Ring& ring, double tolerance, double cornerAngle = 1.0,
                                               FitSpans spans = FitSpans::Longest);
// Points along the chain, at most `tolerance` from the curves (first and last points kept).
Polyline flatten(const std::vector<CubicBezier>& curves, double tolerance);
// The largest distance from any of `points` to the chain (flattened within `precision`, which
// is also about the error of the answer): how far a fit strays from what it fits.
double largestDistanceToChain(const std::vector<Vec2>& points, const std::vector<CubicBezier>& curves, double precision);
// How far a fit strays, both ways: the larger of the points' distance to the chain and the
// chain's distance to the polyline through the points (closed: the ring), the latter
// measured within about 2.5 × `precision`.
double fitDeviation(const std::vector<Vec2>& points, bool closed, const std::vector<CubicBezier>& curves, double precision);

}  // namespace pak
