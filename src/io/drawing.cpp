// What a read document shows, grouped by layer, so that `pak render` and the SVG writer
// draw exactly what the reader understood.
#include "pak/io/drawing.hpp"

#include <algorithm>
#include <string>

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
  // Shapes in document order, which is the order they are painted in: one group per run of
  // shapes of one layer, named by the layer. A layer that comes back after another (a group
  // with an id, copied by a <use> further on) keeps its name on its first run only, so that
  // ids stay unique. Shapes outside any layer are in groups without id.
  std::vector<std::string> named;
  std::string runLayer;
  for (const SvgShape& shape : document.shapes) {
    if (drawing.groups.empty() || shape.layer != runLayer) {
      runLayer = shape.layer;
      drawing.groups.emplace_back();
      if (std::find(named.begin(), named.end(), runLayer) == named.end()) {
        drawing.groups.back().id = runLayer;
        named.push_back(runLayer);
      }
    }
    drawing.groups.back().shapes.push_back({shape, shape.id});
  }
  return drawing;
}

}  // namespace pak
