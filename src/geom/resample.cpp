#include "pak/geom/resample.hpp"

#include <algorithm>
#include <cmath>

#include "pak/error.hpp"

namespace pak {
namespace {

void checkSpacing(double spacing) {
  if (!(spacing > 0.0) || !std::isfinite(spacing))
    throw InputError("", "resampling spacing must be a positive number");
}

void checkLength(double length) {
  if (!std::isfinite(length)) throw InputError("", "non-finite coordinate in a resampled path");
}

// Refuses spacings so small relative to the path that the points would exhaust memory.
void checkCount(double count) {
  if (count > 1e8) throw InputError("", "resampling spacing is too small for the path's length");
}

// Walks a chain of vertices (closed or not) emitting the points at increasing arclengths.
// `targets` must be sorted and within [0, total length].
std::vector<Vec2> pointsAtArclengths(const std::vector<Vec2>& vertices, bool closed,
                                     const std::vector<double>& targets) {
  std::vector<Vec2> out;
  out.reserve(targets.size());
  const std::size_t edges = closed ? vertices.size() : vertices.size() - 1;
  std::size_t edge = 0;
  double edgeStart = 0.0;  // arclength at the start of `edge`
  for (double s : targets) {
    for (;;) {
      const Vec2 a = vertices[edge], b = vertices[(edge + 1) % vertices.size()];
      const double len = distance(a, b);
      if (s <= edgeStart + len || edge + 1 == edges) {
        const double t = len > 0.0 ? std::clamp((s - edgeStart) / len, 0.0, 1.0) : 0.0;
        out.push_back(a + (b - a) * t);
        break;
      }
      edgeStart += len;
      ++edge;
    }
  }
  return out;
}

}  // namespace

Ring resampleRing(const Ring& ring, double spacing) {
  checkSpacing(spacing);
  const double length = perimeter(ring);
  checkLength(length);
  if (ring.size() < 2 || length <= 0.0) return {};
  const double count = std::max(3.0, std::round(length / spacing));
  checkCount(count);
  const std::size_t n = static_cast<std::size_t>(count);
  std::vector<double> targets(n);
  for (std::size_t k = 0; k < n; ++k) targets[k] = length * static_cast<double>(k) / count;
  return pointsAtArclengths(ring, true, targets);
}

Polyline resamplePolyline(const Polyline& line, double spacing) {
  checkSpacing(spacing);
  const double length = polylineLength(line);
  checkLength(length);
  if (line.empty()) return {};
  if (length <= 0.0) return {line.front()};
  // The relative slack keeps a length that is an exact multiple of the spacing from
  // gaining a segment through rounding.
  const double count = std::max(1.0, std::ceil(length / spacing * (1.0 - 1e-12)));
  checkCount(count);
  const std::size_t n = static_cast<std::size_t>(count);
  std::vector<double> targets(n + 1);
  for (std::size_t k = 0; k <= n; ++k) targets[k] = length * static_cast<double>(k) / count;
  Polyline out = pointsAtArclengths(line, false, targets);
  out.back() = line.back();
  return out;
}

Vec2 pointAtArclength(const Ring& ring, double s) {
  if (ring.empty()) return {};
  const double length = perimeter(ring);
  if (!(length > 0.0) || !std::isfinite(length) || !std::isfinite(s)) return ring.front();
  double wrapped = std::fmod(s, length);
  if (wrapped < 0.0) wrapped += length;
  return pointsAtArclengths(ring, true, {wrapped}).front();
}

}  // namespace pak
