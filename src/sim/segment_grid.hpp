#pragma once
// A uniform grid over moving segments, rebuilt every simulation step. Storage is sized once
// (`configure`), so a rebuild allocates nothing unless segments stretch far beyond a cell.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "pak/geom/box.hpp"
#include "pak/geom/vec2.hpp"

namespace pak {

class SegmentGrid {
 public:
  // Cells of side `cellSize` covering `area`; points outside are clamped to the border cells.
  void configure(const Box& area, double cellSize, std::size_t expectedSegments);
  // Segment s runs from positions[ends[2s]] to positions[ends[2s+1]].
  void rebuild(const Vec2* positions, const int* ends, std::size_t segmentCount);

  // Calls visit(segmentIndex) once for every segment registered in the (2r+1)² cells around p,
  // in the order the cells are scanned (rows, then columns).
  template <class Visit>
  void forEachNear(Vec2 p, int r, Visit&& visit) const {
    int ci = cellX(p.x), cj = cellY(p.y);
    int i0 = std::max(0, ci - r), i1 = std::min(nx_ - 1, ci + r);
    int j0 = std::max(0, cj - r), j1 = std::min(ny_ - 1, cj + r);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        int c = j * nx_ + i;
        for (int k = cellStart_[c]; k < cellStart_[c + 1]; ++k) {
          const Entry& e = entries_[k];
          // A segment spanning several cells is visited in the first of them the scan meets.
          if (std::max(e.firstI, i0) == i && std::max(e.firstJ, j0) == j) visit(e.segment);
        }
      }
  }

  double cellSize() const { return cell_; }
  int cellX(double x) const { return std::clamp(static_cast<int>((x - origin_.x) * inverseCell_), 0, nx_ - 1); }
  int cellY(double y) const { return std::clamp(static_cast<int>((y - origin_.y) * inverseCell_), 0, ny_ - 1); }

 private:
  Vec2 origin_;
  double cell_ = 1.0, inverseCell_ = 1.0;
  int nx_ = 1, ny_ = 1;
  std::vector<int> cellStart_;  // CSR offsets, size nx*ny + 1
  std::vector<int> cellFill_;   // per-cell write cursor during rebuild
  struct Entry {
    int segment;
    int firstI, firstJ;  // the lowest cell column and row the segment is registered in
  };
  std::vector<Entry> entries_;  // segments grouped by cell
};

}  // namespace pak
