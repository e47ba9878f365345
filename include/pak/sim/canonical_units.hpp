#pragma once
// Pak's distances are in canonical units, where the thesis's constants apply: the frame's
// longer side is kCanonicalSide. The frame is the containers' bounding box, and for FLOWPAK
// (its l_canvas, thesis 3.3.1) the fixed elements' too.
#include "pak/geom/box.hpp"
#include "pak/geom/scene.hpp"

namespace pak {

constexpr double kCanonicalSide = 1000.0;

// What the canonical frame spans, in input coordinates (empty for a scene without containers).
Box canonicalFrameBox(const Scene& scene, bool spansFixed);

}  // namespace pak
