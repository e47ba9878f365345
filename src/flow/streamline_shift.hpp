#pragma once
// Streamline shifting in the iterative refinement (thesis 3.3.6, Figures 3.5 and 3.6).
#include <array>
#include <vector>

#include "pak/flow/vector_field.hpp"
#include "pak/geom/polygon.hpp"

namespace pak {

struct ShiftOptions {
  double limit = 1.0;        // g_limit = 0.005 l_canvas: how far an endpoint may move
  double fieldWeight = 1.0;  // w_f in eq. 3.2
  double distanceWeight = 0.1;  // w_d in eq. 3.2
  double fieldPower = 3.0;   // p in eq. 3.2
  int neighbours = 150;      // nearest nodes examined from each node
  double fitTolerance = 0.0; // Bézier fit error; 0 means limit / 4
};

// New endpoints: each endpoint moves toward the midpoint of the segment joining the points
// where its left and right perpendiculars meet `occupied` (the other placed elements) or
// leave `freeSpace`, by at most `limit`. Each ray stops at 10 `limit` when it meets nothing.
std::array<Vec2, 2> shiftedEndpoints(const Polyline& streamline, const Region& occupied,
                                     const Region& freeSpace, double limit);

// The shifted streamline: the cheapest path (Dijkstra, edge cost eq. 3.2, no back-tracking)
// between the shifted endpoints over nodes made by resampling the streamline every limit/4
// and offsetting the samples left and right by multiples of limit/4 up to maxLeft / maxRight
// (the blob's widest extents), then fitted with cubic Béziers [Sch90] and flattened.
// A shifted end that is not in free space (e.g. on the blob boundary the streamline was
// extended to) slides back along the streamline by up to 2 limit until it is; the caller
// re-extends the result. Returns the original when no path exists.
// An empty `freeSpace` means "no outer bound" (only `occupied` is avoided). No point or edge
// of a shifted result lies inside `occupied` or outside a non-empty `freeSpace`.
// Throws InputError for an empty streamline, non-finite input or invalid options.
Polyline shiftStreamline(const Polyline& streamline, const VectorField& field, const Region& occupied,
                         const Region& freeSpace, double maxLeft, double maxRight,
                         const ShiftOptions& options);

}  // namespace pak
