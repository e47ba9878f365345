#pragma once
// Filling the small holes of a raster shape (the eyes of an element's art). Not installed.
#include <cstdint>
#include <vector>

namespace pak::metrics_internal {

// In the n × n `mask`, every 4-connected component of 0 cells that does not reach the grid's
// border (a hole of the shape made of the non-zero cells) and has fewer than `maxCells` cells
// is set to `fill`. Returns how many cells were filled.
long long fillSmallHoles(std::vector<std::uint8_t>& mask, int n, double maxCells, std::uint8_t fill);

}  // namespace pak::metrics_internal
