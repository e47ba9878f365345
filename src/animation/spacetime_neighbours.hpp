#pragma once
// Who is near each skin vertex of the spacetime simulation (thesis 5.5.1): the closest point
// of every other element's envelope within the repulsion reach (exact), and for an element
// farther off, the centre of its envelope triangles in the outer shell of the 5 × 5 × 5 block
// of grid cells around the vertex (approximate).
//
// Vertices move at most a velocity cap per step, so the search is not redone every step.
// `rebuild` finds, from a grid of the envelope, each skin vertex's candidate triangles: those
// of each element within twice `margin` (a distance) of its nearest, and within reach plus the
// margin, nearest first. While no vertex has moved more than half the margin since, a vertex
// and a triangle come closer by at most the margin, so the nearest triangle of every element
// within reach is among them: `gather` is exact from the lists alone, and stops at the first
// listed triangle whose distance at the rebuild, less the margin, is no nearer than the best
// found. The shell centres are kept from the rebuild. `track` says when to rebuild.
//
// Between rebuilds most vertices move far less than the margin allows (late in a run, half of
// them under 0.5 of its 2 units). `track` measures each vertex's move since the origin, so
// `gather` skips a listed triangle whose distance at the rebuild, less the query vertex's move
// and its corners' largest move, is no nearer than the best found: a lower bound as exact as
// the margin's, only tighter, so the hits are the same bit for bit.
//
// Everything depends only on the positions given to `rebuild` (the origin) and to `gather`,
// so a checkpoint that keeps the origin resumes bit-identically. Work is split in fixed
// chunks of vertices, each with its own buffers: results do not depend on the thread count,
// and once the buffers have grown no step allocates.
#include <array>
#include <cstdint>
#include <vector>

#include "pak/geom/box3.hpp"
#include "pak/geom/vec3.hpp"
#include "sim/nearest_hits.hpp"
#include "sim/parallel.hpp"

namespace pak {

class SpacetimeNeighbours {
 public:
  // The nearest point of another element: exact (on an envelope triangle) or approximate
  // (a shell centre); any exact hit is nearer than an approximate one.
  struct Hit {
    int element; double d2; Vec3 point; bool exact;
    int key() const { return element; }
    bool nearerThan(const Hit& other) const {
      return (exact && !other.exact) || (exact == other.exact && d2 < other.d2);
    }
  };
  static constexpr int kMaxHits = 16;
  using Hits = NearestHitList<Hit, kMaxHits>;

  struct Layout {
    std::vector<std::array<int, 3>> triangles;  // envelope triangles (vertex indices)
    std::vector<int> triangleElement;
    std::vector<int> vertexElement;             // per vertex
    std::vector<std::uint8_t> isSkin;           // per vertex: only skin vertices query
    Box3 area;                                  // the grid's extent (x, y, t)
    // Set by the caller, which owns these constants (SpacetimeSimulation::finalize).
    double cellSize = 0.0;                      // grid cell = exact reach
    double shellReach = 0.0;                    // approximate hits up to this far
    double margin = 0.0;                        // see above
  };
  SpacetimeNeighbours(Layout layout, ThreadPool& pool);

  // Candidate lists from `origin` (copied: the lists' positions).
  void rebuild(const std::vector<Vec3>& origin);
  // Measures how far each skin vertex has moved from the origin, and returns whether some
  // vertex has moved more than half the margin (then `rebuild` before any `gather`).
  bool track(const std::vector<Vec3>& positions);
  // The hits of skin vertex v at x = positions[v] (triangle corners read from `positions`),
  // which `track` has measured (or `rebuild` taken as the origin).
  void gather(int v, const std::vector<Vec3>& positions, Hits& hits) const;

  const std::vector<Vec3>& origin() const { return origin_; }
  std::size_t triangleCount() const { return layout_.triangles.size(); }

 private:
  struct Group { int element, begin, end; Vec3 centre; Box3 box; };  // one element's triangles in one cell
  struct CellCandidates { int begin = 0, end = 0, shellBegin = 0, shellEnd = 0; };
  struct Far { Vec3 centre; int element; };
  // A vertex's lists: per other element within reach a run of listed triangles (nearest
  // first), and per element in the shell one centre.
  struct Run { int element, count; };
  // A listed triangle: its distance at the origin (0 past the sorted ones), rounded down to a
  // float (`gather` uses it only in lower bounds; an entry takes 16 bytes instead of 24), and
  // its corners, so that `gather` reads no triangle table.
  struct Listed { float distance; std::array<int, 3> corners; };
  struct VertexLists { int runBegin = 0, runEnd = 0, listedBegin = 0, farBegin = 0, farEnd = 0; };
  // A triangle within the list reach of the vertex being listed: its place in the cell order,
  // the element's slot, its box's squared distance and its own (< 0: not computed).
  struct Seen { int j, slot; double box2, d2; };
  // A group of another element within the list reach of the vertex being listed.
  struct Passing { int group, slot; double bound2; };
  struct Chunk {
    std::vector<Run> runs; std::vector<Listed> listed; std::vector<Far> far;
    std::vector<Passing> passing; std::vector<Seen> seen;  // scratch for one vertex at a time
    // Per element, its place among the vertex's shell centres (-1: none yet): a group finds
    // its element's without a search.
    std::vector<int> farSlot;
  };
  static constexpr int kChunk = 512;  // vertices per chunk

  int cellOf(Vec3 p) const;
  void buildGrid();
  void buildCandidates();
  void buildLists(int chunk);

  Layout layout_;
  ThreadPool& pool_;
  std::vector<Vec3> origin_;
  int nx_ = 0, ny_ = 0, nt_ = 0;
  Vec3 gridOrigin_;
  // Grid of the envelope at the origin. `cellCorners_[j]` holds the corners of triangle
  // cellTriangles_[j]: the rebuild reads a group's triangles from one run of memory.
  std::vector<int> triangleCell_, cellStart_, cellTriangles_, cellGroupStart_;
  std::vector<std::array<Vec3, 3>> cellCorners_;
  std::vector<Group> groups_;
  // Per cell holding a skin vertex: the groups within reach of the margin, then those of the
  // outer shell.
  std::vector<int> vertexCell_, queriedCells_, candidates_;
  std::vector<CellCandidates> candidatesOf_;
  // How far each skin vertex has moved from the origin (as `track` last measured it), rounded
  // up to a float: `gather` only subtracts it from a lower bound.
  std::vector<float> moved_;
  std::vector<std::uint8_t> stalePerChunk_;  // scratch for track
  // The lists.
  std::vector<VertexLists> lists_;
  std::vector<Chunk> chunks_;
};

}  // namespace pak
