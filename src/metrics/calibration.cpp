// Calibration (thesis 6.4): one uniform offset of every element outline, found by bisection,
// brings the packing's negative-space ratio to a common target.
#include <algorithm>
#include <cmath>
#include <string>

#include "metrics/metrics_internal.hpp"
#include "pak/error.hpp"

namespace pak {

Calibration calibrateNegativeSpace(const PackingGeometry& packing, double targetNegativeRatio,
                                   double tolerance) {
  using namespace metrics_internal;
  const Frame frame = makeFrame(packing, 0.0);
  if (!(targetNegativeRatio >= 0.0 && targetNegativeRatio <= 1.0))
    throw InputError(packing.source, "calibration target " + std::to_string(targetNegativeRatio) +
                                         " is not a ratio in [0, 1]");
  if (!(tolerance > 0.0)) throw InputError(packing.source, "calibration tolerance must be positive");

  Calibration result;
  result.calibrated.source = packing.source;
  result.calibrated.container = packing.container;
  result.calibrated.fixed = packing.fixed;  // fixed art is not part of the packing's deformation
  auto apply = [&](double d) {
    result.offset = d;
    result.calibrated.elements.clear();
    for (const Region& e : packing.elements)
      result.calibrated.elements.push_back(d == 0.0 ? e : offset(e, d, frame.offset));
    result.negativeRatio =
        area(subtract(packing.container, unite(result.calibrated.elements, frame.clip), frame.clip)) /
        frame.containerArea;
  };

  // The ratio falls monotonically with d: shrinking by half the widest element empties the
  // container, growing by its bounding square's diagonal fills it.
  double widest = 0.0;
  for (const Region& e : packing.elements) {
    const Box b = bounds(e);
    widest = std::max({widest, b.width(), b.height()});
  }
  double lo = -0.5 * widest - frame.side * 1e-6, hi = 1.5 * frame.side;
  apply(0.0);
  for (int iteration = 0; iteration < 200; ++iteration) {
    if (std::abs(result.negativeRatio - targetNegativeRatio) <= tolerance) return result;
    (result.negativeRatio > targetNegativeRatio ? lo : hi) = result.offset;
    apply(0.5 * (lo + hi));
  }
  if (std::abs(result.negativeRatio - targetNegativeRatio) > tolerance)
    throw InputError(packing.source, "calibration did not reach negative-space ratio " +
                                         std::to_string(targetNegativeRatio));
  return result;
}

}  // namespace pak
