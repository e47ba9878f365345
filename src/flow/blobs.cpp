// Sub-region blobs (thesis 3.3.4). The thesis builds an approximate generalized Voronoi
// diagram with a level-set front (Osher & Sethian); here the same front is a multi-source
// Dijkstra over a grid restricted to the free space, each cell keeping its nearest streamline
// point (vector propagation), so blobs follow the free space around holes and fixed elements.
#include "flow/blobs.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "pak/error.hpp"
#include "pak/geom/clipping.hpp"
#include "pak/geom/resample.hpp"
#include "sim/region_index.hpp"

namespace pak {
namespace {

Region cellRuns(const std::vector<int>& label, int which, int nx, int ny, Vec2 origin, double cell) {
  std::vector<Region> rows;
  for (int j = 0; j < ny; ++j) {
    int i = 0;
    while (i < nx) {
      if (label[static_cast<std::size_t>(j) * nx + i] != which) {
        ++i;
        continue;
      }
      int start = i;
      while (i < nx && label[static_cast<std::size_t>(j) * nx + i] == which) ++i;
      Vec2 a = origin + Vec2{start * cell, j * cell}, b = origin + Vec2{i * cell, (j + 1) * cell};
      rows.push_back(Region{Polygon{Ring{a, {b.x, a.y}, b, {a.x, b.y}}, {}}});
    }
  }
  return unite(rows);
}

}  // namespace

std::vector<Region> computeBlobs(const Region& freeSpace, const std::vector<Polyline>& streamlines,
                                 const BlobOptions& options) {
  if (options.resolution < 2 || options.resolution > 8192) throw InputError("", "the blob resolution must be 2 to 8192");
  std::vector<Region> blobs(streamlines.size());
  const Box box = bounds(freeSpace);
  if (streamlines.empty() || box.empty()) return blobs;
  const double cell = std::max(box.width(), box.height()) / options.resolution;
  const int nx = static_cast<int>(std::ceil(box.width() / cell)) + 1;
  const int ny = static_cast<int>(std::ceil(box.height() / cell)) + 1;
  const Vec2 origin = box.min;
  const std::size_t n = static_cast<std::size_t>(nx) * ny;
  auto centre = [&](int i, int j) { return origin + Vec2{(i + 0.5) * cell, (j + 0.5) * cell}; };

  const RegionIndex index(freeSpace, 4.0 * cell);
  std::vector<std::uint8_t> inside(n, 0);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) inside[static_cast<std::size_t>(j) * nx + i] = index.query(centre(i, j), false).inside;

  // Sources: the streamlines' points, sampled finer than a cell.
  std::vector<int> label(n, -1);
  std::vector<Vec2> nearest(n);
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  using Entry = std::pair<double, std::size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> front;
  for (std::size_t s = 0; s < streamlines.size(); ++s) {
    if (streamlines[s].size() < 2) continue;
    for (Vec2 p : resamplePolyline(streamlines[s], 0.5 * cell)) {
      const int i = std::clamp(static_cast<int>((p.x - origin.x) / cell), 0, nx - 1);
      const int j = std::clamp(static_cast<int>((p.y - origin.y) / cell), 0, ny - 1);
      const std::size_t c = static_cast<std::size_t>(j) * nx + i;
      if (!inside[c]) continue;
      const double d = distance(centre(i, j), p);
      if (d < dist[c]) {
        dist[c] = d;
        label[c] = static_cast<int>(s);
        nearest[c] = p;
        front.push({d, c});
      }
    }
  }
  // Each cell takes the source of whichever settled neighbour brings the nearest one.
  while (!front.empty()) {
    auto [d, c] = front.top();
    front.pop();
    if (d > dist[c]) continue;
    const int i = static_cast<int>(c % nx), j = static_cast<int>(c / nx);
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) {
        const int a = i + di, b = j + dj;
        if ((di == 0 && dj == 0) || a < 0 || b < 0 || a >= nx || b >= ny) continue;
        const std::size_t k = static_cast<std::size_t>(b) * nx + a;
        if (!inside[k]) continue;
        const double candidate = distance(centre(a, b), nearest[c]);
        if (candidate < dist[k]) {
          dist[k] = candidate;
          label[k] = label[c];
          nearest[k] = nearest[c];
          front.push({candidate, k});
        }
      }
  }
  // Cell runs per label, cut to the exact free space.
  for (std::size_t s = 0; s < streamlines.size(); ++s) {
    Region cells = cellRuns(label, static_cast<int>(s), nx, ny, origin, cell);
    if (!cells.empty()) blobs[s] = intersect(cells, freeSpace);
  }
  return blobs;
}

Polyline extendToBlob(const Polyline& streamline, const Region& blob, const VectorField& field, double step) {
  if (streamline.size() < 2 || blob.empty() || !(step > 0.0)) return streamline;
  const Box box = bounds(blob);
  const int maxSteps = static_cast<int>(2.0 * (box.width() + box.height()) / step) + 1;
  // Along the field at the end, against it at the start: the direction the curve runs there.
  auto grow = [&](Vec2 end, Vec2 tangent) {
    Polyline added;
    const double sign = dot(field.at(end), tangent) >= 0.0 ? 1.0 : -1.0;
    Vec2 p = end;
    for (int k = 0; k < maxSteps; ++k) {
      Vec2 q = field.advance(p, sign * step);
      if (!(distance(p, q) > 0.25 * step) || !pointInRegion(q, blob)) break;
      added.push_back(q);
      p = q;
    }
    return added;
  };
  const std::size_t n = streamline.size();
  Polyline head = grow(streamline.front(), streamline.front() - streamline[1]);
  Polyline tail = grow(streamline.back(), streamline.back() - streamline[n - 2]);
  Polyline out(head.rbegin(), head.rend());
  out.insert(out.end(), streamline.begin(), streamline.end());
  out.insert(out.end(), tail.begin(), tail.end());
  return out;
}

Region growBlob(const Region& blob, const Region& occupied, const Region& freeSpace, double limit) {
  if (blob.empty() || !(limit > 0.0)) return blob;
  OffsetOptions offsetOptions;
  offsetOptions.arcTolerance = std::max(1e-3, 0.05 * limit);
  Region grown = subtract(intersect(offset(blob, limit, offsetOptions), freeSpace), occupied);
  // Only the parts connected to the blob: growth does not jump across another element.
  Region kept;
  for (const Polygon& polygon : grown)
    if (area(intersect(Region{polygon}, blob)) > 0.0) kept.push_back(polygon);
  return kept;
}

}  // namespace pak
