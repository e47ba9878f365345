#pragma once
// Drawing tileable packings (thesis 4.8, docs/tiling.md): the clones that make one tile
// seamless, and previews of the tile repeated. The periodic geometry is the core's
// (pak/repulsion/tiling.hpp).
#include "pak/geom/vec2.hpp"
#include "pak/io/drawing.hpp"

namespace pak {

// Each child group of `elements` (one per element) gets its clones that reach into the tile
// [0, W] × [0, H], and the group is clipped to the tile, so the drawing is one seamless tile.
void addPeriodicClones(DrawingGroup& elements, Vec2 period);
// The nx × ny repetition of a tile drawing (clips moved along), for previews.
Drawing tileRepetition(const Drawing& tile, Vec2 period, int nx, int ny);

}  // namespace pak
