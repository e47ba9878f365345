#pragma once
// The check every packing command runs on its result, on the art as drawn.
#include <vector>

#include "pak/geom/polygon.hpp"
#include "pak/geom/verify.hpp"

namespace pak::cli {

// Overlaps between `outlines` and parts outside `container`, ignoring areas below 1e-6 of it;
// and the elements whose drawn rings (`rings[i]`, element i's) cross themselves.
PackingCheck checkArt(const std::vector<Region>& outlines, const Region& container,
                      const std::vector<std::vector<Ring>>& rings);

}  // namespace pak::cli
