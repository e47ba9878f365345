#include "pak/geom/art.hpp"

#include <algorithm>

namespace pak {
namespace {

// The stroke of one subpath: its band of half-width `halfWidth`, with the shape's caps,
// joins and miter limit (a closed subpath has no caps; a one-point subpath is a dot).
Region strokeBand(const Shape& shape, const Subpath& subpath, double halfWidth, const ClipOptions& options) {
  if (subpath.points.empty()) return {};
  OffsetOptions offsetOptions;
  offsetOptions.precision = options.precision;
  // Arcs as tight as the grid allows without exploding the vertex count on thin strokes.
  offsetOptions.arcTolerance = std::max(options.precision, halfWidth * 0.01);
  StrokeStyle style;
  style.cap = shape.lineCap;
  style.join = shape.lineJoin;
  style.miterLimit = shape.miterLimit;
  return strokeOutline(subpath.points, subpath.closed, halfWidth, style, offsetOptions);
}

}  // namespace

Region filledRegion(const Shape& shape, const ClipOptions& options) {
  std::vector<Ring> rings;
  rings.reserve(shape.subpaths.size());
  // SVG fills an open subpath as if it were closed, so both kinds are rings here.
  for (const Subpath& subpath : shape.subpaths)
    if (subpath.points.size() >= 3) rings.push_back(subpath.points);
  if (rings.empty()) return {};
  return regionFromRings(rings, shape.fillRule, options);
}

Region paintedRegion(const Shape& shape, const ClipOptions& options) {
  return paintedRegion(shape, shape.fill ? filledRegion(shape, options) : Region{}, options);
}

Region paintedRegion(const Shape& shape, const Region& filled, const ClipOptions& options) {
  std::vector<Region> parts;
  if (shape.fill) parts.push_back(filled);
  if (shape.stroke && shape.strokeWidth > 0.0) {
    for (const Subpath& subpath : shape.subpaths)
      parts.push_back(strokeBand(shape, subpath, 0.5 * shape.strokeWidth, options));
  }
  if (parts.empty()) return {};
  if (parts.size() == 1) return parts.front();
  return unite(parts, options);
}

void scaleStroke(Shape& shape, double factor) {
  shape.strokeWidth *= factor;
  for (double& length : shape.dashArray) length *= factor;
  shape.dashOffset *= factor;
}

Box bounds(const Shape& shape) {
  Box box;
  for (const Subpath& subpath : shape.subpaths)
    for (Vec2 p : subpath.points) box.add(p);
  if (!box.empty() && shape.stroke && shape.strokeWidth > 0.0) {
    const Vec2 half{0.5 * shape.strokeWidth, 0.5 * shape.strokeWidth};
    box.min -= half;
    box.max += half;
  }
  return box;
}

Box bounds(const std::vector<Shape>& shapes) {
  Box box;
  for (const Shape& shape : shapes) box.add(bounds(shape));
  return box;
}

}  // namespace pak
