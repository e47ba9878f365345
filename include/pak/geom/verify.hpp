#pragma once
// Invariant checkers shipped with the library and called by the tests.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "pak/geom/polygon.hpp"
#include "pak/geom/tri_mesh.hpp"

namespace pak {

struct MeshCheck {
  bool ok = true;
  std::vector<std::string> problems;  // e.g. "triangle 12 is inverted (area -0.3)"
};

// Valid indices, no repeated index within a triangle, no inverted or zero-area triangles
// (area <= minArea), no non-finite coordinates.
MeshCheck verifyMesh(const TriMesh& mesh, double minArea = 1e-12);

struct PackingCheck {
  bool ok = true;
  int overlappingPairs = 0;   // pairs overlapping by more than the tolerance
  double overlapArea = 0.0;   // total pairwise overlap area
  int elementsOutside = 0;    // elements with more than the tolerance outside the container
  double outsideArea = 0.0;
  int selfIntersecting = 0;   // elements whose outline crosses itself (see checkSelfIntersections)
  std::vector<std::string> problems;
  std::vector<std::size_t> offending;  // elements in an overlapping pair or outside, ascending
  std::vector<std::pair<std::size_t, std::size_t>> overlapping;  // the pairs (a < b), ascending
  std::vector<std::size_t> outside;                              // ascending
};

struct PackingCheckOptions {
  // An overlap or an excursion outside the container counts only above this area.
  double areaTolerance = 1e-6;
};

// No two elements overlap and every element lies inside the container (and out of its holes).
PackingCheck verifyPacking(const std::vector<Region>& elements, const Region& container,
                           const PackingCheckOptions& options = {});

// Whether two edges of the closed ring that share no vertex cross (a fold, a figure eight).
// Edges that only touch, and repeated consecutive points, are not crossings.
bool ringSelfIntersects(const Ring& ring);
// Where it does: a point where two of its edges cross (the first the sweep finds).
std::optional<Vec2> ringSelfCrossing(const Ring& ring);

// Counts the elements whose outline crosses itself (a limb folded over its own body), one
// problem each: `outlines[i]` holds element i's filled rings as placed. A ring that already
// crosses itself in `rest[i]` (element i's rings as drawn, when given with the same count) was
// drawn that way and is not counted. Clears `check.ok` if any.
void checkSelfIntersections(const std::vector<std::vector<Ring>>& outlines, PackingCheck& check,
                            const std::vector<std::vector<Ring>>& rest = {});

}  // namespace pak
