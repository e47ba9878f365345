// Drawing tileable packings: the tile's layout, clones across its edges, repeated previews.
#include "pak/io/tile_drawing.hpp"

#include <array>
#include <vector>

#include "pak/repulsion/tiling.hpp"

namespace pak {
namespace {

void translate(std::vector<DrawnShape>& shapes, Vec2 offset) {
  for (DrawnShape& s : shapes)
    for (Subpath& sub : s.subpaths)
      for (Vec2& p : sub.points) p += offset;
}

void translate(DrawingGroup& group, Vec2 offset) {
  translate(group.shapes, offset);
  if (group.clip) *group.clip = Box{group.clip->min + offset, group.clip->max + offset};
  for (DrawingGroup& child : group.children) translate(child, offset);
}

}  // namespace

SceneLayout tileLayout(Vec2 size) {
  const Scene tile = tileScene(size);
  SceneLayout layout;
  layout.viewBox = Box{{0.0, 0.0}, size};
  ContainerShape outline;
  outline.shape.subpaths.push_back({tile.container.front().outer, true});
  outline.shape.fill.reset();
  outline.shape.stroke.reset();
  outline.shape.tag = "rect";
  outline.shape.layer = "container";
  outline.keepsPaint = true;  // its paint is none
  layout.containerShapes.push_back(std::move(outline));
  return layout;
}

void addPeriodicClones(DrawingGroup& elements, Vec2 period) {
  const Box tile{{0.0, 0.0}, period};
  const std::array<Vec2, 9> offsets = periodicOffsets(period);
  for (DrawingGroup& element : elements.children) {
    const std::vector<DrawnShape> original = element.shapes;
    Box box;  // strokes included: a stroke may reach across the edge
    for (const DrawnShape& shape : original) box.add(bounds(shape));
    for (std::size_t k = 1; k < offsets.size(); ++k) {
      Box moved{box.min + offsets[k], box.max + offsets[k]};
      if (!moved.overlaps(tile)) continue;
      std::vector<DrawnShape> clone = original;
      translate(clone, offsets[k]);
      element.shapes.insert(element.shapes.end(), clone.begin(), clone.end());
    }
  }
  elements.clip = tile;
}

Drawing tileRepetition(const Drawing& tile, Vec2 period, int nx, int ny) {
  Drawing drawing;
  drawing.viewBox = Box{{0.0, 0.0}, {nx * period.x, ny * period.y}};
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      for (DrawingGroup group : tile.groups) {
        translate(group, {i * period.x, j * period.y});
        if (i != 0 || j != 0) group.id.clear();  // ids stay unique
        drawing.groups.push_back(std::move(group));
      }
  return drawing;
}

}  // namespace pak
