// measurePacking: every quantity of thesis 6.3 for one packing, sharing one negative space.
#include <algorithm>
#include <cmath>

#include "metrics/metrics_internal.hpp"
#include "pak/error.hpp"
#include "pak/limits.hpp"

namespace pak {
namespace {

std::vector<double> evenly(double hi, int count) {
  std::vector<double> r(count);
  for (int k = 0; k < count; ++k) r[k] = count > 1 ? hi * k / (count - 1) : 0.0;
  return r;
}

// Each error names the option as `pak metrics` spells it; the bounds are pak/limits.hpp's.
void checkOptions(const MetricsOptions& o, double containerSide) {
  using namespace limits;
  if (o.radii < 2 || o.radii > kMaxRadii) throw InputError("--radii", "must be 2 to " + std::to_string(kMaxRadii));
  if (o.gridResolution < 2 || o.gridResolution > kMaxGridResolution)
    throw InputError("--grid", "must be 2 to " + std::to_string(kMaxGridResolution));
  if (o.histogramBins < 1 || o.histogramBins > kMaxHistogramBins)
    throw InputError("--bins", "must be 1 to " + std::to_string(kMaxHistogramBins));
  // A gap wider than the container measures nothing, and its offsets overflow.
  if (!(o.gap >= 0.0 && o.gap <= containerSide))
    throw InputError("--gap", "must be 0 (estimated) to the container's size, " + messageNumber(containerSide));
  if (!(o.overlapMaxRadius >= 0.0 && o.overlapMaxRadius <= containerSide))
    throw InputError("", "the overlap radius must be 0 to the container's size, " + messageNumber(containerSide));
}

// H(r) = -Q'(r): central differences inside, one-sided at the ends.
std::vector<double> negativeDerivative(const Curve& q) {
  const std::size_t n = q.r.size();
  std::vector<double> h(n, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t a = k > 0 ? k - 1 : k, b = k + 1 < n ? k + 1 : k;
    const double dr = q.r[b] - q.r[a];
    h[k] = dr > 0.0 ? -(q.value[b] - q.value[a]) / dr : 0.0;
  }
  return h;
}

}  // namespace

PackingMetrics measurePacking(const PackingGeometry& original, const MetricsOptions& options) {
  using namespace metrics_internal;
  const Frame frame = makeFrame(original, options.arcTolerance);
  checkOptions(options, frame.side);
  const Region negative = negativeSpace(original, frame);
  const PackingGeometry packing = simplifiedForOffsets(original, frame);

  PackingMetrics m;
  m.source = packing.source;
  m.containerArea = frame.containerArea;
  m.elementCount = static_cast<int>(packing.elements.size());
  m.negativeRatio = area(negative) / frame.containerArea;
  m.positiveRatio = 1.0 - m.negativeRatio;
  // The grid comes first: its largest distance brackets the exact bisection.
  const GridDistances grid = gridDistances(packing, negative, frame, options.gridResolution);
  const double gridLargest = grid.freeDistances.empty() ? 0.0 : grid.freeDistances.back();
  m.largestEmptyRadius = largestEmptyRadius(packing, negative, frame, gridLargest, 2.0 * grid.cell);

  m.sphericalContact =
      contactCurve(packing, negative, frame, m.largestEmptyRadius, options.radii);
  m.distanceHistogram.r = m.sphericalContact.r;
  m.distanceHistogram.value = negativeDerivative(m.sphericalContact);

  m.gapEstimated = !(options.gap > 0.0);
  m.gap = m.gapEstimated ? gapFromCurve(m.sphericalContact) : options.gap;

  const double overlapMax = options.overlapMaxRadius > 0.0 ? options.overlapMaxRadius : m.gap;
  const std::vector<ElementPair> pairs = nearPairs(packing, std::max(overlapMax, 0.5 * m.gap));
  m.overlap = overlapCurve(packing, pairs, frame, overlapMax, options.radii);

  const double cells = static_cast<double>(std::max<long long>(grid.containerCells, 1));
  const std::vector<double>& d = grid.freeDistances;
  m.gridSphericalContact.r = m.sphericalContact.r;
  for (double r : m.gridSphericalContact.r) {
    const auto atLeast = d.end() - std::lower_bound(d.begin(), d.end(), r);
    m.gridSphericalContact.value.push_back(static_cast<double>(atLeast) / cells);
  }
  const int bins = options.histogramBins;
  // A degenerate packing with no empty disc still gets a unit-free, non-empty range.
  const double top = m.largestEmptyRadius > 0.0 ? m.largestEmptyRadius : grid.cell;
  const double width = top / bins;
  m.binEdges = evenly(top, bins + 1);
  m.binDensity.assign(bins, 0.0);
  for (double v : d) m.binDensity[std::clamp(static_cast<int>(v / width), 0, bins - 1)] += 1.0;
  for (double& b : m.binDensity) b /= cells * width;

  m.contactAtHalfGap = erodedRatio(packing, negative, 0.5 * m.gap, frame);
  m.overlapAtHalfGap = overlapRatio(packing, pairs, 0.5 * m.gap, frame);
  return m;
}

}  // namespace pak
