// How large guided elements come out beside the others (AnimationPak quality issue, item 3).
#include <algorithm>
#include <limits>

#include "pak/animation/animation.hpp"

namespace pak {

double smallestGuidedGrowthRatio(const AnimatedPacking& animation) {
  double smallest = 1.0;
  std::vector<double> unguided;
  const std::size_t slices = static_cast<std::size_t>(animation.slices);
  for (std::size_t s = 0; s < slices; ++s) {
    unguided.clear();
    for (const AnimatedElement& e : animation.elements)
      if (!e.guided && s < e.sliceGrowth.size()) unguided.push_back(e.sliceGrowth[s]);
    if (unguided.empty()) return 1.0;
    const std::size_t mid = unguided.size() / 2;
    std::nth_element(unguided.begin(), unguided.begin() + static_cast<std::ptrdiff_t>(mid), unguided.end());
    double median = unguided[mid];
    if (unguided.size() % 2 == 0)
      median = 0.5 * (median + *std::max_element(unguided.begin(), unguided.begin() + static_cast<std::ptrdiff_t>(mid)));
    if (!(median > 0.0)) continue;
    for (const AnimatedElement& e : animation.elements)
      if (e.guided && s < e.sliceGrowth.size()) smallest = std::min(smallest, e.sliceGrowth[s] / median);
  }
  return smallest;
}

}  // namespace pak
