// Flood fill of the background, one component at a time, with an explicit stack: a component
// is a hole when no cell of it lies on the border.
#include "metrics/small_holes.hpp"

#include <cstddef>

namespace pak::metrics_internal {

long long fillSmallHoles(std::vector<std::uint8_t>& mask, int n, double maxCells, std::uint8_t fill) {
  const std::size_t cells = static_cast<std::size_t>(n) * n;
  std::vector<std::uint8_t> seen(cells, 0);
  std::vector<int> stack, component;
  long long filled = 0;
  for (std::size_t start = 0; start < cells; ++start) {
    if (mask[start] || seen[start]) continue;
    component.clear();
    bool reachesBorder = false;
    seen[start] = 1;
    stack.push_back(static_cast<int>(start));
    while (!stack.empty()) {
      const int k = stack.back();
      stack.pop_back();
      component.push_back(k);
      const int i = k % n, j = k / n;
      if (i == 0 || j == 0 || i == n - 1 || j == n - 1) reachesBorder = true;
      auto visit = [&](int di, int dj) {
        const int a = i + di, b = j + dj;
        if (a < 0 || b < 0 || a >= n || b >= n) return;
        const std::size_t m = static_cast<std::size_t>(b) * n + a;
        if (mask[m] || seen[m]) return;
        seen[m] = 1;
        stack.push_back(static_cast<int>(m));
      };
      visit(1, 0);
      visit(-1, 0);
      visit(0, 1);
      visit(0, -1);
    }
    if (reachesBorder || static_cast<double>(component.size()) >= maxCells) continue;
    for (int k : component) mask[k] = fill;
    filled += static_cast<long long>(component.size());
  }
  return filled;
}

}  // namespace pak::metrics_internal
