#pragma once
// Thesis Fig. 6.3b as an image: the distance transform of the negative space, each free pixel
// coloured by its distance to the nearest element or container boundary (dark: touching,
// light: far), elements in grey, the outside white.
#include <string>

#include "pak/metrics/metrics.hpp"

namespace pak {

// PNG, `width` pixels across the container's bounding square (one distance-map cell per
// pixel), written atomically; throws InputError when it cannot be written.
void writeDistanceMapImage(const PackingGeometry& packing, const std::string& path, int width = 1000);

}  // namespace pak
