// What a packing paints, shared by every packer's checks and reports.
#include "pak/sim/packing.hpp"

#include "pak/geom/clipping.hpp"

namespace pak {

const char* toString(StopReason reason) {
  switch (reason) {
    case StopReason::TargetFill: return "target-fill";
    case StopReason::Stalled: return "stalled";
    case StopReason::IterationCap: return "iteration-cap";
    case StopReason::TimeLimit: return "time-limit";
    case StopReason::Interrupted: return "interrupted";
  }
  return "?";
}

Region artOutline(const std::vector<Shape>& art) {
  std::vector<Region> painted;
  for (const Shape& s : art) painted.push_back(paintedRegion(s));
  return unite(painted);
}

std::vector<Region> artOutlines(const Packing& packing) {
  std::vector<Region> outlines;
  for (const PlacedElement& e : packing.elements) outlines.push_back(artOutline(e.art));
  return outlines;
}

std::vector<Ring> artRings(const std::vector<Shape>& art) {
  std::vector<Ring> rings;
  for (const Shape& s : art)
    if (s.fill)
      for (const Subpath& sub : s.subpaths) rings.push_back(sub.points);
  return rings;
}

std::vector<std::vector<Ring>> artRings(const Packing& packing) {
  std::vector<std::vector<Ring>> rings;
  for (const PlacedElement& e : packing.elements) rings.push_back(artRings(e.art));
  return rings;
}

double artFill(const Packing& packing) {
  double total = area(packing.fixedArt);
  for (const Region& r : artOutlines(packing)) total += area(r);
  double a = area(packing.container);
  return a > 0.0 ? total / a : 0.0;
}

}  // namespace pak
