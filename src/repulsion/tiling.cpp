// Tileable packings (thesis 4.8): periodic geometry shared by seeding, the seeding check and
// verification. The simulation's own periodic neighbour search lives in packing_simulation.cpp
// (it needs the grid); drawing a tile is pak/io's (tile_drawing.hpp).
#include "pak/repulsion/tiling.hpp"

#include <cmath>
#include <string>

#include "pak/error.hpp"
#include "pak/geom/clipping.hpp"

namespace pak {
namespace {

Region rectangle(Box box) {
  return Region{Polygon{{box.min, {box.max.x, box.min.y}, box.max, {box.min.x, box.max.y}}, {}}};
}

Box tileBox(Vec2 size) { return Box{{0.0, 0.0}, size}; }

}  // namespace

Scene tileScene(Vec2 size) {
  if (!(size.x > 0.0 && size.y > 0.0 && std::isfinite(size.x) && std::isfinite(size.y)))
    throw InputError("--tile", "must be two positive numbers W,H");
  Scene scene;
  scene.source = "tile " + std::to_string(size.x) + " x " + std::to_string(size.y);
  scene.container = rectangle(tileBox(size));
  return scene;
}

bool isTileScene(const Scene& scene, Vec2 size) {
  const Region expected = rectangle(tileBox(size));
  return scene.container.size() == 1 && scene.container.front().holes.empty() &&
         scene.container.front().outer == expected.front().outer;
}

std::array<Vec2, 9> periodicOffsets(Vec2 period) {
  std::array<Vec2, 9> offsets;
  int k = 0;
  offsets[k++] = {0.0, 0.0};
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i)
      if (i != 0 || j != 0) offsets[k++] = {i * period.x, j * period.y};
  return offsets;
}

double periodicDistance(Vec2 a, Vec2 b, Vec2 period) {
  // The nearest clone of b along each axis independently.
  Vec2 d = b - a;
  d.x -= period.x * std::round(d.x / period.x);
  d.y -= period.y * std::round(d.y / period.y);
  return length(d);
}

bool clonesOverlap(const std::vector<Region>& regions, Vec2 period) {
  std::vector<Box> boxes;
  for (const Region& r : regions) boxes.push_back(bounds(r));
  const std::array<Vec2, 9> offsets = periodicOffsets(period);
  for (std::size_t i = 0; i < regions.size(); ++i)
    for (std::size_t j = 0; j < regions.size(); ++j)
      for (std::size_t k = 1; k < offsets.size(); ++k) {
        Box moved{boxes[j].min + offsets[k], boxes[j].max + offsets[k]};
        if (!boxes[i].overlaps(moved)) continue;
        if (area(intersect(regions[i], transformed(regions[j], 1.0, offsets[k]))) > 0.0) return true;
      }
  return false;
}

std::vector<Region> periodicRepetition(const std::vector<Region>& regions, Vec2 period, int nx, int ny) {
  const Box block{{0.0, 0.0}, {nx * period.x, ny * period.y}};
  const Region blockRegion = rectangle(block);
  std::vector<Region> pieces;
  for (const Region& r : regions) {
    Box box = bounds(r);
    if (box.empty()) continue;
    // Every clone that can reach the block: offsets from left of it to right of it.
    int i0 = static_cast<int>(std::floor((block.min.x - box.max.x) / period.x));
    int i1 = static_cast<int>(std::ceil((block.max.x - box.min.x) / period.x));
    int j0 = static_cast<int>(std::floor((block.min.y - box.max.y) / period.y));
    int j1 = static_cast<int>(std::ceil((block.max.y - box.min.y) / period.y));
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        Vec2 offset{i * period.x, j * period.y};
        Box moved{box.min + offset, box.max + offset};
        if (!moved.overlaps(block)) continue;
        Region piece = intersect(transformed(r, 1.0, offset), blockRegion);
        if (area(piece) > 0.0) pieces.push_back(std::move(piece));
      }
  }
  return pieces;
}

}  // namespace pak
