#pragma once
// The feature transform of a binary grid: for every cell, which occupied cell is nearest.
// Not installed.
#include <cstdint>
#include <vector>

namespace pak::metrics_internal {

// For every cell of the nx × ny grid (row-major), the index of the nearest cell where
// `occupied` is set, in exact Euclidean distance between cell centres; -1 when none is.
// Felzenszwalb–Huttenlocher's two separable passes, keeping the minimising site instead of
// only its distance. Rows and then columns are spread over the cores; each line is computed
// alone, so the result does not depend on the number of threads. Among equally near cells
// the choice is fixed by the grid alone.
std::vector<int> nearestOccupiedCells(const std::vector<std::uint8_t>& occupied, int nx, int ny);

}  // namespace pak::metrics_internal
