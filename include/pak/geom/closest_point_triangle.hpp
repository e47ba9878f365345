#pragma once
// The point of triangle abc closest to p (Ericson, Real-Time Collision Detection, 5.1.5:
// Voronoi regions of the vertices, then the edges, then the face). Inline: the spacetime
// neighbour search calls it for every skin vertex at each list rebuild and in each step, and
// a call the compiler cannot see through cost about 2 % of a run (docs/animationpak.md,
// eighteenth round).
#include "pak/geom/vec3.hpp"

namespace pak {

inline Vec3 closestPointOnTriangle(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;  // vertex region A

  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return b;  // vertex region B

  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + ab * (d1 / (d1 - d3));  // edge AB

  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return c;  // vertex region C

  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + ac * (d2 / (d2 - d6));  // edge AC

  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
    return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));  // edge BC

  const double sum = va + vb + vc;
  if (sum == 0.0) return a;  // degenerate triangle
  const double v = vb / sum, w = vc / sum;
  return a + ab * v + ac * w;  // inside the face
}

}  // namespace pak
