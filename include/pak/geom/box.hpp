#pragma once
// Axis-aligned bounding box.
#include <algorithm>
#include <limits>

#include "pak/geom/vec2.hpp"

namespace pak {

struct Box {
  Vec2 min{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  Vec2 max{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};

  bool empty() const { return !(min.x <= max.x && min.y <= max.y); }
  double width() const { return max.x - min.x; }
  double height() const { return max.y - min.y; }
  Vec2 center() const { return (min + max) * 0.5; }
  void add(Vec2 p) {
    min = {std::min(min.x, p.x), std::min(min.y, p.y)};
    max = {std::max(max.x, p.x), std::max(max.y, p.y)};
  }
  void add(const Box& b) {
    if (!b.empty()) { add(b.min); add(b.max); }
  }
  bool contains(Vec2 p) const { return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y; }
  bool overlaps(const Box& b) const {
    return min.x <= b.max.x && b.min.x <= max.x && min.y <= b.max.y && b.min.y <= max.y;
  }
};

}  // namespace pak
