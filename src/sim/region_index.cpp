#include "sim/region_index.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pak/geom/closest_point.hpp"

namespace pak {

namespace {
// Outward normal of an edge of a ring whose interior lies to its left (positive signed area).
Vec2 outwardNormal(Vec2 a, Vec2 b) { return normalized(Vec2{b.y - a.y, a.x - b.x}); }
}  // namespace

// The cells of ring r (Chebyshev distance r) around (ci, cj) that lie on the grid, in a fixed order.
template <typename Visit>
void RegionIndex::visitRing(int ci, int cj, int r, Visit&& visit) const {
  for (int j = cj - r; j <= cj + r; ++j) {
    if (j < 0 || j >= ny_) continue;
    const bool edgeRow = (j == cj - r || j == cj + r);
    for (int i = ci - r; i <= ci + r; i += (edgeRow ? 1 : 2 * r)) {
      if (i >= 0 && i < nx_) visit(i, j);
      if (r == 0) break;
    }
  }
}

RegionIndex::RegionIndex(const Region& input, double cellSize) : cell_(cellSize) {
  Region region = input;
  normalizeOrientation(region);  // outer rings positive, holes negative: interior on the left
  auto addRing = [&](const Ring& ring) {
    std::size_t n = ring.size(), first = segments_.size();
    if (n < 3) return;
    for (std::size_t k = 0; k < n; ++k) {
      Vec2 a = ring[k], b = ring[(k + 1) % n];
      segments_.push_back({a, b, outwardNormal(a, b), {}, {}});
    }
    // Vertex pseudo-normals decide the side when the closest point is a vertex.
    for (std::size_t k = 0; k < n; ++k) {
      Segment& s = segments_[first + k];
      const Segment& prev = segments_[first + (k + n - 1) % n];
      const Segment& next = segments_[first + (k + 1) % n];
      s.normalA = normalized(prev.normal + s.normal);
      s.normalB = normalized(s.normal + next.normal);
    }
  };
  Box box;
  for (const Polygon& poly : region) {
    addRing(poly.outer);
    for (const Ring& h : poly.holes) addRing(h);
    box.add(bounds(poly));
  }
  if (segments_.empty()) return;
  origin_ = box.min - Vec2{cell_, cell_};
  nx_ = static_cast<int>(std::ceil((box.width() + 2 * cell_) / cell_)) + 1;
  ny_ = static_cast<int>(std::ceil((box.height() + 2 * cell_) / cell_)) + 1;
  std::vector<std::vector<int>> buckets(static_cast<std::size_t>(nx_) * ny_);
  for (std::size_t s = 0; s < segments_.size(); ++s) {
    const Segment& seg = segments_[s];
    // Conservative: every cell the segment's bounding box touches.
    int i0 = static_cast<int>(std::floor((std::min(seg.a.x, seg.b.x) - origin_.x) / cell_));
    int i1 = static_cast<int>(std::floor((std::max(seg.a.x, seg.b.x) - origin_.x) / cell_));
    int j0 = static_cast<int>(std::floor((std::min(seg.a.y, seg.b.y) - origin_.y) / cell_));
    int j1 = static_cast<int>(std::floor((std::max(seg.a.y, seg.b.y) - origin_.y) / cell_));
    for (int j = std::max(0, j0); j <= std::min(ny_ - 1, j1); ++j)
      for (int i = std::max(0, i0); i <= std::min(nx_ - 1, i1); ++i)
        buckets[cellIndex(i, j)].push_back(static_cast<int>(s));
  }
  cellStart_.assign(buckets.size() + 1, 0);
  cellState_.assign(buckets.size(), kOutside);
  for (std::size_t c = 0; c < buckets.size(); ++c) {
    cellStart_[c + 1] = cellStart_[c] + static_cast<int>(buckets[c].size());
    entries_.insert(entries_.end(), buckets[c].begin(), buckets[c].end());
    if (!buckets[c].empty()) {
      cellState_[c] = kCrossed;
    } else {
      int i = static_cast<int>(c % nx_), j = static_cast<int>(c / nx_);
      Vec2 centre = origin_ + Vec2{(i + 0.5) * cell_, (j + 0.5) * cell_};
      cellState_[c] = pointInRegion(centre, region) ? kInside : kOutside;
    }
  }
  // Two chamfer passes give the exact Chebyshev distance to the nearest crossed cell.
  const int far = nx_ + ny_;
  cellsToBoundary_.assign(cellState_.size(), far);
  for (std::size_t c = 0; c < cellState_.size(); ++c)
    if (cellState_[c] == kCrossed) cellsToBoundary_[c] = 0;
  auto relax = [&](int i, int j, int di, int dj) {
    const int ni = i + di, nj = j + dj;
    if (ni < 0 || nj < 0 || ni >= nx_ || nj >= ny_) return;
    int& here = cellsToBoundary_[cellIndex(i, j)];
    here = std::min(here, cellsToBoundary_[cellIndex(ni, nj)] + 1);
  };
  for (int j = 0; j < ny_; ++j)
    for (int i = 0; i < nx_; ++i) { relax(i, j, -1, 0); relax(i, j, -1, -1); relax(i, j, 0, -1); relax(i, j, 1, -1); }
  for (int j = ny_ - 1; j >= 0; --j)
    for (int i = nx_ - 1; i >= 0; --i) { relax(i, j, 1, 0); relax(i, j, 1, 1); relax(i, j, 0, 1); relax(i, j, -1, 1); }
}

// Every point of a cell is within half its diagonal of the centre, so no nearer to the
// boundary than the centre's distance plus that: a segment whose bounding box is farther from
// the cell cannot be nearest to any point in it. The rest are listed in the order the ring
// search meets them (first meeting), so that among equally near segments the list yields the
// one the search would.
void RegionIndex::listNearSegments() {
  if (segments_.empty() || !nearStart_.empty()) return;
  const std::size_t cells = cellState_.size();
  std::vector<double> bound(cells, 0.0);
  for (std::size_t c = 0; c < cells; ++c)  // before any list exists: by the ring search
    if (cellsToBoundary_[c] <= kListedRings) {
      const int i = static_cast<int>(c % nx_), j = static_cast<int>(c / nx_);
      const Vec2 centre = origin_ + Vec2{(i + 0.5) * cell_, (j + 0.5) * cell_};
      bound[c] = closestAround(centre).distance + 0.5 * std::sqrt(2.0) * cell_;
    }
  std::vector<int> start(cells + 1, 0);
  std::vector<std::size_t> seenBy(segments_.size(), cells);
  for (std::size_t c = 0; c < cells; ++c) {
    start[c] = static_cast<int>(nearSegments_.size());
    if (cellsToBoundary_[c] > kListedRings) continue;
    const int i = static_cast<int>(c % nx_), j = static_cast<int>(c / nx_);
    const Vec2 lo = origin_ + Vec2{i * cell_, j * cell_}, hi = lo + Vec2{cell_, cell_};
    // A segment met in ring r touches a cell at least (r − 1) cells from this one.
    const int rings = static_cast<int>(bound[c] / cell_) + 1;
    for (int r = 0; r <= rings; ++r)
      visitRing(i, j, r, [&](int ri, int rj) {
        const int rc = cellIndex(ri, rj);
        for (int k = cellStart_[rc]; k < cellStart_[rc + 1]; ++k) {
          const int s = entries_[k];
          if (seenBy[s] == c) continue;
          seenBy[s] = c;
          const Segment& seg = segments_[s];
          const double dx = std::max({0.0, lo.x - std::max(seg.a.x, seg.b.x), std::min(seg.a.x, seg.b.x) - hi.x});
          const double dy = std::max({0.0, lo.y - std::max(seg.a.y, seg.b.y), std::min(seg.a.y, seg.b.y) - hi.y});
          if (dx * dx + dy * dy <= bound[c] * bound[c]) nearSegments_.push_back(s);
        }
      });
  }
  start[cells] = static_cast<int>(nearSegments_.size());
  nearStart_ = std::move(start);
}

double RegionIndex::insideDistanceBound(Vec2 p) const {
  if (segments_.empty() || !std::isfinite(p.x) || !std::isfinite(p.y)) return 0.0;
  const double fi = std::floor((p.x - origin_.x) / cell_), fj = std::floor((p.y - origin_.y) / cell_);
  if (!(fi >= 0 && fj >= 0 && fi < nx_ && fj < ny_)) return 0.0;
  const int c = cellIndex(static_cast<int>(fi), static_cast<int>(fj));
  if (cellState_[c] != kInside) return 0.0;
  // The nearest crossed cell r rings away is r - 1 whole cells from any point of this one.
  const int r = cellsToBoundary_[c];
  return std::max(0, r - 1) * cell_;
}

// A point off the grid: the rings around its nearest cell would have to grow with the
// square root of its distance before their bound passed the best found, because far away
// many cells are almost equally near. Instead, visit the cells column by column away from
// p's nearest column and, in each, row by row away from its nearest row, skipping the rest of
// a column (or of the columns) once the cell's own distance from p is no nearer than the best.
// Far off, those cells form a band along the grid's near side, so the cost is bounded by the
// grid's size whatever the distance.
template <typename VisitCell>
void RegionIndex::closestFromOffGrid(Vec2 p, VisitCell&& visitCell, const double& best) const {
  auto nearest = [&](double offset, int n) {
    return static_cast<int>(std::clamp(std::floor(offset / cell_), 0.0, double(n - 1)));
  };
  const int ci = nearest(p.x - origin_.x, nx_), cj = nearest(p.y - origin_.y, ny_);
  // Distance along one axis from p to the interval of column (row) k.
  auto gap = [&](double coordinate, double start, int k) {
    const double lo = start + k * cell_, hi = lo + cell_;
    return coordinate < lo ? lo - coordinate : (coordinate > hi ? coordinate - hi : 0.0);
  };
  auto scanColumn = [&](int i) {
    const double dx = gap(p.x, origin_.x, i);
    if (dx * dx >= best) return false;
    for (int step : {-1, 1})
      for (int j = step < 0 ? cj : cj + 1; j >= 0 && j < ny_; j += step) {
        const double dy = gap(p.y, origin_.y, j);
        if (dx * dx + dy * dy >= best) break;
        visitCell(i, j);
      }
    return true;
  };
  scanColumn(ci);
  for (int i = ci - 1; i >= 0 && scanColumn(i); --i) {}
  for (int i = ci + 1; i < nx_ && scanColumn(i); ++i) {}
}

RegionIndex::Query RegionIndex::closestAround(Vec2 p) const {
  // A non-finite point has no closest boundary; the step's assertion reports it.
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) return Query{};
  double best = std::numeric_limits<double>::infinity();
  int bestSegment = -1;
  double bestT = 0.0;
  Vec2 bestPoint;
  auto consider = [&](int s) {
    double t;
    Vec2 q = closestPointOnSegment(p, segments_[s].a, segments_[s].b, &t);
    double d = lengthSquared(p - q);
    if (d < best) { best = d; bestSegment = s; bestT = t; bestPoint = q; }
  };
  auto visitCell = [&](int i, int j) {
    const int c = cellIndex(i, j);
    for (int k = cellStart_[c]; k < cellStart_[c + 1]; ++k) consider(entries_[k]);
  };
  const Vec2 gridMax = origin_ + Vec2{nx_ * cell_, ny_ * cell_};
  if (p.x < origin_.x || p.y < origin_.y || p.x > gridMax.x || p.y > gridMax.y) {
    closestFromOffGrid(p, visitCell, best);
  } else {
    // Rings of cells around p's cell; once the best distance is within the ring's inner
    // radius, stop.
    const int ci = std::min(nx_ - 1, static_cast<int>((p.x - origin_.x) / cell_));
    const int cj = std::min(ny_ - 1, static_cast<int>((p.y - origin_.y) / cell_));
    const int c = cellIndex(ci, cj);
    if (!nearStart_.empty() && nearStart_[c] < nearStart_[c + 1]) {
      for (int k = nearStart_[c]; k < nearStart_[c + 1]; ++k) consider(nearSegments_[k]);
    } else {
      const int maxRing = std::max(nx_, ny_) + 1;
      for (int r = 0; r <= maxRing; ++r) {
        visitRing(ci, cj, r, visitCell);
        if (bestSegment >= 0 && std::sqrt(best) <= r * cell_) break;
      }
    }
  }
  Query q;
  if (bestSegment < 0) return q;
  const Segment& s = segments_[bestSegment];
  Vec2 normal = bestT <= 0.0 ? s.normalA : (bestT >= 1.0 ? s.normalB : s.normal);
  q.closest = bestPoint;
  q.distance = std::sqrt(best);
  q.inside = dot(p - bestPoint, normal) < 0.0;
  q.computed = true;
  return q;
}

RegionIndex::Query RegionIndex::query(Vec2 p, bool wantClosest) const {
  Query q;
  if (segments_.empty()) return q;
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) return q;
  double fi = std::floor((p.x - origin_.x) / cell_), fj = std::floor((p.y - origin_.y) / cell_);
  bool inGrid = fi >= 0 && fj >= 0 && fi < nx_ && fj < ny_;
  int ci = inGrid ? static_cast<int>(fi) : 0, cj = inGrid ? static_cast<int>(fj) : 0;
  if (inGrid && cellState_[cellIndex(ci, cj)] != kCrossed && !wantClosest) {
    q.inside = cellState_[cellIndex(ci, cj)] == kInside;
    return q;
  }
  return closestAround(p);
}

}  // namespace pak
