// What a read document shows, grouped by layer, so that `pak render` and the SVG writer
// draw exactly what the reader understood.
#include "pak/io/drawing.hpp"

#include "pak/io/svg_reader.hpp"

namespace pak {

Drawing drawingFromDocument(const SvgDocument& document) {
  Drawing drawing;
  drawing.viewBox = document.viewBox.empty() ? bounds(document.shapes) : document.viewBox;
  drawing.width = document.width;
  drawing.height = document.height;
  // One group per layer, in the order layers first appear; shapes keep their document
  // order inside their layer. Shapes outside any layer share a group without id.
  for (const Shape& shape : document.shapes) {
    DrawingGroup* group = nullptr;
    for (DrawingGroup& existing : drawing.groups)
      if (existing.id == shape.layer) group = &existing;
    if (!group) {
      drawing.groups.emplace_back();
      group = &drawing.groups.back();
      group->id = shape.layer;
    }
    group->shapes.push_back(shape);
  }
  return drawing;
}

}  // namespace pak
