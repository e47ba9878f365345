// Douglas–Peucker simplification of closed rings.
#include <vector>

#include "pak/geom/closest_point.hpp"
#include "pak/geom/simplify.hpp"

namespace pak {
namespace {

// Marks the vertices of ring[first..last] (indices modulo n) to keep, iteratively.
void keepFurthest(const Ring& ring, std::size_t first, std::size_t last, double tolerance2,
                  std::vector<char>& keep) {
  const std::size_t n = ring.size();
  std::vector<std::pair<std::size_t, std::size_t>> stack{{first, last}};
  while (!stack.empty()) {
    auto [a, b] = stack.back();
    stack.pop_back();
    double worst = tolerance2;
    std::size_t index = a;
    for (std::size_t k = a + 1; k < b; ++k) {
      const Vec2 p = ring[k % n];
      const Vec2 q = closestPointOnSegment(p, ring[a % n], ring[b % n]);
      const double d2 = dot(p - q, p - q);
      if (d2 > worst) worst = d2, index = k;
    }
    if (index == a) continue;
    keep[index % n] = 1;
    stack.push_back({a, index});
    stack.push_back({index, b});
  }
}

}  // namespace

Ring simplifyRing(const Ring& ring, double tolerance) {
  const std::size_t n = ring.size();
  if (n <= 3 || !(tolerance > 0.0)) return ring;
  // Split at vertex 0 and the vertex furthest from it: both are kept.
  std::size_t far = 0;
  double best = -1.0;
  for (std::size_t k = 1; k < n; ++k) {
    const double d2 = dot(ring[k] - ring[0], ring[k] - ring[0]);
    if (d2 > best) best = d2, far = k;
  }
  std::vector<char> keep(n, 0);
  keep[0] = keep[far] = 1;
  keepFurthest(ring, 0, far, tolerance * tolerance, keep);
  keepFurthest(ring, far, n, tolerance * tolerance, keep);
  Ring out;
  for (std::size_t k = 0; k < n; ++k)
    if (keep[k]) out.push_back(ring[k]);
  return out.size() >= 3 ? out : ring;
}

Region simplifyRegion(const Region& region, double tolerance) {
  Region out = region;
  for (Polygon& p : out) {
    p.outer = simplifyRing(p.outer, tolerance);
    for (Ring& h : p.holes) h = simplifyRing(h, tolerance);
  }
  return out;
}

}  // namespace pak
