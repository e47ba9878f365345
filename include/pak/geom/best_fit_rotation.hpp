#pragma once
// The rotation that best maps one set of offsets onto another in the least-squares sense (2-D
// shape matching): the weighted sums of the dot and cross products of corresponding offsets,
// normalised, are its cosine and sine.
#include <cmath>

#include "pak/geom/vec2.hpp"

namespace pak {

struct BestFitRotation {
  double along = 0.0, across = 0.0;

  void add(Vec2 from, Vec2 to, double weight = 1.0) {
    along += weight * dot(from, to);
    across += weight * cross(from, to);
  }
  // The turn as a unit (cos, sin) pair, for rotated(a, turn); no turn when the offsets vanish.
  Vec2 turn() const {
    const double norm = std::hypot(along, across);
    return norm > 0.0 ? Vec2{along / norm, across / norm} : Vec2{1.0, 0.0};
  }
};

}  // namespace pak
