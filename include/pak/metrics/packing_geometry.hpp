#pragma once
// The metrics' view of a packing Pak has just made, for reports that measure it without
// writing and re-reading an SVG (e.g. `pak pack --report`):
//
//   Evenness e = measureEvenness(packingGeometry(packing, "out.svg"));
#include <string>

#include "pak/metrics/metrics.hpp"

namespace pak {

struct Packing;

// The container, what each placed element paints (artOutlines) and what the fixed elements
// paint (Packing::fixedArt), in the packing's input coordinates, as readPacking would return
// them for the SVG Pak writes of it. `source` names it in errors.
PackingGeometry packingGeometry(const Packing& packing, const std::string& source = "");

}  // namespace pak
