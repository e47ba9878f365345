#pragma once
// Which cell centres of a square grid lie in a region: the rasterization every grid metric
// shares, so the distance map and the evenness measure see the same cells. Not installed.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "pak/geom/polygon.hpp"

namespace pak::metrics_internal {

// n × n cells of side `cell`, row-major from `origin`; cell (i, j) is centred at
// origin + ((i + 0.5) cell, (j + 0.5) cell).
struct CellGrid {
  Vec2 origin;
  double cell = 0.0;
  int n = 0;
  std::size_t cells() const { return static_cast<std::size_t>(n) * n; }
};

// Sets mask[k] = value for every cell whose centre lies in `region` (even-odd over all rings:
// Clipper's regions are disjoint polygons with holes, so parity is membership). Centres on
// an edge count on one side only (half-open rows and spans). Cells outside leave mask alone.
void paintRegion(const Region& region, const CellGrid& grid, std::vector<std::uint8_t>& mask,
                 std::uint8_t value = 1);

}  // namespace pak::metrics_internal
