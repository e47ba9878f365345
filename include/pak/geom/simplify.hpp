#pragma once
// Douglas–Peucker simplification of closed rings and regions.
#include "pak/geom/polygon.hpp"

namespace pak {

// The fewest vertices of `ring` (a subset, first vertex kept) such that no removed vertex lies
// further than `tolerance` from the simplified ring.
Ring simplifyRing(const Ring& ring, double tolerance);
// simplifyRing on every ring; rings that would fall below 3 vertices are kept as they are.
Region simplifyRegion(const Region& region, double tolerance);

}  // namespace pak
