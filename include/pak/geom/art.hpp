#pragma once
// Vector art as Pak understands it: flattened shapes with their paint.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "pak/geom/clipping.hpp"
#include "pak/geom/polygon.hpp"

namespace pak {

struct Color {
  std::uint8_t r = 0, g = 0, b = 0;
  double alpha = 1.0;  // fill-opacity / stroke-opacity folded in
  friend bool operator==(const Color&, const Color&) = default;
};

struct Subpath {
  std::vector<Vec2> points;  // flattened; the closing vertex is not repeated
  bool closed = false;
};

// One drawn shape (an SVG path, rect, circle … after flattening and transforms).
struct Shape {
  std::vector<Subpath> subpaths;
  std::optional<Color> fill;     // nullopt: fill="none"
  std::optional<Color> stroke;   // nullopt: no stroke
  double strokeWidth = 1.0;      // in the same units as the points
  double opacity = 1.0;          // group/element opacity
  FillRule fillRule = FillRule::NonZero;
  std::string id;                // the SVG id, if any
  std::string tag;               // "path", "rect", … or "path-file" for .path input
  std::string layer;             // lower-cased name of the enclosing layer ("" if none)
  int topGroup = -1;             // index of the enclosing top-level <g>, -1 if none
  int layerGroup = -1;           // index of the enclosing direct child <g> of the layer's group
                                 // (one packed element in Pak's output), -1 if none
  std::string elements;          // `data-elements` of the shape or its nearest group that has
                                 // one: the library a container shape asks for ("" if none)
  std::string gap;               // `data-gap`, likewise: a container's own FLOWPAK s_gap ("" if none)
};

// The region the shape's fill covers (fill rule applied; open subpaths closed, as SVG does).
// Geometry only: computed whether or not the shape has a fill paint (fill="none" included).
Region filledRegion(const Shape& shape, const ClipOptions& = {});
// Everything the shape paints: its fill (if any), plus its stroke (if any) grown to
// strokeWidth/2 with round joins and caps.
Region paintedRegion(const Shape& shape, const ClipOptions& = {});
// Bounds of the points, grown by strokeWidth/2 when the shape has a stroke.
Box bounds(const Shape& shape);
Box bounds(const std::vector<Shape>& shapes);

}  // namespace pak
