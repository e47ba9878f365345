// Keyframe tracks: a cubic Hermite curve through the keys whose tangent at each key is the
// finite difference of its two neighbours over their time difference,
//   mᵢ = (pᵢ₊₁ − pᵢ₋₁) / (tᵢ₊₁ − tᵢ₋₁),
// i.e. Catmull–Rom generalised to non-uniform key times. Why this form: it passes through
// every key, reproduces keys lying on a line in (t, value) exactly (every tangent is then the
// line's slope), and, since tangents are real slopes per unit t, uneven key spacing does not
// make the curve overshoot the way the uniform-parameter formula does.
// Ends of an open track use the one-sided difference to their single neighbour.
//
// Periodic tracks: t = 0 and t = 1 are the same moment. When keys sit at both ends (the
// usual loop), the neighbour before the first key is the second-to-last key one period
// earlier and the neighbour after the last key is the second key one period later, both
// offset by Δ = p_last − p_first so that a track that keeps going (a rotation 0° → 72° of a
// five-fold star) continues with the same slope; both end tangents are then one and the same
// and the loop is C1 at the seam. When the keys do not reach both ends, the track wraps: after
// the last key it runs on to the first key one period later.
#include "pak/animation/keyframes.hpp"

#include <algorithm>
#include <cassert>
#include <vector>

namespace pak {
namespace {

// Keys at both ends closer than this to 0 and 1 make a track "span" the loop.
constexpr double kEndTolerance = 1e-9;

template <class V>
struct Key {
  double t;
  V value;
};

template <class V>
V hermite(const Key<V>& a, V ma, const Key<V>& b, V mb, double t) {
  const double h = b.t - a.t;
  if (h <= 0.0) return t < b.t ? a.value : b.value;
  const double s = (t - a.t) / h, s2 = s * s, s3 = s2 * s;
  const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s;
  const double h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
  return a.value * h00 + ma * (h10 * h) + b.value * h01 + mb * (h11 * h);
}

template <class V>
V slope(const Key<V>& a, const Key<V>& b) {
  const double dt = b.t - a.t;
  return dt > 0.0 ? (b.value - a.value) / dt : a.value * 0.0;
}

// The keys get a virtual neighbour on each side (one period away for periodic tracks) so
// every real key has a central-difference tangent.
template <class V>
V sample(const std::vector<Key<V>>& keys, double t, V fallback, bool periodic) {
  const std::size_t n = keys.size();
  if (n == 0) return fallback;
  if (n == 1) return keys.front().value;

  std::vector<Key<V>> ext;  // ext[0] and ext[n+1] are the virtual neighbours
  ext.reserve(n + 2);
  const bool spans = keys.front().t <= kEndTolerance && keys.back().t >= 1.0 - kEndTolerance;
  if (periodic && spans) {
    const V delta = keys.back().value - keys.front().value;
    ext.push_back({keys[n - 2].t - 1.0, keys[n - 2].value - delta});
    ext.insert(ext.end(), keys.begin(), keys.end());
    ext.push_back({keys[1].t + 1.0, keys[1].value + delta});
  } else if (periodic) {
    ext.push_back({keys[n - 1].t - 1.0, keys[n - 1].value});
    ext.insert(ext.end(), keys.begin(), keys.end());
    ext.push_back({keys[0].t + 1.0, keys[0].value});
  } else {
    // Each end its own neighbour: the difference there is the one-sided one.
    ext.push_back(keys[0]);
    ext.insert(ext.end(), keys.begin(), keys.end());
    ext.push_back(keys[n - 1]);
  }
  auto tangent = [&](std::size_t i) { return slope(ext[i - 1], ext[i + 1]); };

  if (periodic && !spans) {
    // Bring t into [first key, first key + 1): the stretch after the last key wraps.
    if (t < keys.front().t) t += 1.0;
    if (t > keys.back().t) {
      // Between the last key and the first key one period later; its tangent is the first's.
      Key<V> wrapped = ext[n + 1];
      return hermite(ext[n], tangent(n), wrapped, tangent(1), std::min(t, wrapped.t));
    }
  }
  if (t <= keys.front().t) return keys.front().value;
  if (t >= keys.back().t) return keys.back().value;
  // The segment [keys[i], keys[i+1]] holding t: ext index i+1.
  const auto upper = std::upper_bound(keys.begin(), keys.end(), t, [](double v, const Key<V>& k) { return v < k.t; });
  const std::size_t i = static_cast<std::size_t>(upper - keys.begin()) - 1;
  return hermite(ext[i + 1], tangent(i + 1), ext[i + 2], tangent(i + 2), t);
}

}  // namespace

double sampleTrack(const std::vector<ScalarKey>& keys, double t, double fallback, bool periodic) {
  std::vector<Key<double>> converted;
  converted.reserve(keys.size());
  for (const ScalarKey& key : keys) converted.push_back({key.t, key.value});
  return sample(converted, t, fallback, periodic);
}

Vec2 sampleTrack(const std::vector<PointKey>& keys, double t, Vec2 fallback, bool periodic) {
  std::vector<Key<Vec2>> converted;
  converted.reserve(keys.size());
  for (const PointKey& key : keys) converted.push_back({key.t, key.value});
  return sample(converted, t, fallback, periodic);
}

}  // namespace pak
