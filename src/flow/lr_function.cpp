// LR functions and their matching (thesis 3.3.2, 3.3.4, 3.3.5 eq. 3.1).
#include "pak/flow/lr_function.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "flow/arclength_frame.hpp"
#include "pak/error.hpp"

namespace pak {

namespace {

// Raw extents -> maxima and the [0, 1] range the thesis matches.
void normalise(LRFunction& f) {
  f.maxLeft = f.left.empty() ? 0.0 : *std::max_element(f.left.begin(), f.left.end());
  f.maxRight = f.right.empty() ? 0.0 : *std::max_element(f.right.begin(), f.right.end());
  double scale = std::max(f.maxLeft, f.maxRight);
  double inverse = scale > 0.0 ? 1.0 / scale : 0.0;
  f.normalisedLeft.resize(f.left.size());
  f.normalisedRight.resize(f.right.size());
  for (std::size_t i = 0; i < f.left.size(); ++i) f.normalisedLeft[i] = f.left[i] * inverse;
  for (std::size_t i = 0; i < f.right.size(); ++i) f.normalisedRight[i] = f.right[i] * inverse;
}

void checkSamples(int samples, const char* where) {
  if (samples < 1) throw InputError(where, "the number of samples must be at least 1, got " + std::to_string(samples));
}

// Where the line through `origin` along the unit `direction` first meets the region's
// boundary on either side, in one pass over the edges. Crossings on the forward side also
// give the even-odd inside test (the same half-open rule as pointInRing), so a point outside
// the region has no extents.
struct LineHits {
  double forward = 0.0, backward = 0.0;
};
LineHits boundaryAlongLine(Vec2 origin, Vec2 direction, const Region& region) {
  double forward = std::numeric_limits<double>::infinity(), backward = forward;
  int forwardCrossings = 0;
  auto scan = [&](const Ring& ring) {
    for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
      Vec2 a = ring[j], b = ring[i];
      double sa = cross(direction, a - origin), sb = cross(direction, b - origin);
      if ((sa > 0.0) == (sb > 0.0)) continue;  // the edge stays on one side of the line
      Vec2 x = a + (sa / (sa - sb)) * (b - a);
      double t = dot(x - origin, direction);
      if (t > 0.0) {
        ++forwardCrossings;
        forward = std::min(forward, t);
      } else if (t < 0.0) {
        backward = std::min(backward, -t);
      }
    }
  };
  for (const Polygon& polygon : region) {
    if (polygon.outer.size() >= 3) scan(polygon.outer);
    for (const Ring& hole : polygon.holes)
      if (hole.size() >= 3) scan(hole);
  }
  if (forwardCrossings % 2 == 0 || !std::isfinite(forward) || !std::isfinite(backward)) return {};
  return {forward, backward};
}

// Value at fraction x in [0, 1] of a function sampled at (i + 0.5) / n, linear in between.
double sampleAt(const std::vector<double>& f, double x) {
  const int n = static_cast<int>(f.size());
  double position = std::clamp(x * n - 0.5, 0.0, static_cast<double>(n - 1));
  int i = std::min(static_cast<int>(position), n - 1);
  if (i == n - 1) return f[i];
  double t = position - i;
  return (1.0 - t) * f[i] + t * f[i + 1];
}

double squaredDistance(const std::vector<double>& element, const std::vector<double>& blob) {
  double sum = 0.0;
  const std::size_t n = blob.size();
  for (std::size_t i = 0; i < n; ++i) {
    double a = element.size() == n ? element[i] : sampleAt(element, (i + 0.5) / static_cast<double>(n));
    sum += (a - blob[i]) * (a - blob[i]);
  }
  return sum;
}

}  // namespace

LRFunction elementLRFunction(const Region& outline, Vec2 spineStart, Vec2 spineEnd, int samples) {
  const char* where = "elementLRFunction";
  checkSamples(samples, where);
  if (!(distance(spineStart, spineEnd) > 0.0) || !std::isfinite(distance(spineStart, spineEnd)))
    throw InputError(where, "the spine's two ends must be distinct finite points");
  const Vec2 axis = normalized(spineEnd - spineStart), normal = perp(axis);

  // Every ring in (along, across) coordinates relative to the spine.
  std::vector<std::vector<Vec2>> rings;
  double alongMin = std::numeric_limits<double>::infinity(), alongMax = -alongMin;
  auto add = [&](const Ring& ring) {
    if (ring.empty()) return;
    std::vector<Vec2>& local = rings.emplace_back();
    for (Vec2 p : ring) {
      Vec2 q{dot(p - spineStart, axis), dot(p - spineStart, normal)};
      if (!std::isfinite(q.x) || !std::isfinite(q.y)) throw InputError(where, "the outline has a non-finite point");
      local.push_back(q);
      alongMin = std::min(alongMin, q.x);
      alongMax = std::max(alongMax, q.x);
    }
  };
  for (const Polygon& polygon : outline) {
    add(polygon.outer);
    for (const Ring& hole : polygon.holes) add(hole);
  }
  if (rings.empty()) throw InputError(where, "the outline is empty");

  LRFunction f;
  f.length = alongMax - alongMin;
  f.left.assign(samples, 0.0);
  f.right.assign(samples, 0.0);
  const double step = f.length / samples;
  auto record = [&](int i, double across) {
    if (across > 0.0) f.left[i] = std::max(f.left[i], across);
    else f.right[i] = std::max(f.right[i], -across);
  };
  if (step > 0.0) {
    // Each edge meets the perpendicular lines of the samples whose position it spans
    // (half-open, so a line through a vertex counts it once per side of the vertex).
    for (const std::vector<Vec2>& ring : rings) {
      for (std::size_t k = 0, j = ring.size() - 1; k < ring.size(); j = k++) {
        Vec2 a = ring[j], b = ring[k];
        double lo = std::min(a.x, b.x), hi = std::max(a.x, b.x);
        int first = std::max(0, static_cast<int>(std::ceil((lo - alongMin) / step - 0.5)) - 1);
        int last = std::min(samples - 1, static_cast<int>(std::floor((hi - alongMin) / step - 0.5)) + 1);
        for (int i = first; i <= last; ++i) {
          double position = alongMin + (i + 0.5) * step;
          if (a.x == b.x) {  // on a sample line: both ends are extents there
            if (position == a.x) { record(i, a.y); record(i, b.y); }
            continue;
          }
          if (!(position >= lo && position < hi)) continue;
          record(i, a.y + (position - a.x) / (b.x - a.x) * (b.y - a.y));
        }
      }
    }
  } else {
    // Degenerate: the outline is a segment perpendicular to the spine.
    for (const std::vector<Vec2>& ring : rings)
      for (Vec2 q : ring)
        for (int i = 0; i < samples; ++i) record(i, q.y);
  }
  normalise(f);
  return f;
}

LRFunction blobLRFunction(const Region& blob, const Polyline& streamline, int samples) {
  const char* where = "blobLRFunction";
  checkSamples(samples, where);
  flow_detail::ArclengthFrame frame(streamline, where);
  LRFunction f;
  f.length = frame.length();
  f.left.assign(samples, 0.0);
  f.right.assign(samples, 0.0);
  for (int i = 0; i < samples; ++i) {
    auto sample = frame.at((i + 0.5) / samples * frame.length());
    LineHits hits = boundaryAlongLine(sample.point, sample.normal, blob);
    f.left[i] = hits.forward;
    f.right[i] = hits.backward;
  }
  normalise(f);
  return f;
}

LRFunction reflected(const LRFunction& function, Reflection reflection) {
  LRFunction f = function;
  if (reflection == Reflection::AcrossSpine || reflection == Reflection::Both) {
    std::swap(f.left, f.right);
    std::swap(f.normalisedLeft, f.normalisedRight);
    std::swap(f.maxLeft, f.maxRight);
  }
  if (reflection == Reflection::AlongSpine || reflection == Reflection::Both) {
    for (auto* v : {&f.left, &f.right, &f.normalisedLeft, &f.normalisedRight}) std::reverse(v->begin(), v->end());
  }
  return f;
}

double matchCost(const LRFunction& element, Reflection reflection, const LRFunction& blob) {
  if (element.normalisedLeft.empty() || element.normalisedRight.empty())
    throw InputError("matchCost", "the element's LR function has no samples");
  LRFunction alpha = reflected(element, reflection);
  // Eq. 3.1: sum over the samples of the squared differences, left and right.
  return squaredDistance(alpha.normalisedLeft, blob.normalisedLeft) +
         squaredDistance(alpha.normalisedRight, blob.normalisedRight);
}

LRMatch bestMatch(const std::vector<LRFunction>& candidates, const LRFunction& blob) {
  LRMatch best;
  best.cost = std::numeric_limits<double>::infinity();
  const Reflection all[] = {Reflection::None, Reflection::AcrossSpine, Reflection::AlongSpine, Reflection::Both};
  for (std::size_t c = 0; c < candidates.size(); ++c)
    for (Reflection r : all) {
      double cost = matchCost(candidates[c], r, blob);
      if (cost < best.cost) best = {static_cast<int>(c), r, cost};
    }
  if (best.candidate < 0) best.cost = 0.0;
  return best;
}

}  // namespace pak
