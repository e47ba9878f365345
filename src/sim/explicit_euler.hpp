#pragma once
// The integrator both simulators use (thesis 4.5 and 5.5, "Simulation Details"): one explicit
// Euler step per vertex, velocity from force, then position from velocity, with damping and
// a cap on the speed. Templated over the vector type: Vec2 for RepulsionPak, Vec3 (x, y, t)
// for AnimationPak. Pure per-vertex arithmetic: no allocation, no shared state, so a
// parallel loop over vertices gives the same result on any number of threads.
#include <cassert>
#include <cmath>

#include "pak/geom/vec2.hpp"
#include "pak/geom/vec3.hpp"

namespace pak {

inline bool isFinite(Vec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }
inline bool isFinite(Vec3 p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.t); }

// Every point of [begin, end) finite: what a step must leave behind.
template <class V>
bool allFinite(const V* begin, const V* end) {
  for (const V* p = begin; p != end; ++p)
    if (!isFinite(*p)) return false;
  return true;
}

// v ← (1 − d) v + Δt f, capped at the velocity cap; x ← x + Δt v. The damping d takes a
// fraction of the velocity the vertex arrives with, not of this step's push, so a vertex at
// rest answers a force in full.
class ExplicitEuler {
 public:
  // damping d ∈ [0, 1): the fraction of the velocity lost per step; velocityCap > 0.
  ExplicitEuler(double timeStep, double velocityCap, double damping)
      : timeStep_(timeStep), velocityCap_(velocityCap), keep_(1.0 - damping) {
    assert(timeStep > 0.0 && velocityCap > 0.0 && damping >= 0.0 && damping < 1.0);
  }

  // One step of one vertex under `force`.
  template <class V>
  void advance(V& position, V& velocity, V force) const {
    V next = velocity * keep_ + force * timeStep_;
    const double speed = length(next);
    if (speed > velocityCap_) next *= velocityCap_ / speed;
    velocity = next;
    position += next * timeStep_;
  }

 private:
  double timeStep_, velocityCap_, keep_;
};

}  // namespace pak
