#pragma once
// The forces of the RepulsionPak simulation (thesis eq. 4.2–4.6), as pure functions of
// positions so they can be tested against hand-computed values. Repulsion, edge, overlap and
// boundary forces are templates over the vector type: RepulsionPak uses them in the plane
// (Vec2), AnimationPak in (x, y, t) spacetime (Vec3, thesis 5.5).
#include <algorithm>

#include "pak/geom/vec2.hpp"
#include "pak/geom/vec3.hpp"

namespace pak::forces {

// Eq. 4.2, one neighbour: pushes x away from x_i, the closest point on the neighbour's skin.
// `soft` (ς) bounds the magnitude at k/ς when the points meet.
template <class V = Vec2>  // Vec2 when called with braced points
inline V repulsion(V x, V closestOnNeighbour, double k, double soft) {
  V u = x - closestOnNeighbour;
  double d2 = lengthSquared(u);
  if (d2 == 0.0) return {};
  return u * (k / (std::sqrt(d2) * (soft + d2)));
}

// Eq. 4.3: quadratic spring on vertex a (apply the negation to b). Pulls a toward b when
// stretched, pushes it away when compressed; magnitude k (|u| - rest)².
template <class V = Vec2>  // Vec2 when called with braced points
inline V edge(V a, V b, double restLength, double k) {
  V u = b - a;
  double len = length(u);
  if (len == 0.0) return {};
  double stretch = len - restLength;
  double s = stretch >= 0.0 ? 1.0 : -1.0;
  return u * (k * s * stretch * stretch / len);
}

// Eq. 4.4, one incident triangle: pulls an intruding vertex toward the triangle's centroid.
template <class V = Vec2>  // Vec2 when called with braced points
inline V overlap(V x, V triangleCentroid, double k) { return (triangleCentroid - x) * k; }

// Eq. 4.5: pulls a vertex outside the container toward the closest boundary point.
template <class V = Vec2>  // Vec2 when called with braced points
inline V boundary(V x, V closestOnBoundary, double k) { return (closestOnBoundary - x) * k; }

// Eq. 4.6: turns x about the element's current centre c back toward its rest direction
// `restDirection` (x_rest - c_rest rotated by the preferred orientation). Returns k·u⊥ with
// the sign of the angle from u to the rest direction, so the vertex rotates toward it.
inline Vec2 torsion(Vec2 x, Vec2 centre, Vec2 restDirection, double k) {
  Vec2 u = x - centre;
  double len = length(u);
  if (len == 0.0) return {};
  double turn = cross(u, restDirection);  // > 0: rest direction is counter-clockwise of u
  if (turn == 0.0) return {};
  Vec2 uPerp = perp(u) / len;
  return uPerp * (turn > 0.0 ? k : -k);
}

// Pocket pressure (Pak, not the thesis; docs/repulsionpak.md): a skin vertex whose nearest
// other skin or wall is `free` away, farther than `clearance`, is pushed along its outward
// `normal`, fully from `reach` (the repulsion cut-off) on.
inline Vec2 pocketPressure(Vec2 normal, double free, double clearance, double reach, double k) {
  if (free <= clearance) return {};
  return normal * (k * std::min(1.0, (free - clearance) / (reach - clearance)));
}

// A skin vertex where the ring turns inward by more than asin 0.2 (between `before` and
// `after`) is reflex: pushing both sides of a notch outward would fold them over it.
inline bool reflexSkinVertex(Vec2 before, Vec2 x, Vec2 after) {
  constexpr double kReflexTurn = 0.2;
  return cross(normalized(x - before), normalized(after - x)) < -kReflexTurn;
}

}  // namespace pak::forces
