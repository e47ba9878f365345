#include "sim/segment_grid.hpp"

#include <cmath>

namespace pak {

void SegmentGrid::configure(const Box& area, double cellSize, std::size_t expectedSegments) {
  cell_ = cellSize;
  inverseCell_ = 1.0 / cellSize;
  origin_ = area.min;
  nx_ = std::max(1, static_cast<int>(std::ceil(area.width() * inverseCell_)));
  ny_ = std::max(1, static_cast<int>(std::ceil(area.height() * inverseCell_)));
  cellStart_.assign(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
  cellFill_.assign(static_cast<std::size_t>(nx_) * ny_, 0);
  // Most skin segments are shorter than a cell and touch at most four cells.
  entries_.reserve(expectedSegments * 4);
}

void SegmentGrid::rebuild(const Vec2* positions, const int* ends, std::size_t segmentCount) {
  // Counting sort into cells: count, prefix sum, fill. Deterministic order within a cell.
  std::fill(cellStart_.begin(), cellStart_.end(), 0);
  auto cellRange = [&](std::size_t s, int& i0, int& i1, int& j0, int& j1) {
    Vec2 a = positions[ends[2 * s]], b = positions[ends[2 * s + 1]];
    i0 = cellX(std::min(a.x, b.x)); i1 = cellX(std::max(a.x, b.x));
    j0 = cellY(std::min(a.y, b.y)); j1 = cellY(std::max(a.y, b.y));
  };
  for (std::size_t s = 0; s < segmentCount; ++s) {
    int i0, i1, j0, j1;
    cellRange(s, i0, i1, j0, j1);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) ++cellStart_[j * nx_ + i + 1];
  }
  for (std::size_t c = 1; c < cellStart_.size(); ++c) cellStart_[c] += cellStart_[c - 1];
  entries_.resize(static_cast<std::size_t>(cellStart_.back()));
  std::copy(cellStart_.begin(), cellStart_.end() - 1, cellFill_.begin());
  for (std::size_t s = 0; s < segmentCount; ++s) {
    int i0, i1, j0, j1;
    cellRange(s, i0, i1, j0, j1);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) entries_[cellFill_[j * nx_ + i]++] = {static_cast<int>(s), i0, j0};
  }
}

}  // namespace pak
