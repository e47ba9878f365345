#pragma once
// An axis-aligned box in (x, y, t) spacetime: a cheap lower bound on distances, for pruning
// closest-point searches.
#include <algorithm>
#include <limits>

#include "pak/geom/vec3.hpp"

namespace pak {

struct Box3 {
  Vec3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::infinity()};
  Vec3 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
          -std::numeric_limits<double>::infinity()};

  void add(Vec3 p) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.t, p.t)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.t, p.t)};
  }
  void add(const Box3& b) {
    add(b.lo);
    add(b.hi);
  }
};

// Squared distance from p to the box (0 inside).
inline double distanceSquared(const Box3& box, Vec3 p) {
  const double dx = std::max(std::max(box.lo.x - p.x, p.x - box.hi.x), 0.0);
  const double dy = std::max(std::max(box.lo.y - p.y, p.y - box.hi.y), 0.0);
  const double dt = std::max(std::max(box.lo.t - p.t, p.t - box.hi.t), 0.0);
  return dx * dx + dy * dy + dt * dt;
}

// Squared distance between two boxes (0 when they meet).
inline double distanceSquared(const Box3& a, const Box3& b) {
  const double dx = std::max(std::max(a.lo.x - b.hi.x, b.lo.x - a.hi.x), 0.0);
  const double dy = std::max(std::max(a.lo.y - b.hi.y, b.lo.y - a.hi.y), 0.0);
  const double dt = std::max(std::max(a.lo.t - b.hi.t, b.lo.t - a.hi.t), 0.0);
  return dx * dx + dy * dy + dt * dt;
}

}  // namespace pak
