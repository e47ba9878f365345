// Even-odd scanline fill of cell centres, limited to the rows the region spans so that many
// small elements painted one by one cost what their own rows cost.
#include "metrics/cell_raster.hpp"

#include <algorithm>
#include <cmath>

namespace pak::metrics_internal {

void paintRegion(const Region& region, const CellGrid& grid, std::vector<std::uint8_t>& mask,
                 std::uint8_t value) {
  const Box box = bounds(region);
  if (box.empty() || grid.n <= 0) return;
  const int n = grid.n;
  auto firstCentreAtOrAbove = [&](double v, double origin) {
    return static_cast<int>(std::ceil((v - origin) / grid.cell - 0.5));
  };
  const int rowBegin = std::max(0, firstCentreAtOrAbove(box.min.y, grid.origin.y));
  const int rowEnd = std::min(n, firstCentreAtOrAbove(box.max.y, grid.origin.y) + 1);
  if (rowBegin >= rowEnd) return;
  std::vector<std::vector<double>> crossings(static_cast<std::size_t>(rowEnd - rowBegin));
  auto addRing = [&](const Ring& ring) {
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const Vec2 a = ring[k], b = ring[(k + 1) % ring.size()];
      if (a.y == b.y) continue;
      const double lo = std::min(a.y, b.y), hi = std::max(a.y, b.y);
      // Rows whose centre y is in [lo, hi): half-open so shared vertices count once.
      for (int j = std::max(rowBegin, firstCentreAtOrAbove(lo, grid.origin.y)); j < rowEnd; ++j) {
        const double y = grid.origin.y + (j + 0.5) * grid.cell;
        if (y >= hi) break;
        if (y < lo) continue;
        crossings[j - rowBegin].push_back(a.x + (y - a.y) / (b.y - a.y) * (b.x - a.x));
      }
    }
  };
  for (const Polygon& p : region) {
    addRing(p.outer);
    for (const Ring& h : p.holes) addRing(h);
  }
  for (int j = rowBegin; j < rowEnd; ++j) {
    std::vector<double>& xs = crossings[j - rowBegin];
    std::sort(xs.begin(), xs.end());
    for (std::size_t k = 0; k + 1 < xs.size(); k += 2) {
      // Cells whose centre x is in [xs[k], xs[k+1]).
      const int i0 = std::max(0, firstCentreAtOrAbove(xs[k], grid.origin.x));
      const int i1 = std::min(n, firstCentreAtOrAbove(xs[k + 1], grid.origin.x));
      for (int i = i0; i < i1; ++i) mask[static_cast<std::size_t>(j) * n + i] = value;
    }
  }
}

}  // namespace pak::metrics_internal
