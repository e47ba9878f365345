#pragma once
// Distance fields on regular grids.
#include <cstdint>
#include <vector>

#include "pak/geom/polygon.hpp"

namespace pak {

// Samples at cell centres: sample (i, j) is at origin + ((i + 0.5) * cell, (j + 0.5) * cell).
struct DistanceGrid {
  Vec2 origin;
  double cell = 1.0;
  int nx = 0;
  int ny = 0;
  std::vector<double> values;  // row-major, index j * nx + i

  double at(int i, int j) const { return values[static_cast<std::size_t>(j) * nx + i]; }
  Vec2 center(int i, int j) const { return origin + Vec2{(i + 0.5) * cell, (j + 0.5) * cell}; }
  // Bilinear interpolation, clamped at the grid's border.
  double sample(Vec2 p) const;
};

// Signed distance to the region's boundary over `area`, negative inside the region and
// positive outside (the sign convention of thesis eq. 4.10). `resolution` cells along the
// longer side of `area`. Distances are exact to the polygon boundary.
DistanceGrid signedDistanceField(const Region& region, const Box& area, int resolution);

// Exact Euclidean distance transform of a binary grid (Felzenszwalb & Huttenlocher):
// for every cell, the distance (in cells) to the nearest cell where `occupied` is true.
std::vector<double> euclideanDistanceTransform(const std::vector<std::uint8_t>& occupied, int nx, int ny);

}  // namespace pak
