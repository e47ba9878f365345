// Nearest occupied cell by the separable exact EDT: along each row the nearest occupied
// column, then down each column the lower envelope of the parabolas (i - column)² + (j - j')².
#include "metrics/nearest_occupied.hpp"

#include <algorithm>
#include <cassert>
#include <limits>

#include "metrics/metrics_internal.hpp"

namespace pak::metrics_internal {
namespace {

// Lines are handed to the cores in this many chunks: enough to balance two to a few dozen
// cores, few enough that dispatch costs nothing next to a chunk.
constexpr int kChunks = 32;

void inChunks(int lines, const std::function<void(int, int)>& body) {
  const int chunks = std::min(kChunks, std::max(lines, 1));
  parallelFor(chunks, [&](int c) {
    const int begin = static_cast<int>(static_cast<long long>(lines) * c / chunks);
    const int end = static_cast<int>(static_cast<long long>(lines) * (c + 1) / chunks);
    body(begin, end);
  });
}

}  // namespace

std::vector<int> nearestOccupiedCells(const std::vector<std::uint8_t>& occupied, int nx, int ny) {
  if (nx <= 0 || ny <= 0) return {};
  assert(occupied.size() == static_cast<std::size_t>(nx) * ny);
  auto at = [nx](int i, int j) { return static_cast<std::size_t>(j) * nx + i; };

  // Pass 1: the nearest occupied column in each cell's own row (-1: the row has none).
  std::vector<int> column(occupied.size(), -1);
  inChunks(ny, [&](int rowBegin, int rowEnd) {
    for (int j = rowBegin; j < rowEnd; ++j) {
      int last = -1;
      for (int i = 0; i < nx; ++i) {
        if (occupied[at(i, j)]) last = i;
        column[at(i, j)] = last;
      }
      last = -1;
      for (int i = nx - 1; i >= 0; --i) {
        if (occupied[at(i, j)]) last = i;
        const int left = column[at(i, j)];
        // The nearer of the two; the left one on a tie.
        if (last >= 0 && (left < 0 || last - i < i - left)) column[at(i, j)] = last;
      }
    }
  });

  // Pass 2: down each column, the row j' minimising (i - column(j'))² + (j - j')².
  std::vector<int> nearest(occupied.size(), -1);
  inChunks(nx, [&](int columnBegin, int columnEnd) {
    std::vector<int> sites(ny);                  // rows of the envelope's parabolas
    std::vector<double> bounds(ny + 1);          // where each parabola starts to be lowest
    std::vector<double> height(ny);              // (i - column)² of each row
    for (int i = columnBegin; i < columnEnd; ++i) {
      int k = -1;
      for (int q = 0; q < ny; ++q) {
        const int c = column[at(i, q)];
        if (c < 0) continue;
        height[q] = static_cast<double>(i - c) * (i - c);
        // Where parabola q meets parabola sites[k]; pop those it hides entirely.
        double s = -std::numeric_limits<double>::infinity();
        while (k >= 0) {
          const int v = sites[k];
          s = ((height[q] + static_cast<double>(q) * q) - (height[v] + static_cast<double>(v) * v)) /
              (2.0 * (q - v));
          if (s > bounds[k]) break;
          --k;
        }
        ++k;
        sites[k] = q;
        bounds[k] = k == 0 ? -std::numeric_limits<double>::infinity() : s;
      }
      if (k < 0) continue;  // nothing occupied within reach of this column
      bounds[k + 1] = std::numeric_limits<double>::infinity();
      int m = 0;
      for (int j = 0; j < ny; ++j) {
        while (bounds[m + 1] < j) ++m;
        const int row = sites[m];
        nearest[at(i, j)] = static_cast<int>(at(column[at(i, row)], row));
      }
    }
  });
  return nearest;
}

}  // namespace pak::metrics_internal
