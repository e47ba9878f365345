#pragma once
// A drawing to write or render: nested groups of shapes in a coordinate box. The SVG
// writer and the PNG renderer both take a Drawing, so every output looks the same in both.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "pak/geom/art.hpp"
#include "pak/geom/box.hpp"
#include "pak/io/raw_markup.hpp"

namespace pak {

struct DrawingGroup {
  std::string id;       // e.g. "container", "elements"
  std::string cssClass; // e.g. "element"
  std::vector<std::pair<std::string, std::string>> attributes;  // e.g. {"data-source", "cat.svg"}
  std::vector<Shape> shapes;
  std::vector<DrawingGroup> children;
  std::optional<Box> clip = std::nullopt;  // draw only inside this box (an SVG clipPath), e.g. a tile
  // The SVG writer writes this instead of `shapes` (the PNG renderer still draws `shapes`).
  std::optional<RawMarkup> markup = std::nullopt;
};

struct Drawing {
  Box viewBox;
  double width = 0.0, height = 0.0;  // output size in user units (0: viewBox size)
  std::vector<DrawingGroup> groups;
};

// Unfilled lines in one colour: what debug layers and outlines are drawn with.
inline Shape strokedLines(std::vector<Subpath> subpaths, Color colour, double width) {
  Shape s;
  s.subpaths = std::move(subpaths);
  s.fill.reset();
  s.stroke = colour;
  s.strokeWidth = width;
  return s;
}

// Everything the document shows, grouped by layer, for `pak render` and debugging.
struct SvgDocument;
Drawing drawingFromDocument(const SvgDocument& document);

}  // namespace pak
