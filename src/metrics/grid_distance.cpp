// The discrete distance transform of thesis 6.3.2: cell centres over the container's bounding
// square, occupied outside the container or inside an element, and an exact grid EDT.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "metrics/cell_raster.hpp"
#include "metrics/metrics_internal.hpp"
#include "pak/error.hpp"
#include "pak/geom/distance_field.hpp"

namespace pak::metrics_internal {
namespace {

std::vector<std::uint8_t> rasterize(const Region& region, Vec2 origin, double cell, int n) {
  std::vector<std::uint8_t> inside(static_cast<std::size_t>(n) * n, 0);
  paintRegion(region, CellGrid{origin, cell, n}, inside);
  return inside;
}

// Distance from each cell centre of the n × n grid at `origin` to the nearest occupied
// (non-free) centre, less half a cell, since the boundary lies about half a cell short of it;
// -1 for occupied cells.
std::vector<double> freeCellDistances(const Region& negative, Vec2 origin, double cell, int n) {
  const std::vector<std::uint8_t> free = rasterize(negative, origin, cell, n);
  std::vector<std::uint8_t> occupied(free.size());
  for (std::size_t k = 0; k < free.size(); ++k) occupied[k] = free[k] ? 0 : 1;
  std::vector<double> distance = euclideanDistanceTransform(occupied, n, n);
  for (std::size_t k = 0; k < free.size(); ++k) distance[k] = free[k] ? (distance[k] - 0.5) * cell : -1.0;
  return distance;
}

}  // namespace

GridDistances gridDistances(const PackingGeometry& packing, const Region& negative,
                            const Frame& frame, int resolution) {
  GridDistances out;
  out.cell = frame.side / resolution;
  // One ring of occupied cells around the square so a container edge on the square's border
  // still bounds the distances.
  const int n = resolution + 2;
  const Vec2 origin = frame.box.min - Vec2{out.cell, out.cell};
  const std::vector<std::uint8_t> inContainer = rasterize(packing.container, origin, out.cell, n);
  const std::vector<double> distance = freeCellDistances(negative, origin, out.cell, n);
  for (std::size_t k = 0; k < distance.size(); ++k) {
    out.containerCells += inContainer[k];
    if (distance[k] >= 0.0) out.freeDistances.push_back(distance[k]);
  }
  std::sort(out.freeDistances.begin(), out.freeDistances.end());
  return out;
}

}  // namespace pak::metrics_internal

namespace pak {

DistanceMap distanceMap(const PackingGeometry& packing, int resolution) {
  using namespace metrics_internal;
  if (resolution < 2 || resolution > 20000) throw InputError(packing.source, "distance map resolution must be 2 to 20000");
  const Frame frame = makeFrame(packing, 0.0);
  DistanceMap map;
  map.cell = frame.side / resolution;
  map.columns = std::max(1, static_cast<int>(std::ceil(frame.box.width() / map.cell)));
  map.rows = std::max(1, static_cast<int>(std::ceil(frame.box.height() / map.cell)));
  map.origin = frame.box.min;
  // The same padded square grid as gridDistances, cropped to the container's box.
  const int n = resolution + 2;
  const Vec2 origin = frame.box.min - Vec2{map.cell, map.cell};
  const std::vector<double> distance = freeCellDistances(negativeSpace(packing, frame), origin, map.cell, n);
  map.distance.resize(static_cast<std::size_t>(map.columns) * map.rows);
  for (int j = 0; j < map.rows; ++j)
    for (int i = 0; i < map.columns; ++i) {
      const double d = distance[static_cast<std::size_t>(j + 1) * n + (i + 1)];
      map.distance[static_cast<std::size_t>(j) * map.columns + i] = d;
      map.largest = std::max(map.largest, d);
    }
  return map;
}

}  // namespace pak
