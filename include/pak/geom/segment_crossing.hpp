#pragma once
// Where two segments cross properly: each one's ends strictly on opposite sides of the other
// (touching, collinear and shared-end cases are not crossings).
#include <optional>

#include "pak/geom/vec2.hpp"

namespace pak {

struct SegmentCrossing {
  double t = 0.0;  // along a→b
  double u = 0.0;  // along c→d
};

inline std::optional<SegmentCrossing> properCrossing(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  auto side = [](Vec2 p, Vec2 q, Vec2 r) {
    const double o = cross(q - p, r - p);
    return (o > 0.0) - (o < 0.0);
  };
  if (side(a, b, c) * side(a, b, d) >= 0 || side(c, d, a) * side(c, d, b) >= 0) return std::nullopt;
  const double denominator = cross(b - a, d - c);
  return SegmentCrossing{cross(c - a, d - c) / denominator, cross(c - a, b - a) / denominator};
}

}  // namespace pak
