// Algorithm 1 of the thesis (after Jobard & Lefer): streamlines grown from a sorted seed list,
// each stopping at s_max, near another streamline, at the container's edge or at a fixed
// element; accepted ones (≥ s_min) seed new candidates s_gap to either side.
#include "flow/streamlines.hpp"

#include <algorithm>
#include <cmath>
#include <queue>

#include "pak/error.hpp"
#include "pak/geom/closest_point.hpp"
#include "pak/geom/resample.hpp"
#include "pak/geom/rng.hpp"
#include "sim/region_index.hpp"

namespace pak {
namespace {

// Points of accepted streamlines in square cells of side s_stop, so "is any streamline within
// s_stop of p" looks at 3 × 3 cells.
class StreamlinePoints {
 public:
  StreamlinePoints(const Box& area, double cell) : origin_(area.min), cell_(cell) {
    nx_ = std::max(1, static_cast<int>(std::ceil(area.width() / cell)) + 1);
    ny_ = std::max(1, static_cast<int>(std::ceil(area.height() / cell)) + 1);
    cells_.resize(static_cast<std::size_t>(nx_) * ny_);
  }
  void add(Vec2 p) { cells_[cellOf(p)].push_back(p); }
  bool near(Vec2 p, double d) const {
    const int ci = column(p.x), cj = row(p.y);
    const double d2 = d * d;
    for (int j = std::max(0, cj - 1); j <= std::min(ny_ - 1, cj + 1); ++j)
      for (int i = std::max(0, ci - 1); i <= std::min(nx_ - 1, ci + 1); ++i)
        for (Vec2 q : cells_[static_cast<std::size_t>(j) * nx_ + i])
          if (lengthSquared(q - p) < d2) return true;
    return false;
  }

 private:
  int column(double x) const { return std::clamp(static_cast<int>((x - origin_.x) / cell_), 0, nx_ - 1); }
  int row(double y) const { return std::clamp(static_cast<int>((y - origin_.y) / cell_), 0, ny_ - 1); }
  std::size_t cellOf(Vec2 p) const { return static_cast<std::size_t>(row(p.y)) * nx_ + column(p.x); }
  Vec2 origin_;
  double cell_;
  int nx_ = 1, ny_ = 1;
  std::vector<std::vector<Vec2>> cells_;
};

struct Seed {
  Vec2 p;
  double distance;      // from the boundary and guides: Sort(P)'s key
  std::uint64_t order;  // random: breaks ties in distance randomly, as the thesis asks
  bool operator>(const Seed& o) const { return distance != o.distance ? distance > o.distance : order > o.order; }
};

}  // namespace

std::vector<Polyline> traceStreamlines(const VectorField& field, const StreamlineInput& input,
                                       const StreamlineOptions& options) {
  const double gap = options.gap, stop = options.stopRatio * options.gap;
  const double step = options.step > 0.0 ? options.step : 0.5 * options.sampleSpacing;
  if (!(gap > 0.0) || !(stop > 0.0) || !(options.sampleSpacing > 0.0) || !(step > 0.0) ||
      !(options.minLength >= 0.0) || !(options.maxLength >= options.minLength))
    throw InputError("", "streamline options must be positive with s_min ≤ s_max");
  if (input.container.empty()) return {};

  const Box box = bounds(input.container);
  const double indexCell = std::max(4.0 * options.sampleSpacing, std::max(box.width(), box.height()) / 256.0);
  const RegionIndex container(input.container, indexCell);
  const RegionIndex obstacles = input.obstacles.empty() ? RegionIndex{} : RegionIndex(input.obstacles, indexCell);
  auto free = [&](Vec2 p) {
    return container.query(p, false).inside && (obstacles.empty() || !obstacles.query(p, false).inside);
  };
  // Sort(P)'s distance: to the container's boundary or the nearest guide.
  auto seedDistance = [&](Vec2 p) {
    double d = container.query(p, true).distance;
    for (const Polyline& g : input.guides) d = std::min(d, closestPointOnPolyline(p, g).distance);
    return d;
  };

  Rng rng(options.seed);
  std::priority_queue<Seed, std::vector<Seed>, std::greater<Seed>> seeds;
  // Boundary seeds sit a little inside, where the inside test is unambiguous (outer rings are
  // counter-clockwise and holes clockwise, so the interior is on the left of each).
  auto addRing = [&](const Ring& ring) {
    Ring samples = resampleRing(ring, options.sampleSpacing);
    for (std::size_t k = 0; k < samples.size(); ++k) {
      Vec2 t = normalized(samples[(k + 1) % samples.size()] - samples[(k + samples.size() - 1) % samples.size()]);
      Vec2 p = samples[k] + perp(t) * (0.5 * options.sampleSpacing);
      if (free(p)) seeds.push({p, 0.0, rng.next()});
    }
  };
  for (const Polygon& polygon : input.container) {
    addRing(polygon.outer);
    for (const Ring& hole : polygon.holes) addRing(hole);
  }
  for (const Polyline& g : input.guides) {
    if (g.size() < 2) continue;
    for (Vec2 p : resamplePolyline(g, options.sampleSpacing))
      if (free(p)) seeds.push({p, 0.0, rng.next()});
  }

  StreamlinePoints taken(box, stop);
  for (const Polyline& fixed : input.fixedStreamlines)
    if (fixed.size() >= 2)
      for (Vec2 p : resamplePolyline(fixed, step)) taken.add(p);

  // Follows the field from `start` in the direction of `sign` until a stopping rule of
  // Algorithm 1 holds or `budget` of length is used; returns the points after `start`.
  const double selfWindow = 2.0 * gap;  // own points this far back along the curve may not be approached
  auto trace = [&](Vec2 start, double sign, double budget, const Polyline& before) {
    Polyline points;
    Vec2 p = start;
    double length = 0.0;
    std::vector<double> arclength;  // of `points`
    while (true) {
      Vec2 q = field.advance(p, sign * step);
      const double segment = distance(p, q);
      if (!(segment > 0.25 * step) || length + segment > budget) break;
      if (!free(q) || taken.near(q, stop)) break;
      // A curve closing on itself (a vortex) stops before it meets its own earlier part.
      bool closing = false;
      for (std::size_t k = 0; k < points.size() && !closing; ++k)
        closing = length + segment - arclength[k] > selfWindow && lengthSquared(points[k] - q) < stop * stop;
      for (std::size_t k = 0; k < before.size() && !closing; ++k)
        closing = lengthSquared(before[k] - q) < stop * stop && distance(before[k], start) > 0.5 * stop;
      if (closing) break;
      length += segment;
      points.push_back(q);
      arclength.push_back(length);
      p = q;
    }
    return points;
  };

  std::vector<Polyline> result;
  while (!seeds.empty()) {
    Seed seed = seeds.top();
    seeds.pop();
    if (!free(seed.p) || taken.near(seed.p, stop)) continue;
    Polyline forward = trace(seed.p, 1.0, options.maxLength, {});
    const double forwardLength = polylineLength(forward) + (forward.empty() ? 0.0 : distance(seed.p, forward.front()));
    Polyline backward = trace(seed.p, -1.0, options.maxLength - forwardLength, forward);
    Polyline line(backward.rbegin(), backward.rend());
    line.push_back(seed.p);
    line.insert(line.end(), forward.begin(), forward.end());
    if (line.size() < 2 || polylineLength(line) < options.minLength) continue;
    for (Vec2 p : line) taken.add(p);
    // New candidates s_gap to either side.
    Polyline samples = resamplePolyline(line, options.sampleSpacing);
    for (std::size_t k = 0; k < samples.size(); ++k) {
      Vec2 t = normalized(samples[std::min(k + 1, samples.size() - 1)] - samples[k == 0 ? 0 : k - 1]);
      for (double side : {1.0, -1.0}) {
        Vec2 c = samples[k] + perp(t) * (side * gap);
        if (free(c) && !taken.near(c, stop)) seeds.push({c, seedDistance(c), rng.next()});
      }
    }
    result.push_back(std::move(line));
  }
  return result;
}

}  // namespace pak
