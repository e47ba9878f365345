#pragma once
// Keyframe tracks of AnimationPak's scripted animations (thesis 5.3.2): values given at a few
// times t ∈ [0, 1], interpolated smoothly between them (Catmull–Rom through the keys),
// constant before the first key and after the last.
#include <vector>

#include "pak/geom/vec2.hpp"

namespace pak {

struct ScalarKey {
  double t = 0.0;
  double value = 0.0;
};

struct PointKey {
  double t = 0.0;
  Vec2 value;
};

// Keys must be sorted by t (readers check this). Empty: `fallback`. One key: its value.
// `periodic`: the track loops (t = 0 and t = 1 are the same moment), so the tangents at the
// ends are taken across the seam and a looping animation has no kink there.
double sampleTrack(const std::vector<ScalarKey>& keys, double t, double fallback, bool periodic = false);
Vec2 sampleTrack(const std::vector<PointKey>& keys, double t, Vec2 fallback, bool periodic = false);

}  // namespace pak
