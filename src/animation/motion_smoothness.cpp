// How calmly the elements move (thesis Fig. 5.21): weak time springs buy a tighter packing
// with frantic motion. Measured as the centroid's acceleration from frame to frame.
#include <cmath>

#include "animation/slice_bracket.hpp"
#include "pak/animation/animation.hpp"

namespace pak {

namespace {
// The mean of an element's mesh vertices at t, interpolated between its slices as a frame is.
Vec2 centroidAt(const AnimatedElement& element, double t) {
  const auto [s, w] = sliceBracket(element.sliceTimes, t);
  Vec2 a, b;
  for (Vec2 p : element.slices[s]) a += p;
  for (Vec2 p : element.slices[s + 1]) b += p;
  const double n = static_cast<double>(element.slices[s].size());
  return (a + (b - a) * w) / n;
}
}  // namespace

double meanCentroidAcceleration(const AnimatedPacking& animation, int frames) {
  if (frames < 3) return 0.0;
  auto frameTime = [&](int i) {
    return animation.loop ? static_cast<double>(i) / frames : static_cast<double>(i) / (frames - 1);
  };
  double sum = 0.0;
  int count = 0;
  std::vector<Vec2> path(static_cast<std::size_t>(frames));
  for (const AnimatedElement& element : animation.elements) {
    if (element.guided || element.slices.size() < 2) continue;
    for (int i = 0; i < frames; ++i) path[i] = centroidAt(element, frameTime(i));
    // A loop wraps around; an open animation has no neighbour beyond its ends.
    const int first = animation.loop ? 0 : 1, end = animation.loop ? frames : frames - 1;
    for (int i = first; i < end; ++i) {
      const Vec2 before = path[(i + frames - 1) % frames], after = path[(i + 1) % frames];
      sum += length(before - path[i] * 2.0 + after) * animation.canonicalScale;
      ++count;
    }
  }
  return count > 0 ? sum / count : 0.0;
}

}  // namespace pak
