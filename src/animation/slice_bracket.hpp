#pragma once
// The two slices a time falls between, and how far along from the first to the second: a
// frame at t interpolates them (thesis 5.6).
#include <algorithm>
#include <vector>

namespace pak {

struct SliceBracket {
  int slice;      // the first of the two; the second is slice + 1
  double weight;  // 0 at the first, 1 at the second
};

// `times` are the slices' times in increasing order (at least two); t outside them clamps.
inline SliceBracket sliceBracket(const std::vector<double>& times, double t) {
  const int last = static_cast<int>(times.size()) - 1;
  int s = static_cast<int>(std::upper_bound(times.begin(), times.end(), t) - times.begin()) - 1;
  s = std::clamp(s, 0, last - 1);
  const double span = times[s + 1] - times[s];
  return {s, span > 0.0 ? std::clamp((t - times[s]) / span, 0.0, 1.0) : 0.0};
}

}  // namespace pak
