// What a read document shows, grouped by layer, so that `pak render` and the SVG writer
// draw exactly what the reader understood.
#include "pak/io/drawing.hpp"

#include "pak/io/svg_reader.hpp"

namespace pak {

std::vector<DrawnShape> drawnShapes(const std::vector<Shape>& shapes) {
  std::vector<DrawnShape> drawn;
  drawn.reserve(shapes.size());
  for (const Shape& shape : shapes) drawn.push_back({shape});
  return drawn;
}

std::vector<DrawnShape> drawnShapes(const std::vector<SvgShape>& shapes) {
  std::vector<DrawnShape> drawn;
  drawn.reserve(shapes.size());
  for (const SvgShape& shape : shapes) drawn.push_back({shape, shape.id});
  return drawn;
}

Drawing drawingFromDocument(const SvgDocument& document) {
  Drawing drawing;
  drawing.viewBox = document.viewBox.empty() ? bounds(document.shapes) : document.viewBox;
  drawing.width = document.width;
  drawing.height = document.height;
  drawing.widthText = document.widthText;
  drawing.heightText = document.heightText;
  // One group per layer, in the order layers first appear; shapes keep their document
  // order inside their layer. Shapes outside any layer share a group without id.
  for (const SvgShape& shape : document.shapes) {
    DrawingGroup* group = nullptr;
    for (DrawingGroup& existing : drawing.groups)
      if (existing.id == shape.layer) group = &existing;
    if (!group) {
      drawing.groups.emplace_back();
      group = &drawing.groups.back();
      group->id = shape.layer;
    }
    group->shapes.push_back({shape, shape.id});
  }
  return drawing;
}

}  // namespace pak
