// The packing's frame and negative space, with the input checks every metric shares.
#include <algorithm>
#include <cmath>
#include <string>

#include "metrics/metrics_internal.hpp"
#include "pak/error.hpp"
#include "pak/limits.hpp"
#include "pak/geom/simplify.hpp"

namespace pak::metrics_internal {

Frame makeFrame(const PackingGeometry& packing, double arcTolerance) {
  Frame frame;
  frame.containerArea = area(packing.container);
  if (packing.container.empty() || !(frame.containerArea > 0.0))
    throw InputError(packing.source, "no container");
  if (packing.elements.empty()) throw InputError(packing.source, "no elements");
  frame.box = bounds(packing.container);
  frame.side = std::max(frame.box.width(), frame.box.height());
  // 1e-7 of the container keeps Clipper's integers in its fast 32-bit-product range.
  frame.clip.precision = frame.side * 1e-7;
  frame.offset.precision = frame.clip.precision;
  // Much finer, Clipper's arcs take millions of points (limits.hpp).
  const double finest = frame.side * limits::kMinArcToleranceShare;
  if (!(arcTolerance == 0.0 || (arcTolerance >= finest && arcTolerance <= frame.side)))
    throw InputError("--arc-tolerance", "must be 0 (automatic) or " + messageNumber(finest) + " to " +
                                            messageNumber(frame.side) + " (1e-8 to 1 of the container's size)");
  frame.offset.arcTolerance = arcTolerance > 0.0 ? arcTolerance : frame.side * 1e-4;
  for (std::size_t i = 0; i < packing.elements.size(); ++i) {
    const std::string name = "element " + std::to_string(i + 1);
    if (!(area(packing.elements[i]) > 0.0)) throw InputError(packing.source, name + " has no area");
    // Cheap accept first: most elements have a vertex inside the container.
    bool inside = false;
    for (const Polygon& p : packing.elements[i])
      for (Vec2 v : p.outer) inside = inside || pointInRegion(v, packing.container);
    if (!inside && !(area(intersect(packing.elements[i], packing.container, frame.clip)) > 0.0))
      throw InputError(packing.source, name + " lies entirely outside the container");
  }
  return frame;
}

Region negativeSpace(const PackingGeometry& packing, const Frame& frame) {
  return subtract(packing.container, unite(packing.elements, frame.clip), frame.clip);
}

PackingGeometry simplifiedForOffsets(const PackingGeometry& packing, const Frame& frame) {
  PackingGeometry simplified = packing;
  for (Region& e : simplified.elements) e = simplifyRegion(e, frame.offset.arcTolerance);
  return simplified;
}

Region unionOperand(std::vector<Region>&& parts, const Frame&) {
  Region all;
  for (Region& part : parts)
    for (Polygon& p : part) all.push_back(std::move(p));
  return all;
}

}  // namespace pak::metrics_internal
