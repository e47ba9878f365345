#include "flow/flow_prototype.hpp"

#include <cmath>
#include <numbers>

namespace pak {

std::array<Vec2, 2> elementSpine(const ElementArt& element) {
  if (element.spine && distance((*element.spine)[0], (*element.spine)[1]) > 0.0) return *element.spine;
  // Second moments of area about the centroid, summed over the rings' triangles (Green's
  // theorem); holes are clockwise so they subtract.
  Vec2 c = centroid(element.outline);
  double sxx = 0.0, syy = 0.0, sxy = 0.0;
  auto addRing = [&](const Ring& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      Vec2 a = ring[i] - c, b = ring[(i + 1) % ring.size()] - c;
      double w = cross(a, b);
      sxx += w * (a.x * a.x + a.x * b.x + b.x * b.x) / 12.0;
      syy += w * (a.y * a.y + a.y * b.y + b.y * b.y) / 12.0;
      sxy += w * (a.x * b.y + 2.0 * a.x * a.y + 2.0 * b.x * b.y + b.x * a.y) / 24.0;
    }
  };
  for (const Polygon& p : element.outline) {
    addRing(p.outer);
    for (const Ring& h : p.holes) addRing(h);
  }
  // Larger eigenvector of [[sxx, sxy], [sxy, syy]] (x², the spread along x, is sxx).
  double angle = 0.5 * std::atan2(2.0 * sxy, sxx - syy);
  Vec2 axis{std::cos(angle), std::sin(angle)};
  return {c - axis, c + axis};
}

FlowPrototype flowPrototype(const ElementArt& element, int maxRotationDegrees, int lrSamples) {
  FlowPrototype p;
  p.art = &element;
  p.outline = element.outline;
  auto spine = elementSpine(element);
  p.spineStart = spine[0];
  p.spineEnd = spine[1];
  p.rotations.push_back(0.0);
  for (int d = 1; d <= maxRotationDegrees; ++d) {
    p.rotations.push_back(d * std::numbers::pi / 180.0);
    p.rotations.push_back(-d * std::numbers::pi / 180.0);
  }
  for (double r : p.rotations) {
    StrokeFrame frame = strokeFrameFor(p.outline, p.spineStart, p.spineEnd, r);
    p.frames.push_back(frame);
    p.lr.push_back(elementLRFunction(rotatedElement(p.outline, frame), p.spineStart, p.spineEnd, lrSamples));
  }
  return p;
}

}  // namespace pak
