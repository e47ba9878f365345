// The medial axis from the feature transform: neighbours whose nearest boundary cells are far
// apart and face each other (Hesselink and Roerdink's integer medial axis, pruned by angle).
#include "metrics/medial_axis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>

namespace pak::metrics_internal {
namespace {

constexpr double kMinSeparation = 3.0;   // cells between the two nearest boundary cells
constexpr double kMinAngle = 105.0 * std::numbers::pi / 180.0;

}  // namespace

std::vector<AxisCrossing> medialAxisCrossings(const std::vector<std::uint8_t>& inside,
                                              const std::vector<int>& nearest, int n) {
  std::vector<AxisCrossing> crossings;
  auto consider = [&](int p, int q, int pi, int pj, int di, int dj) {
    const int a = nearest[p], b = nearest[q];
    if (a == b || a < 0 || b < 0) return;
    const double ai = a % n, aj = a / n, bi = b % n, bj = b / n;
    const double dx = bi - ai, dy = bj - aj;
    const double separation2 = dx * dx + dy * dy;
    const double along = di * dx + dj * dy;  // (b - a) · (q - p)
    if (separation2 < kMinSeparation * kMinSeparation || along == 0.0) return;
    // x = p + t (q - p) on the bisector: |x - a|² = |x - b|².
    const double t = std::clamp(((bi * bi + bj * bj) - (ai * ai + aj * aj) - 2.0 * (pi * dx + pj * dy)) / (2.0 * along),
                                0.0, 1.0);
    const double xi = pi + t * di - ai, xj = pj + t * dj - aj;
    const double reach = std::sqrt(xi * xi + xj * xj), separation = std::sqrt(separation2);
    // |b - a| = 2 |x - a| sin(angle / 2) for an x on the bisector. a and b are cell centres,
    // each within about half a cell of the boundary point it stands for, so the angle is
    // known to within 2 atan(0.5 / reach): count it only when it surely exceeds the limit.
    const double angle = 2.0 * std::asin(std::min(1.0, separation / (2.0 * reach)));
    if (angle - 2.0 * std::atan(0.5 / reach) < kMinAngle) return;
    // Distances between cell centres; the boundary lies about half a cell short of a and b.
    crossings.push_back({reach - 0.5, std::abs(along) / separation, t <= 0.5 ? p : q});
  };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int p = j * n + i;
      if (!inside[p]) continue;
      if (i + 1 < n && inside[p + 1]) consider(p, p + 1, i, j, 1, 0);
      if (j + 1 < n && inside[p + n]) consider(p, p + n, i, j, 0, 1);
    }
  return crossings;
}

}  // namespace pak::metrics_internal
