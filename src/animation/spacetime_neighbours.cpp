#include "animation/spacetime_neighbours.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "pak/geom/closest_point_triangle.hpp"

namespace pak {

namespace {

// The 5 × 5 × 5 block of cells around a query cell: the 3 × 3 × 3 block nearest first, then
// the outer shell.
struct BlockOffsets {
  std::array<std::array<int, 3>, 27> inner;
  std::array<std::array<int, 3>, 98> shell;
  BlockOffsets() {
    int i = 0, s = 0;
    for (int dt = -2; dt <= 2; ++dt)
      for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
          if (std::abs(dx) <= 1 && std::abs(dy) <= 1 && std::abs(dt) <= 1) inner[i++] = {dx, dy, dt};
          else shell[s++] = {dx, dy, dt};
        }
    std::stable_sort(inner.begin(), inner.end(), [](const auto& a, const auto& b) {
      return a[0] * a[0] + a[1] * a[1] + a[2] * a[2] < b[0] * b[0] + b[1] * b[1] + b[2] * b[2];
    });
  }
};
const BlockOffsets kBlock;

// Distances computed at the origin and now may differ in their last bits; a lower bound is
// lowered by this much (canonical units) to stay one.
constexpr double kRoundingSlack = 1e-9;

// A float no larger (below) or no smaller (above) than a distance, for the bounds: rounding to
// float moves a value by at most 2^-24 of it, so a 2^-20 widening first keeps the side (a
// subnormal's absolute error is far inside kRoundingSlack). No branch and no libm call.
float floatBelow(double distance) { return static_cast<float>(distance * (1.0 - 0x1p-20)); }
float floatAbove(double distance) { return static_cast<float>(distance * (1.0 + 0x1p-20)); }

Box3 triangleBox(Vec3 a, Vec3 b, Vec3 c) {
  Box3 box;
  box.add(a), box.add(b), box.add(c);
  return box;
}

}  // namespace

SpacetimeNeighbours::SpacetimeNeighbours(Layout layout, ThreadPool& pool) : layout_(std::move(layout)), pool_(pool) {
  const double cell = layout_.cellSize;
  assert(cell > 0.0 && layout_.margin > 0.0 && layout_.shellReach >= cell);
  const Box3& area = layout_.area;
  gridOrigin_ = {area.lo.x - cell, area.lo.y - cell, area.lo.t - cell};
  auto cellsAlong = [&](double length) { return std::max(1, static_cast<int>(std::ceil((length + 2 * cell) / cell))); };
  nx_ = cellsAlong(area.hi.x - area.lo.x);
  ny_ = cellsAlong(area.hi.y - area.lo.y);
  nt_ = cellsAlong(area.hi.t - area.lo.t);
  const std::size_t cells = static_cast<std::size_t>(nx_) * ny_ * nt_;
  const std::size_t nt = layout_.triangles.size(), nv = layout_.vertexElement.size();
  triangleCell_.assign(nt, 0);
  cellCorners_.assign(nt, {});
  cellStart_.assign(cells + 1, 0);
  cellTriangles_.assign(nt, 0);
  cellGroupStart_.assign(cells + 1, 0);
  groups_.assign(nt, {});
  vertexCell_.assign(nv, 0);
  candidatesOf_.assign(cells, {});
  moved_.assign(nv, 0.0);
  lists_.assign(nv, {});
  chunks_.resize((nv + kChunk - 1) / kChunk);
  const int elements = layout_.vertexElement.empty() ? 0 : *std::max_element(layout_.vertexElement.begin(), layout_.vertexElement.end()) + 1;
  for (Chunk& chunk : chunks_) chunk.farSlot.assign(static_cast<std::size_t>(elements), -1);
}

int SpacetimeNeighbours::cellOf(Vec3 p) const {
  const double inv = 1.0 / layout_.cellSize;
  auto clampTo = [](double v, int n) { return std::clamp(static_cast<int>(std::floor(v)), 0, n - 1); };
  const int x = clampTo((p.x - gridOrigin_.x) * inv, nx_), y = clampTo((p.y - gridOrigin_.y) * inv, ny_),
            t = clampTo((p.t - gridOrigin_.t) * inv, nt_);
  return (t * ny_ + y) * nx_ + x;
}

void SpacetimeNeighbours::rebuild(const std::vector<Vec3>& origin) {
  assert(origin.size() == layout_.vertexElement.size());
  origin_ = origin;
  std::fill(moved_.begin(), moved_.end(), 0.0f);
  buildGrid();
  buildCandidates();
  pool_.parallelFor(chunks_.size(), 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t c = begin; c < end; ++c) buildLists(static_cast<int>(c));
  });
}

bool SpacetimeNeighbours::track(const std::vector<Vec3>& positions) {
  const double limit = 0.5 * layout_.margin;
  // Per chunk of vertices, whether one moved past the limit (a fixed split: no shared flag).
  const std::size_t nv = positions.size(), chunks = (nv + kChunk - 1) / kChunk;
  std::vector<std::uint8_t>& past = stalePerChunk_;
  past.assign(chunks, 0);
  pool_.parallelFor(chunks, 8, [&](std::size_t begin, std::size_t end) {
    for (std::size_t c = begin; c < end; ++c)
      for (std::size_t v = c * kChunk; v < std::min(nv, (c + 1) * kChunk); ++v)
        if (layout_.isSkin[v]) {
          const double moved = std::sqrt(lengthSquared(positions[v] - origin_[v]));
          moved_[v] = floatAbove(moved);
          if (moved > limit) past[c] = 1;
        }
  });
  return std::find(past.begin(), past.end(), 1) != past.end();
}

// The envelope triangles by cell of their centroid, and within a cell in runs of one element
// (groups), each with its centre and bounding box.
void SpacetimeNeighbours::buildGrid() {
  const std::size_t nt = layout_.triangles.size();
  pool_.parallelFor(nt, 1024, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const auto& tri = layout_.triangles[i];
      triangleCell_[i] = cellOf((origin_[tri[0]] + origin_[tri[1]] + origin_[tri[2]]) / 3.0);
    }
  });
  // Counting sort by cell; stable, so each cell lists its triangles element by element.
  std::fill(cellStart_.begin(), cellStart_.end(), 0);
  for (std::size_t i = 0; i < nt; ++i) ++cellStart_[triangleCell_[i] + 1];
  const std::size_t cells = cellStart_.size() - 1;
  for (std::size_t c = 0; c < cells; ++c) cellStart_[c + 1] += cellStart_[c];
  std::copy(cellStart_.begin(), cellStart_.end(), cellGroupStart_.begin());  // a moving cursor, for now
  for (std::size_t i = 0; i < nt; ++i) cellTriangles_[cellGroupStart_[triangleCell_[i]]++] = static_cast<int>(i);
  pool_.parallelFor(nt, 1024, [&](std::size_t begin, std::size_t end) {
    for (std::size_t j = begin; j < end; ++j) {
      const auto& tri = layout_.triangles[cellTriangles_[j]];
      cellCorners_[j] = {origin_[tri[0]], origin_[tri[1]], origin_[tri[2]]};
    }
  });
  std::size_t groupCount = 0;
  for (std::size_t c = 0; c < cells; ++c) {
    cellGroupStart_[c] = static_cast<int>(groupCount);
    for (int k = cellStart_[c]; k < cellStart_[c + 1];) {
      const int element = layout_.triangleElement[cellTriangles_[k]];
      Group group{element, k, k, {}, {}};
      for (; group.end < cellStart_[c + 1] && layout_.triangleElement[cellTriangles_[group.end]] == element; ++group.end) {
        const auto& [a, b, d] = cellCorners_[group.end];
        group.centre += (a + b + d) / 3.0;
        group.box.add(triangleBox(a, b, d));
      }
      group.centre = group.centre / static_cast<double>(group.end - group.begin);
      groups_[groupCount++] = group;
      k = group.end;
    }
  }
  cellGroupStart_[cells] = static_cast<int>(groupCount);
}

// Per cell holding a skin vertex: the groups of the 5 × 5 × 5 block that come within reach
// plus the margin of the cell, then the groups of the outer shell whose centre comes within
// the shell reach plus the margin.
void SpacetimeNeighbours::buildCandidates() {
  const std::size_t nv = origin_.size();
  pool_.parallelFor(nv, 4096, [&](std::size_t begin, std::size_t end) {
    for (std::size_t v = begin; v < end; ++v)
      if (layout_.isSkin[v]) vertexCell_[v] = cellOf(origin_[v]);
  });
  for (CellCandidates& c : candidatesOf_) c.end = -1;  // not queried
  queriedCells_.clear();
  for (std::size_t v = 0; v < nv; ++v)
    if (layout_.isSkin[v] && candidatesOf_[vertexCell_[v]].end < 0) {
      candidatesOf_[vertexCell_[v]].end = 0;
      queriedCells_.push_back(vertexCell_[v]);
    }
  std::sort(queriedCells_.begin(), queriedCells_.end());
  auto blockCell = [&](int cell, const std::array<int, 3>& o) {
    const int x = cell % nx_ + o[0], y = cell / nx_ % ny_ + o[1], t = cell / (nx_ * ny_) + o[2];
    if (x < 0 || x >= nx_ || y < 0 || y >= ny_ || t < 0 || t >= nt_) return -1;
    return (t * ny_ + y) * nx_ + x;
  };
  auto groupsIn = [&](int c) { return c < 0 ? 0 : cellGroupStart_[c + 1] - cellGroupStart_[c]; };
  // Room for every group of the block twice (near, then shell); each cell fills its own range.
  int room = 0;
  for (int cell : queriedCells_) {
    CellCandidates& c = candidatesOf_[cell];
    c.begin = room;
    int shell = 0;
    for (const auto& o : kBlock.inner) room += groupsIn(blockCell(cell, o));
    for (const auto& o : kBlock.shell) shell += groupsIn(blockCell(cell, o));
    c.shellBegin = room + shell;  // the near groups fit before it, the shell's after
    room = c.shellBegin + shell;
  }
  if (candidates_.size() < static_cast<std::size_t>(room)) candidates_.resize(static_cast<std::size_t>(room) * 5 / 4);
  const double cell = layout_.cellSize, margin = layout_.margin;
  const double nearReach2 = (cell + margin) * (cell + margin);
  const double farReach2 = (layout_.shellReach + margin) * (layout_.shellReach + margin);
  constexpr double kInf = std::numeric_limits<double>::infinity();
  pool_.parallelFor(queriedCells_.size(), 16, [&](std::size_t begin, std::size_t end) {
    for (std::size_t q = begin; q < end; ++q) {
      const int index = queriedCells_[q];
      const int ix = index % nx_, iy = index / nx_ % ny_, it = index / (nx_ * ny_);
      // The cell's box; a border cell also holds the points clamped into it.
      Box3 box;
      box.lo = {gridOrigin_.x + ix * cell, gridOrigin_.y + iy * cell, gridOrigin_.t + it * cell};
      box.hi = {box.lo.x + cell, box.lo.y + cell, box.lo.t + cell};
      if (ix == 0) box.lo.x = -kInf;
      if (iy == 0) box.lo.y = -kInf;
      if (it == 0) box.lo.t = -kInf;
      if (ix == nx_ - 1) box.hi.x = kInf;
      if (iy == ny_ - 1) box.hi.y = kInf;
      if (it == nt_ - 1) box.hi.t = kInf;
      // The near groups from the front of the cell's room, the shell's from its middle: one
      // pass over the shell sees each of its groups once.
      CellCandidates& out = candidatesOf_[index];
      int near = out.begin, far = out.shellBegin;
      for (const auto& o : kBlock.inner)
        if (const int c = blockCell(index, o); c >= 0)
          for (int g = cellGroupStart_[c]; g < cellGroupStart_[c + 1]; ++g)
            if (distanceSquared(box, groups_[g].box) <= nearReach2) candidates_[near++] = g;
      for (const auto& o : kBlock.shell)
        if (const int c = blockCell(index, o); c >= 0)
          for (int g = cellGroupStart_[c]; g < cellGroupStart_[c + 1]; ++g) {
            const Group& group = groups_[g];
            if (distanceSquared(box, group.box) <= nearReach2) candidates_[near++] = g;
            if (distanceSquared(box, group.centre) < farReach2) candidates_[far++] = g;
          }
      out.end = near;
      out.shellEnd = far;
    }
  });
}

// Each skin vertex of one chunk: per other element within reach plus the margin, its
// triangles within twice the margin of its nearest (nearest first); per element in the shell,
// its nearest group centre.
void SpacetimeNeighbours::buildLists(int chunkIndex) {
  Chunk& chunk = chunks_[chunkIndex];
  chunk.runs.clear();
  chunk.listed.clear();
  chunk.far.clear();
  const double reach = layout_.cellSize, margin = layout_.margin;
  const double listReach = reach + margin, listReach2 = listReach * listReach;
  const double farReach2 = (layout_.shellReach + margin) * (layout_.shellReach + margin);
  // How far (squared) an element's triangles are listed, from its nearest one's distance.
  auto listLimit2 = [&](double best2) {
    const double limit = std::min(std::sqrt(best2) + 2.0 * margin, listReach);
    return limit * limit;
  };
  // Elements near one vertex: a handful (they are at least a gap apart); more are ignored.
  constexpr int kElements = 32;
  struct Near { int element; double best2; };
  struct Far { int element; double d2; Vec3 centre; };
  struct Sorted { double d2; int triangle; };
  constexpr int kSorted = 256;
  std::array<Near, kElements> near;
  std::array<Far, kElements> far;
  std::array<Sorted, kSorted> sorted;
  const int vBegin = chunkIndex * kChunk;
  const int vEnd = std::min(vBegin + kChunk, static_cast<int>(origin_.size()));
  for (int v = vBegin; v < vEnd; ++v) {
    VertexLists& lists = lists_[v];
    lists.runBegin = static_cast<int>(chunk.runs.size());
    lists.listedBegin = static_cast<int>(chunk.listed.size());
    lists.farBegin = static_cast<int>(chunk.far.size());
    if (!layout_.isSkin[v]) {
      lists.runEnd = lists.runBegin, lists.farEnd = lists.farBegin;
      continue;
    }
    const Vec3 x = origin_[v];
    const int self = layout_.vertexElement[v];
    const CellCandidates& around = candidatesOf_[vertexCell_[v]];
    // Each element's nearest distance (capped at the list reach), over the triangles of the
    // groups that come within the list reach, each seen once (the listing below reuses them).
    // Groups nearest first: once a group's box is farther than an element's best plus twice the
    // margin, none of its triangles can be the nearest or listed.
    int elements = 0;
    chunk.passing.clear();
    for (int k = around.begin; k < around.end; ++k) {
      const Group& group = groups_[candidates_[k]];
      if (group.element == self) continue;
      const double bound2 = distanceSquared(group.box, x);
      if (bound2 >= listReach2) continue;
      int e = 0;
      while (e < elements && near[e].element != group.element) ++e;
      if (e == elements) {
        if (elements == kElements) continue;
        near[elements++] = {group.element, listReach2};
      }
      chunk.passing.push_back({candidates_[k], e, bound2});
    }
    for (std::size_t i = 1; i < chunk.passing.size(); ++i)  // a few: insertion sort (stable, no buffer)
      for (std::size_t at = i; at > 0 && chunk.passing[at].bound2 < chunk.passing[at - 1].bound2; --at)
        std::swap(chunk.passing[at], chunk.passing[at - 1]);
    chunk.seen.clear();
    for (const Passing& passing : chunk.passing) {
      double& best2 = near[passing.slot].best2;
      if (passing.bound2 > listLimit2(best2)) continue;
      const Group& group = groups_[passing.group];
      for (int j = group.begin; j < group.end; ++j) {
        const auto& [a, b, c] = cellCorners_[j];
        const double box2 = distanceSquared(triangleBox(a, b, c), x);
        if (box2 > listReach2) continue;
        double d2 = -1.0;  // not computed: its box is no nearer than the best
        if (box2 < best2) best2 = std::min(best2, d2 = lengthSquared(closestPointOnTriangle(x, a, b, c) - x));
        chunk.seen.push_back({j, passing.slot, box2, d2});
      }
    }
    // Per element: every triangle that may become its nearest before the next rebuild.
    for (int e = 0; e < elements; ++e) {
      if (near[e].best2 >= listReach2) continue;
      const double limit2 = listLimit2(near[e].best2);
      const std::size_t first = chunk.listed.size();
      int count = 0;
      for (const Seen& seen : chunk.seen) {
        if (seen.slot != e || seen.box2 > limit2) continue;
        double d2 = seen.d2;
        if (d2 < 0.0) {
          const auto& [a, b, c] = cellCorners_[seen.j];
          d2 = lengthSquared(closestPointOnTriangle(x, a, b, c) - x);
        }
        if (d2 > limit2) continue;
        const int tri = cellTriangles_[seen.j];
        if (count == kSorted) {  // beyond the sorted ones (not seen in practice): still listed
          chunk.listed.push_back({0.0f, layout_.triangles[tri]});
          continue;
        }
        // Nearest first (ties by triangle), so that gather prunes early.
        int at = count++;
        for (; at > 0 && (sorted[at - 1].d2 > d2 || (sorted[at - 1].d2 == d2 && sorted[at - 1].triangle > tri)); --at)
          sorted[at] = sorted[at - 1];
        sorted[at] = {d2, tri};
      }
      // Nearest first after any overflow (distance 0), so gather stops at the first entry out of reach.
      for (int i = 0; i < count; ++i)
        chunk.listed.push_back({floatBelow(std::sqrt(sorted[i].d2)), layout_.triangles[sorted[i].triangle]});
      chunk.runs.push_back({near[e].element, static_cast<int>(chunk.listed.size() - first)});
    }
    lists.runEnd = static_cast<int>(chunk.runs.size());
    // Per element in the shell: its nearest group centre there.
    int farCount = 0;
    for (int k = around.shellBegin; k < around.shellEnd; ++k) {
      const Group& group = groups_[candidates_[k]];
      if (group.element == self) continue;
      const double d2 = lengthSquared(x - group.centre);
      if (d2 >= farReach2) continue;
      int& e = chunk.farSlot[static_cast<std::size_t>(group.element)];
      if (e < 0) {
        if (farCount == kElements) continue;
        e = farCount;
        far[farCount++] = {group.element, d2, group.centre};
      } else if (d2 < far[e].d2) {
        far[e].d2 = d2, far[e].centre = group.centre;
      }
    }
    for (int e = 0; e < farCount; ++e) {
      chunk.far.push_back({far[e].centre, far[e].element});
      chunk.farSlot[static_cast<std::size_t>(far[e].element)] = -1;
    }
    lists.farEnd = static_cast<int>(chunk.far.size());
  }
}

void SpacetimeNeighbours::gather(int v, const std::vector<Vec3>& positions, Hits& hits) const {
  const Vec3 x = positions[v];
  const double reach2 = layout_.cellSize * layout_.cellSize;
  const double shellReach2 = layout_.shellReach * layout_.shellReach;
  const Chunk& chunk = chunks_[v / kChunk];
  const VertexLists& lists = lists_[v];
  const double margin = layout_.margin + kRoundingSlack, moved = double{moved_[v]} + kRoundingSlack;
  const Listed* listed = chunk.listed.data() + lists.listedBegin;
  for (int r = lists.runBegin; r < lists.runEnd; ++r) {
    const auto [element, count] = chunk.runs[r];
    const Listed* run = listed;
    listed += count;
    double best = reach2;
    Vec3 nearest;
    for (int i = 0; i < count; ++i) {
      // Lower bounds on the triangle's distance now: the margin's, which grows along the list
      // (so none after this one can be nearer), then the moves' (its own and its corners').
      const double distanceAtOrigin = run[i].distance;  // a float, widened exactly
      const double bound = distanceAtOrigin - margin;
      if (bound > 0.0 && bound * bound >= best) break;
      const auto& c = run[i].corners;
      const double tighter = distanceAtOrigin - moved - double{std::max({moved_[c[0]], moved_[c[1]], moved_[c[2]]})};
      if (tighter > 0.0 && tighter * tighter >= best) continue;
      const Vec3 a = positions[c[0]], b = positions[c[1]], d = positions[c[2]];
      if (distanceSquared(triangleBox(a, b, d), x) >= best) continue;
      const Vec3 q = closestPointOnTriangle(x, a, b, d);
      if (const double d2 = lengthSquared(q - x); d2 < best) best = d2, nearest = q;
    }
    if (best < reach2) hits.offer({element, best, nearest, true});
  }
  for (int k = lists.farBegin; k < lists.farEnd; ++k) {
    const Far& far = chunk.far[k];
    const double d2 = lengthSquared(x - far.centre);
    if (d2 >= shellReach2) continue;
    if (const int known = hits.find(far.element); known >= 0 && hits[known].exact) continue;
    hits.offer({far.element, d2, far.centre, false});
  }
}

}  // namespace pak
