#pragma once
// Drawing tileable packings (thesis 4.8, docs/tiling.md): the tile's layout, the clones that
// make one tile seamless, and previews of the tile repeated. The periodic geometry is the
// core's (pak/repulsion/tiling.hpp).
#include "pak/geom/vec2.hpp"
#include "pak/io/drawing.hpp"
#include "pak/io/scene_layout.hpp"

namespace pak {

// The layout of tileScene(size): the tile [0, W] × [0, H] as the view box, its rectangle as
// the container shape, drawn without paint (a visible outline would show as a line between
// tiles). Throws InputError unless W and H are positive and finite.
SceneLayout tileLayout(Vec2 size);

// Each child group of `elements` (one per element) gets its clones that reach into the tile
// [0, W] × [0, H], and the group is clipped to the tile, so the drawing is one seamless tile.
void addPeriodicClones(DrawingGroup& elements, Vec2 period);
// The nx × ny repetition of a tile drawing (clips moved along), for previews.
Drawing tileRepetition(const Drawing& tile, Vec2 period, int nx, int ny);

}  // namespace pak
