#pragma once
// The check every packing command runs on its result, on the art as drawn.
#include <vector>

#include "pak/geom/polygon.hpp"
#include "pak/geom/verify.hpp"

namespace pak::cli {

// Overlaps and parts outside below this share of the container's area are not counted.
inline constexpr double kArtAreaTolerance = 1e-6;

// Overlaps between `outlines` and parts outside `container`, ignoring areas below
// kArtAreaTolerance of it;
// and the elements whose placed rings (`rings[i]`, element i's) cross themselves where their
// rings as drawn (`rest[i]`) do not.
PackingCheck checkArt(const std::vector<Region>& outlines, const Region& container,
                      const std::vector<std::vector<Ring>>& rings, const std::vector<std::vector<Ring>>& rest = {});

}  // namespace pak::cli
