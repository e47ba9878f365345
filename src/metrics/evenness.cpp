// The evenness measure: positive space rasterized with its small holes filled, the feature
// transform of the negative space, its medial axis, and the pocket shares built on h.
#include "pak/metrics/evenness.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "metrics/cell_raster.hpp"
#include "metrics/medial_axis.hpp"
#include "metrics/nearest_occupied.hpp"
#include "metrics/small_holes.hpp"
#include "pak/error.hpp"
#include "pak/limits.hpp"

namespace pak {
namespace {

using namespace metrics_internal;

// D > k h compares distances computed along different roundings; a hair of slack keeps
// cells exactly at k h (the centre row of an odd-width stripe) out on every platform.
constexpr double kTieSlack = 1e-9;

struct EvennessGrid {
  CellGrid grid;
  std::vector<EvennessCell> kind;
  std::vector<double> depth;  // D in cells on negative cells, 0 elsewhere
  std::vector<AxisCrossing> axis;
  Evenness summary;
};

void checkInput(const PackingGeometry& packing, const EvennessOptions& options) {
  if (options.resolution < 2 || options.resolution > limits::kMaxGridResolution)
    throw InputError("--grid", "must be 2 to " + std::to_string(limits::kMaxGridResolution));
  if (!(options.smallHoleArea >= 0.0) || !std::isfinite(options.smallHoleArea))
    throw InputError(packing.source, "small-hole area must be a non-negative fraction");
  if (packing.container.empty() || !(area(packing.container) > 0.0)) throw InputError(packing.source, "no container");
}

// The lowest radius at which the axis weight below reaches `fraction` of the total.
double weightedQuantile(const std::vector<AxisCrossing>& sorted, double total, double fraction) {
  double below = 0.0;
  for (const AxisCrossing& c : sorted) {
    below += c.weight;
    if (below >= fraction * total) return c.radius;
  }
  return sorted.empty() ? 0.0 : sorted.back().radius;
}

Evenness summarize(const EvennessGrid& g, int resolution) {
  Evenness e;
  e.resolution = resolution;
  e.cell = g.grid.cell;
  double largest = 0.0;
  for (std::size_t k = 0; k < g.kind.size(); ++k) {
    if (g.kind[k] == EvennessCell::Outside) continue;
    ++e.containerCells;
    if (g.kind[k] == EvennessCell::FilledHole) ++e.filledHoleCells;
    if (g.kind[k] != EvennessCell::Negative) continue;
    ++e.negativeCells;
    largest = std::max(largest, g.depth[k]);
  }
  e.negativeRatio = e.containerCells > 0 ? static_cast<double>(e.negativeCells) / e.containerCells : 0.0;
  e.largestEmptyRadius = largest * e.cell;

  std::vector<AxisCrossing> sorted = g.axis;
  std::sort(sorted.begin(), sorted.end(), [](const AxisCrossing& a, const AxisCrossing& b) {
    return a.radius < b.radius || (a.radius == b.radius && a.cell < b.cell);
  });
  double total = 0.0;
  for (const AxisCrossing& c : sorted) total += c.weight;
  e.axisLength = total * e.cell;
  const double h = weightedQuantile(sorted, total, 0.5);
  if (e.negativeCells == 0 || !(h > 0.0)) return e;

  e.halfWidth = h * e.cell;
  std::array<long long, 3> deeper{};
  for (std::size_t k = 0; k < g.kind.size(); ++k) {
    if (g.kind[k] != EvennessCell::Negative) continue;
    for (int m = 0; m < 3; ++m)
      if (g.depth[k] > (m + 1) * h + kTieSlack) ++deeper[m];
  }
  for (int m = 0; m < 3; ++m) e.pocketShare[m] = static_cast<double>(deeper[m]) / e.negativeCells;
  e.largestRadiusOverHalfWidth = largest / h;
  e.widthSpread = (weightedQuantile(sorted, total, 0.75) - weightedQuantile(sorted, total, 0.25)) / h;
  return e;
}

EvennessGrid measureOnGrid(const PackingGeometry& packing, const EvennessOptions& options) {
  checkInput(packing, options);
  EvennessGrid g;
  const Box box = bounds(packing.container);
  const int resolution = options.resolution;
  g.grid.cell = std::max(box.width(), box.height()) / resolution;
  // One ring of cells around the bounding square, always outside the container, so that the
  // wall bounds every distance and a hole never touches the border.
  g.grid.n = resolution + 2;
  g.grid.origin = box.min - Vec2{g.grid.cell, g.grid.cell};
  const std::size_t cells = g.grid.cells();

  std::vector<std::uint8_t> inContainer(cells, 0);
  paintRegion(packing.container, g.grid, inContainer);
  // Elements one by one: outlines may overlap, and painting them is cheaper than uniting them.
  constexpr std::uint8_t kPainted = 1, kFilled = 2;
  std::vector<std::uint8_t> positive(cells, 0);
  for (const Region& element : packing.elements) paintRegion(element, g.grid, positive, kPainted);
  paintRegion(packing.fixed, g.grid, positive, kPainted);
  const double holeCells = options.smallHoleArea * resolution * static_cast<double>(resolution);
  fillSmallHoles(positive, g.grid.n, holeCells, kFilled);

  g.kind.assign(cells, EvennessCell::Outside);
  std::vector<std::uint8_t> negative(cells, 0), occupied(cells, 1);
  for (std::size_t k = 0; k < cells; ++k) {
    if (!inContainer[k]) continue;
    g.kind[k] = positive[k] == kPainted  ? EvennessCell::Positive
                : positive[k] == kFilled ? EvennessCell::FilledHole
                                         : EvennessCell::Negative;
    negative[k] = g.kind[k] == EvennessCell::Negative;
    occupied[k] = !negative[k];
  }
  const std::vector<int> nearest = nearestOccupiedCells(occupied, g.grid.n, g.grid.n);
  g.depth.assign(cells, 0.0);
  for (std::size_t k = 0; k < cells; ++k) {
    if (!negative[k] || nearest[k] < 0) continue;
    const double di = static_cast<double>(nearest[k] % g.grid.n) - static_cast<double>(k % g.grid.n);
    const double dj = static_cast<double>(nearest[k] / g.grid.n) - static_cast<double>(k / g.grid.n);
    // Between cell centres; the boundary lies about half a cell short of the occupied centre
    // (exact for a wall along cell edges), as in the distance map.
    g.depth[k] = std::sqrt(di * di + dj * dj) - 0.5;
  }
  g.axis = medialAxisCrossings(negative, nearest, g.grid.n);
  g.summary = summarize(g, resolution);
  return g;
}

}  // namespace

Evenness measureEvenness(const PackingGeometry& packing, const EvennessOptions& options) {
  return measureOnGrid(packing, options).summary;
}

EvennessMap evennessMap(const PackingGeometry& packing, const EvennessOptions& options) {
  const EvennessGrid g = measureOnGrid(packing, options);
  EvennessMap map;
  map.evenness = g.summary;
  map.cell = g.grid.cell;
  const Box box = bounds(packing.container);
  map.origin = box.min;
  map.columns = std::clamp(static_cast<int>(std::ceil(box.width() / map.cell - 1e-9)), 1, options.resolution);
  map.rows = std::clamp(static_cast<int>(std::ceil(box.height() / map.cell - 1e-9)), 1, options.resolution);
  const std::size_t cells = static_cast<std::size_t>(map.columns) * map.rows;
  map.kind.resize(cells);
  map.distance.resize(cells);
  map.axis.assign(cells, 0);
  const int n = g.grid.n;
  auto cropped = [&](int k) -> long long {
    const int i = k % n - 1, j = k / n - 1;
    if (i < 0 || j < 0 || i >= map.columns || j >= map.rows) return -1;
    return static_cast<long long>(j) * map.columns + i;
  };
  for (int j = 0; j < map.rows; ++j)
    for (int i = 0; i < map.columns; ++i) {
      const std::size_t from = static_cast<std::size_t>(j + 1) * n + (i + 1);
      const std::size_t to = static_cast<std::size_t>(j) * map.columns + i;
      map.kind[to] = g.kind[from];
      map.distance[to] = g.depth[from] * map.cell;
    }
  for (const AxisCrossing& c : g.axis)
    if (const long long to = cropped(c.cell); to >= 0) map.axis[static_cast<std::size_t>(to)] = 1;
  return map;
}

}  // namespace pak
