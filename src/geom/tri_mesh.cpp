#include "pak/geom/tri_mesh.hpp"

namespace pak {

double triangleSignedArea(Vec2 a, Vec2 b, Vec2 c) { return 0.5 * cross(b - a, c - a); }

std::array<double, 3> barycentric(Vec2 p, Vec2 a, Vec2 b, Vec2 c) {
  const double whole = triangleSignedArea(a, b, c);
  // A degenerate triangle has no barycentric frame; fall back to its first vertex.
  if (whole == 0.0) return {1.0, 0.0, 0.0};
  const double u = triangleSignedArea(p, b, c) / whole;
  const double v = triangleSignedArea(a, p, c) / whole;
  return {u, v, 1.0 - u - v};
}

}  // namespace pak
