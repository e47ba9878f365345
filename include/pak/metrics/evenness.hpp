#pragma once
// How even a packing's negative space is, as one set of numbers a user can compare across
// packings (RepulsionPak quality issue, item 1):
//
//   Evenness e = measureEvenness(geometry);     // or measureEvenness(packingGeometry(packing))
//   e.pocketShare[1]                             // P2: share of the negative space deeper than 2h
//
// On a grid of `resolution` cells along the container's bounding square, the positive space is
// the element art and the fixed art, with its small holes (eyes) filled; the negative space is
// the rest of the container. D is its exact Euclidean distance transform (to the nearest
// element or wall) and h the median of D along the medial axis of the negative space: the
// typical half-width of its channels. Everything is a ratio of grid lengths, so scaling the
// whole packing changes nothing but `cell`, `halfWidth` and `largestEmptyRadius`.
#include <array>
#include <cstdint>
#include <vector>

#include "pak/metrics/metrics.hpp"

namespace pak {

struct EvennessOptions {
  int resolution = 1000;        // grid cells along the container's bounding square (2 to 10000)
  // Holes of the positive space smaller than this fraction of the bounding square's area are
  // filled (counted as positive): 4e-4 is the 400 cells at resolution 1000, and keeps
  // meaning the same area at any resolution.
  double smallHoleArea = 4e-4;
};

struct Evenness {
  int resolution = 0;
  double cell = 0.0;                // side of a grid cell, packing units
  double negativeRatio = 0.0;       // negative-space cells / container cells
  double halfWidth = 0.0;           // h: median of D along the medial axis, packing units
  std::array<double, 3> pocketShare{};  // P_k = |{D > k h}| / |negative space|, k = 1, 2, 3
  double largestEmptyRadius = 0.0;  // largest D, packing units
  double largestRadiusOverHalfWidth = 0.0;
  double widthSpread = 0.0;         // (Q3 - Q1) / median of D along the medial axis
  double axisLength = 0.0;          // length of the medial axis, packing units
  long long containerCells = 0;
  long long negativeCells = 0;
  long long filledHoleCells = 0;    // holes of the positive space counted as positive
};
// With no negative space or no medial axis, h and every ratio built on it are 0.

// Throws InputError for a container without area or a resolution out of range.
Evenness measureEvenness(const PackingGeometry& packing, const EvennessOptions& options = {});

// The same measurement cell by cell, for pictures: the grid cropped to the container's box,
// row-major from `origin`.
enum class EvennessCell : std::uint8_t { Outside, Positive, FilledHole, Negative };
struct EvennessMap {
  Evenness evenness;
  Vec2 origin;
  double cell = 0.0;
  int columns = 0, rows = 0;
  std::vector<EvennessCell> kind;
  std::vector<double> distance;   // D in packing units on negative cells, 0 elsewhere
  std::vector<std::uint8_t> axis; // 1 on the cells the medial axis passes through
};
EvennessMap evennessMap(const PackingGeometry& packing, const EvennessOptions& options = {});

}  // namespace pak
