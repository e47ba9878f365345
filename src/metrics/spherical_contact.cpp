// Spherical contact probability Q(r) (thesis 6.3.1): the negative space eroded by a disc of
// radius r, by an exact polygon offset, over the container area.
#include <algorithm>

#include "metrics/metrics_internal.hpp"

namespace pak {
namespace metrics_internal {

namespace {

// erode(C \ U E_i, r) = erode(C, r) \ U grow(E_i, r): small offsets are far cheaper than one
// offset of the whole negative space with all its self-intersections. With a `window` known
// to hold the whole answer, elements whose grown box misses it cannot touch the answer.
Region erodedRegion(const PackingGeometry& packing, double r, const Frame& frame,
                    const Box* window) {
  Region inner = offset(packing.container, -r, frame.offset);
  if (inner.empty()) return inner;
  std::vector<Region> grown;
  for (const Region& e : packing.elements) {
    Box b = bounds(e);
    b.min = b.min - Vec2{r, r};
    b.max = b.max + Vec2{r, r};
    if (!window || b.overlaps(*window)) grown.push_back(offset(e, r, frame.offset));
  }
  if (window) {
    const Vec2 lo = window->min, hi = window->max;
    inner = intersect(inner, Region{Polygon{{lo, {hi.x, lo.y}, hi, {lo.x, hi.y}}, {}}}, frame.clip);
  }
  return subtract(inner, unionOperand(std::move(grown), frame), frame.clip);
}

}  // namespace

double erodedRatio(const PackingGeometry& packing, const Region& negative, double r,
                   const Frame& frame) {
  if (r <= 0.0) return area(negative) / frame.containerArea;
  return area(erodedRegion(packing, r, frame, nullptr)) / frame.containerArea;
}

double largestEmptyRadius(const PackingGeometry& packing, const Region& negative,
                          const Frame& frame, double guess, double slack) {
  if (!(area(negative) > 0.0)) return 0.0;
  // No disc wider than the container's bounding square fits in it.
  double lo = 0.0, hi = frame.side * 0.5;
  Box window = frame.box;  // holds N(lo), hence N(r) for every r >= lo
  auto nonEmpty = [&](double r) {
    const Region eroded = erodedRegion(packing, r, frame, &window);
    if (!(area(eroded) > 0.0)) return false;
    window = bounds(eroded);
    return true;
  };
  // A bracket around the grid's answer saves most of the bisection when it holds.
  if (guess > 0.0 && slack > 0.0) {
    if (guess - slack > 0.0 && nonEmpty(guess - slack)) lo = guess - slack;
    if (guess + slack < hi) (nonEmpty(guess + slack) ? lo : hi) = guess + slack;
  }
  while (hi - lo > 1e-7 * hi) {
    const double mid = 0.5 * (lo + hi);
    (nonEmpty(mid) ? lo : hi) = mid;
  }
  return lo;
}

double gapFromCurve(const Curve& q) {
  if (q.value.empty()) return 0.0;
  const double half = 0.5 * q.value.front();
  for (std::size_t k = 1; k < q.value.size(); ++k)
    if (q.value[k] <= half) {
      // Linear between samples: exact for stripes, whose Q is linear.
      const double t = (q.value[k - 1] - half) / (q.value[k - 1] - q.value[k]);
      return 4.0 * (q.r[k - 1] + t * (q.r[k] - q.r[k - 1]));
    }
  return 4.0 * q.r.back();
}

Curve contactCurve(const PackingGeometry& packing, const Region& negative, const Frame& frame,
                   double largest, int count) {
  Curve q;
  q.r.resize(count);
  q.value.resize(count);
  for (int k = 0; k < count; ++k) q.r[k] = count > 1 ? largest * k / (count - 1) : 0.0;
  // N(r) shrinks as r grows, so N(r_k) = N(r_j) ∩ erode(C, r_k) \ U grow(E_i, r_k) for any
  // r_j < r_k, where only elements whose grown box meets a piece of N(r_j) take part: at
  // large r few pockets remain and few elements are offset. The radii are split into a fixed
  // number of interleaved chains (not one per thread), so the result is the same on any
  // number of cores.
  constexpr int kChains = 4;
  parallelFor(std::min(kChains, count), [&](int chain) {
    Region previous;
    bool havePrevious = false;
    for (int k = chain; k < count; k += kChains) {
      const double r = q.r[k];
      if (r <= 0.0 || (havePrevious && previous.empty())) {
        q.value[k] = r <= 0.0 ? area(negative) / frame.containerArea : 0.0;
        if (r <= 0.0) { previous = negative; havePrevious = true; }
        continue;
      }
      Region current;
      if (!havePrevious) {
        current = erodedRegion(packing, r, frame, nullptr);
      } else {
        std::vector<Box> pieces;
        for (const Polygon& p : previous) pieces.push_back(bounds(p.outer));
        std::vector<Region> grown;
        for (const Region& e : packing.elements) {
          Box b = bounds(e);
          b.min = b.min - Vec2{r, r};
          b.max = b.max + Vec2{r, r};
          if (std::any_of(pieces.begin(), pieces.end(), [&](const Box& piece) { return piece.overlaps(b); }))
            grown.push_back(offset(e, r, frame.offset));
        }
        Region inner = intersect(offset(packing.container, -r, frame.offset), previous, frame.clip);
        current = grown.empty() ? std::move(inner)
                                : subtract(inner, unionOperand(std::move(grown), frame), frame.clip);
      }
      q.value[k] = area(current) / frame.containerArea;
      previous = std::move(current);
      havePrevious = true;
    }
  });
  return q;
}

}  // namespace metrics_internal

double sphericalContact(const PackingGeometry& packing, double r, double arcTolerance) {
  using namespace metrics_internal;
  const Frame frame = makeFrame(packing, arcTolerance);
  return erodedRatio(simplifiedForOffsets(packing, frame), negativeSpace(packing, frame), r, frame);
}

double estimateGap(const PackingGeometry& packing) {
  using namespace metrics_internal;
  const Frame frame = makeFrame(packing, 0.0);
  const Region negative = negativeSpace(packing, frame);
  const PackingGeometry simplified = simplifiedForOffsets(packing, frame);
  const double largest = largestEmptyRadius(simplified, negative, frame);
  return gapFromCurve(contactCurve(simplified, negative, frame, largest, MetricsOptions{}.radii));
}

}  // namespace pak
