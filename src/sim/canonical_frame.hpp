#pragma once
// Pak simulates in a canonical frame: the container's bounding square maps to
// [0, 1000]² (same orientation as the input, so y points down as in SVG), where the thesis's
// constants apply; results map back to the input's coordinates.
#include <algorithm>

#include "pak/geom/box.hpp"
#include "pak/geom/vec2.hpp"
#include "pak/sim/canonical_units.hpp"

namespace pak {

// canonical = (input - origin) * scale.
struct CanonicalFrame {
  Vec2 origin;
  double scale = 1.0;
  Vec2 toCanonical(Vec2 p) const { return (p - origin) * scale; }
  Vec2 toInput(Vec2 p) const { return p / scale + origin; }
  // The frame that maps `box`'s bounding square onto [0, 1000]².
  static CanonicalFrame of(const Box& box) {
    return {box.min, kCanonicalSide / std::max(box.width(), box.height())};
  }
};

}  // namespace pak
