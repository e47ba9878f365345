#pragma once
// An indexed triangle mesh.
#include <array>
#include <vector>

#include "pak/geom/vec2.hpp"

namespace pak {

struct TriMesh {
  std::vector<Vec2> vertices;
  // Counter-clockwise (positive area in a y-up frame) vertex index triples.
  std::vector<std::array<int, 3>> triangles;
};

double triangleSignedArea(Vec2 a, Vec2 b, Vec2 c);
// Barycentric coordinates of p with respect to triangle abc (may be negative outside).
std::array<double, 3> barycentric(Vec2 p, Vec2 a, Vec2 b, Vec2 c);

}  // namespace pak
