#pragma once
// The evenness measure as an image, one pixel per grid cell: the negative space shaded by its
// distance D to the nearest element or wall (dark blue at the wall, teal at 2h), the pockets
// D > 2h in orange and D > 3h in red, the medial axis in white, elements and fixed art light
// grey, the small holes counted as positive space darker grey, the outside white. The axis is
// drawn three cells wide so it survives being shown smaller.
#include <string>

#include "pak/metrics/evenness.hpp"

namespace pak {

// PNG of evennessMap(packing, options), written atomically; returns the measurement drawn.
// Throws InputError when it cannot be written or the resolution is not 16 to 8192.
Evenness writeEvennessMapImage(const PackingGeometry& packing, const std::string& path,
                               const EvennessOptions& options = {});

}  // namespace pak
