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
#include "pak/io/svg_shape.hpp"

namespace pak {

// A shape as drawn: its geometry and paint, and the id the SVG writer gives it.
struct DrawnShape : Shape {
  std::string id;  // "" for none
};

struct DrawingGroup {
  std::string id;       // e.g. "container", "elements"
  std::string cssClass; // e.g. "element"
  std::vector<std::pair<std::string, std::string>> attributes;  // e.g. {"data-source", "cat.svg"}
  std::vector<DrawnShape> shapes;
  std::vector<DrawingGroup> children;
  std::optional<Box> clip = std::nullopt;  // draw only inside this box (an SVG clipPath), e.g. a tile
  // The SVG writer writes this instead of `shapes` (the PNG renderer still draws `shapes`).
  std::optional<RawMarkup> markup = std::nullopt;
  // The markup is the whole group as the input wrote it, its own <g> included (a scene's
  // layer, with its id, name and style): written in place of this group's <g>.
  bool markupReplacesGroup = false;
};

struct Drawing {
  Box viewBox;
  double width = 0.0, height = 0.0;  // output size in user units (0: viewBox size)
  // The size as the scene wrote it ("210mm", "8.5in"): written as it is instead of width and
  // height when either is given, so a packing opens at the size the artist drew (a side the
  // scene left out stays out).
  std::string widthText, heightText;
  std::vector<DrawingGroup> groups;
};

// Shapes to draw: the core's without ids (copies of one element must not repeat its SVG
// ids), a document's with theirs.
std::vector<DrawnShape> drawnShapes(const std::vector<Shape>& shapes);
std::vector<DrawnShape> drawnShapes(const std::vector<SvgShape>& shapes);

// Unfilled lines in one colour: what debug layers and outlines are drawn with.
inline DrawnShape strokedLines(std::vector<Subpath> subpaths, Color colour, double width) {
  DrawnShape s;
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
