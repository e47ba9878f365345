#pragma once
// Reference packings with exact metric values (thesis Figure 6.2).
#include <cmath>
#include <numbers>

#include "pak/metrics/metrics.hpp"

namespace pak::test {

inline Region rect(double x0, double y0, double x1, double y1) {
  return {Polygon{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}}};
}

inline Region disc(Vec2 c, double radius, int vertices = 4096) {
  Ring ring;
  for (int k = 0; k < vertices; ++k) {
    const double t = 2.0 * std::numbers::pi * k / vertices;
    ring.push_back(c + Vec2{radius * std::cos(t), radius * std::sin(t)});
  }
  return {Polygon{ring, {}}};
}

// `count` gaps of width g between full-width bands of width b; the first and last bands are
// half outside the container, so every gap is g wide and Q(0) = g / (g + b).
inline PackingGeometry stripes(double width, int count, double b, double g) {
  PackingGeometry p;
  p.source = "stripes";
  const double period = b + g;
  p.container = rect(0, 0, width, count * period);
  for (int k = 0; k <= count; ++k)
    p.elements.push_back(rect(-1, k * period - b / 2, width + 1, k * period + b / 2));
  return p;
}

// n x n squares of side s, gap g between them and g/2 to the walls: the four-way crossings
// (empty discs of radius g*sqrt(2)/2) beat the wall junctions (g/2) and corners.
inline PackingGeometry squareGrid(int n, double s, double g) {
  PackingGeometry p;
  p.source = "squares";
  const double side = n * (s + g);
  p.container = rect(0, 0, side, side);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = g / 2 + i * (s + g), y = g / 2 + j * (s + g);
      p.elements.push_back(rect(x, y, x + s, y + s));
    }
  return p;
}

}  // namespace pak::test
