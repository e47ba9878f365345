#pragma once
// Vector art as Pak understands it: flattened shapes with their paint.
#include <cstdint>
#include <optional>
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

// One drawn shape (an SVG path, rect, circle … after flattening and transforms): geometry
// and paint. What only documents know of it (id, layer, groups) is pak/io's SvgShape.
struct Shape {
  std::vector<Subpath> subpaths;
  std::optional<Color> fill;     // nullopt: fill="none"
  std::optional<Color> stroke;   // nullopt: no stroke
  double strokeWidth = 1.0;      // in the same units as the points
  double opacity = 1.0;          // group/element opacity
  FillRule fillRule = FillRule::NonZero;
  // Stroke ends, corners and miter limit. Round by default (shapes Pak draws itself, legacy
  // .path files); the SVG reader sets what the file says, with SVG's defaults (butt, miter, 4).
  StrokeCap lineCap = StrokeCap::Round;
  StrokeJoin lineJoin = StrokeJoin::Round;
  double miterLimit = 4.0;
  // Dashes: the lengths of dash and gap in turn (an even count), in the same units as the
  // points, and how far into that pattern the path starts. Empty: solid. Drawing only: the
  // outline (paintedRegion) takes the stroke as solid, which covers every dash.
  std::vector<double> dashArray;
  double dashOffset = 0.0;
  // The coordinate pairs it was drawn with (1 per move or line, 3 per cubic, as editors
  // count Bézier points); 0 when Pak made it. What the output's fitted curves are measured by.
  int drawnPoints = 0;
};

// What the shape's stroke becomes when the shape is scaled by `factor`: its width and dashes
// scaled alike.
void scaleStroke(Shape& shape, double factor);

// The region the shape's fill covers (fill rule applied; open subpaths closed, as SVG does).
// Geometry only: computed whether or not the shape has a fill paint (fill="none" included).
Region filledRegion(const Shape& shape, const ClipOptions& = {});
// Everything the shape paints: its fill (if any), plus its stroke (if any) grown to
// strokeWidth/2 with the shape's caps, joins and miter limit. A zero-length subpath with round
// or square caps paints a dot, as renderers do.
Region paintedRegion(const Shape& shape, const ClipOptions& = {});
// The same, given the shape's filledRegion with the same options: a caller that needs both
// unites the rings once (a shape of 100,000 subpaths costs Clipper a second a union).
Region paintedRegion(const Shape& shape, const Region& filled, const ClipOptions& = {});
// Bounds of the points, grown by strokeWidth/2 when the shape has a stroke.
Box bounds(const Shape& shape);
Box bounds(const std::vector<Shape>& shapes);

}  // namespace pak
