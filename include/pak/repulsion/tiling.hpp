#pragma once
// Tileable packings (thesis 4.8, Figure 4.12): the packing lives on a torus, the rectangle
// [0, W] × [0, H] with opposite edges identified. An element may cross the tile's edge; its
// clones at offsets (k W, l H) fill in on the other side, so copies of the tile placed side by
// side join seamlessly.
#include <array>
#include <vector>

#include "pak/geom/polygon.hpp"
#include "pak/geom/scene.hpp"

namespace pak {

inline bool isTiled(Vec2 tile) { return tile.x > 0.0 && tile.y > 0.0; }

// The scene of a tile run: the rectangle [0, W] × [0, H] as the container (pak/io's
// tileLayout draws it). Throws InputError unless W and H are positive and finite.
Scene tileScene(Vec2 size);
// Is `scene` exactly tileScene(size)'s container?
bool isTileScene(const Scene& scene, Vec2 size);

// The offsets (k W, l H) of the 3 × 3 neighbourhood, k, l ∈ {-1, 0, 1}, (0, 0) first.
std::array<Vec2, 9> periodicOffsets(Vec2 period);
// Distance between a and b on the torus: the shortest over all clones of b.
double periodicDistance(Vec2 a, Vec2 b, Vec2 period);

// Does any region overlap a clone of any region (itself included) at a non-zero offset?
bool clonesOverlap(const std::vector<Region>& regions, Vec2 period);

// The nx × ny repetition of a tile at [0, W] × [0, H] whose `regions` may cross its edge:
// every clone of every region clipped to [0, nx W] × [0, ny H], one entry per non-empty
// clone. verifyPacking of this against that rectangle checks the seams.
std::vector<Region> periodicRepetition(const std::vector<Region>& regions, Vec2 period, int nx, int ny);

}  // namespace pak
