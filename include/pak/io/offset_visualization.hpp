#pragma once
// Thesis Fig. 6.4 as an image: every element outline offset by r over the container, with the
// areas covered by two or more offset elements in red.
#include <string>

#include "pak/metrics/metrics.hpp"

namespace pak {

// PNG, `width` pixels wide, written atomically; throws InputError when it cannot be written.
void writeOffsetVisualization(const PackingGeometry& packing, double r, const std::string& path, int width = 1000);

}  // namespace pak
