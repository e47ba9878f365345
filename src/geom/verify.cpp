#include "pak/geom/verify.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "pak/error.hpp"
#include "pak/geom/clipping.hpp"
#include "pak/geom/segment_crossing.hpp"

namespace pak {

MeshCheck verifyMesh(const TriMesh& mesh, double minArea) {
  MeshCheck check;
  auto fail = [&](std::string problem) {
    check.ok = false;
    check.problems.push_back(std::move(problem));
  };
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const Vec2 p = mesh.vertices[v];
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) fail("vertex " + std::to_string(v) + " has a non-finite coordinate");
  }
  const long long vertexCount = static_cast<long long>(mesh.vertices.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const std::array<int, 3>& tri = mesh.triangles[t];
    const std::string name = "triangle " + std::to_string(t);
    bool indicesValid = true;
    for (int v : tri)
      if (v < 0 || v >= vertexCount) {
        fail(name + " has vertex index " + std::to_string(v) + " outside [0, " + std::to_string(vertexCount) + ")");
        indicesValid = false;
      }
    if (!indicesValid) continue;
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) {
      fail(name + " repeats a vertex (" + std::to_string(tri[0]) + ", " + std::to_string(tri[1]) + ", " +
           std::to_string(tri[2]) + ")");
      continue;
    }
    const double a = triangleSignedArea(mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]]);
    if (a < 0.0)
      fail(name + " is inverted (area " + messageNumber(a) + ")");
    else if (!(a > minArea))  // also catches a NaN area
      fail(name + " has zero area (area " + messageNumber(a) + ", minimum " + messageNumber(minArea) + ")");
  }
  return check;
}

PackingCheck verifyPacking(const std::vector<Region>& elements, const Region& container,
                           const PackingCheckOptions& options) {
  PackingCheck check;
  const double tolerance = options.areaTolerance;

  std::vector<Box> boxes(elements.size());
  for (std::size_t e = 0; e < elements.size(); ++e) boxes[e] = bounds(elements[e]);

  // Sweep over boxes sorted by their left side: only pairs whose boxes overlap are clipped.
  std::vector<std::size_t> order(elements.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  order.erase(std::remove_if(order.begin(), order.end(), [&](std::size_t e) { return boxes[e].empty(); }), order.end());
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return boxes[a].min.x < boxes[b].min.x; });
  struct Overlap {
    std::size_t a, b;
    double area;
  };
  std::vector<Overlap> overlaps;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::size_t a = order[k];
    for (std::size_t m = k + 1; m < order.size() && boxes[order[m]].min.x <= boxes[a].max.x; ++m) {
      const std::size_t b = order[m];
      if (!boxes[a].overlaps(boxes[b])) continue;
      const double shared = area(intersect(elements[a], elements[b]));
      check.overlapArea += shared;
      if (shared > tolerance) overlaps.push_back({std::min(a, b), std::max(a, b), shared});
    }
  }
  // Report in element order, independent of the sweep's order.
  std::sort(overlaps.begin(), overlaps.end(),
            [](const Overlap& x, const Overlap& y) { return x.a < y.a || (x.a == y.a && x.b < y.b); });
  for (const Overlap& o : overlaps) {
    check.offending.push_back(o.a);
    check.offending.push_back(o.b);
    check.overlapping.emplace_back(o.a, o.b);
    ++check.overlappingPairs;
    check.problems.push_back("elements " + std::to_string(o.a) + " and " + std::to_string(o.b) + " overlap by " +
                             messageNumber(o.area));
  }

  for (std::size_t e = 0; e < elements.size(); ++e) {
    if (boxes[e].empty()) continue;
    const double outside = area(subtract(elements[e], container));
    if (outside > tolerance) {
      check.offending.push_back(e);
      check.outside.push_back(e);
      ++check.elementsOutside;
      check.outsideArea += outside;
      check.problems.push_back("element " + std::to_string(e) + " lies outside the container (or in a hole) by " +
                               messageNumber(outside) + " of its area " + messageNumber(area(elements[e])));
    }
  }
  std::sort(check.offending.begin(), check.offending.end());
  check.offending.erase(std::unique(check.offending.begin(), check.offending.end()), check.offending.end());
  check.ok = check.overlappingPairs == 0 && check.elementsOutside == 0;
  return check;
}

bool ringSelfIntersects(const Ring& input) { return ringSelfCrossing(input).has_value(); }

std::optional<Vec2> ringSelfCrossing(const Ring& input) {
  Ring ring;
  for (Vec2 p : input)
    if (ring.empty() || !(p == ring.back())) ring.push_back(p);
  while (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
  const std::size_t n = ring.size();
  if (n < 4) return std::nullopt;
  // Sweep the edges by their smallest x; only edges whose x ranges overlap are compared.
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  auto lo = [&](std::size_t e) { return std::min(ring[e].x, ring[(e + 1) % n].x); };
  auto hi = [&](std::size_t e) { return std::max(ring[e].x, ring[(e + 1) % n].x); };
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return lo(a) < lo(b); });
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t e = order[i];
    const Vec2 a = ring[e], b = ring[(e + 1) % n];
    const double eMinY = std::min(a.y, b.y), eMaxY = std::max(a.y, b.y), eMaxX = hi(e);
    for (std::size_t j = i + 1; j < n && lo(order[j]) <= eMaxX; ++j) {
      const std::size_t f = order[j];
      if (f == (e + 1) % n || e == (f + 1) % n) continue;  // neighbours share a vertex
      const Vec2 c = ring[f], d = ring[(f + 1) % n];
      if (std::max(c.y, d.y) < eMinY || std::min(c.y, d.y) > eMaxY) continue;
      if (const auto crossing = properCrossing(a, b, c, d)) return a + (b - a) * crossing->t;
    }
  }
  return std::nullopt;
}

void checkSelfIntersections(const std::vector<std::vector<Ring>>& outlines, PackingCheck& check,
                            const std::vector<std::vector<Ring>>& rest) {
  for (std::size_t i = 0; i < outlines.size(); ++i)
    for (std::size_t r = 0; r < outlines[i].size(); ++r)
      if (ringSelfIntersects(outlines[i][r])) {
        const bool drawnSo = i < rest.size() && rest[i].size() == outlines[i].size() && ringSelfIntersects(rest[i][r]);
        if (drawnSo) continue;
        ++check.selfIntersecting;
        check.ok = false;
        check.problems.push_back("element " + std::to_string(i) + "'s outline crosses itself");
        break;
      }
}

}  // namespace pak
