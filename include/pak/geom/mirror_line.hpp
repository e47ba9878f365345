#pragma once
// A mirror line for symmetric packings (thesis Figs. 3.13 and 5.18): the packing is made on
// one side of the line and reflected across it. The line runs through `from` and `to` (input
// units, y down as in SVG); the packed side is the one on the left of a walk from `from` to
// `to` as seen on screen. So x = c is from (c, 1) to (c, 0): the part left of it is packed;
// y = c is from (0, c) to (1, c): the part above it.
#include <cmath>

#include "pak/geom/polygon.hpp"

namespace pak {

struct MirrorLine {
  Vec2 from, to;

  static MirrorLine vertical(double x) { return {{x, 1.0}, {x, 0.0}}; }
  static MirrorLine horizontal(double y) { return {{0.0, y}, {1.0, y}}; }

  Vec2 direction() const { return normalized(to - from); }
  // Whether the line is x = constant (from.x).
  bool isVertical() const { return from.x == to.x; }
  // p reflected across the line.
  Vec2 reflect(Vec2 p) const {
    const Vec2 d = direction(), v = p - from;
    return from + d * (2.0 * dot(d, v)) - v;
  }
  // The packed side, as a polygon (a square of side 2 × reach around the foot of `centre`):
  // clip with it.
  Polygon packedSide(Vec2 centre, double reach) const {
    const Vec2 d = direction(), left{d.y, -d.x};  // on screen (y down): the walker's left
    const Vec2 foot = from + d * dot(d, centre - from);
    const Vec2 a = foot - d * reach, b = foot + d * reach;
    return Polygon{{a, b, b + left * (2.0 * reach), a + left * (2.0 * reach)}, {}};
  }
};

}  // namespace pak
