#pragma once
// Fast, exact "is this point inside the region, and where is the nearest boundary point?"
// for a static region (a container, or fixed obstacles). Cells that no boundary segment
// touches answer inside/outside from a precomputed flag; the rest search outward ring by ring.
// For an index that answers many queries (a simulation's container), `listNearSegments` makes
// each cell within a few rings of the boundary keep the segments that can be nearest to a
// point in it, in the order that search meets them, so a query there scans a short list
// instead and finds the same segment.
#include <cstdint>
#include <vector>

#include "pak/geom/polygon.hpp"

namespace pak {

class RegionIndex {
 public:
  RegionIndex() = default;
  // `cellSize` about the length of a few boundary segments works well.
  RegionIndex(const Region& region, double cellSize);

  struct Query {
    bool inside = false;
    Vec2 closest;          // nearest boundary point (valid when `computed`)
    double distance = 0.0; // to `closest`
    bool computed = false;
  };
  // Inside test; the nearest boundary point is computed only when needed: always if
  // `wantClosest`, else only for points in cells the boundary crosses.
  Query query(Vec2 p, bool wantClosest) const;
  // For p inside the region, a lower bound on its distance to the boundary, from the grid
  // alone; 0 near the boundary, outside or off the grid. Lets a caller skip an exact query
  // when it only asks "inside and farther than d?".
  double insideDistanceBound(Vec2 p) const;
  bool empty() const { return segments_.empty(); }
  // Lists the near segments of every cell within kListedRings of the boundary (see above):
  // the same answers, faster, for a few hundred queries per cell of boundary to pay back.
  void listNearSegments();

 private:
  struct Segment { Vec2 a, b; Vec2 normal; Vec2 normalA, normalB; };  // outward normals
  Query closestAround(Vec2 p) const;
  template <typename Visit>
  void visitRing(int ci, int cj, int r, Visit&& visit) const;
  template <typename VisitCell>
  void closestFromOffGrid(Vec2 p, VisitCell&& visitCell, const double& best) const;
  int cellIndex(int i, int j) const { return j * nx_ + i; }

  std::vector<Segment> segments_;
  Vec2 origin_;
  double cell_ = 1.0;
  int nx_ = 0, ny_ = 0;
  std::vector<int> cellStart_, entries_;
  enum : std::uint8_t { kOutside = 0, kInside = 1, kCrossed = 2 };
  std::vector<std::uint8_t> cellState_;
  std::vector<int> cellsToBoundary_;  // Chebyshev distance, in cells, to the nearest crossed cell
  // Per cell within kListedRings of a crossed cell (else empty): the segments that can be nearest.
  static constexpr int kListedRings = 4;
  std::vector<int> nearStart_, nearSegments_;
};

}  // namespace pak
