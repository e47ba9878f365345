#pragma once
// Meshes the repulsion tests share: a hand-made square and library art meshed at a chosen size.
#include <vector>

#include "pak/geom/scene.hpp"
#include "pak/sim/element_mesh.hpp"

namespace pak::test {

// A 10 × 10 square mesh centred at the origin: 4 boundary vertices, 2 triangles, 5 springs.
inline ElementMesh squareMesh() {
  ElementMesh m;
  m.mesh.vertices = {{-5, -5}, {5, -5}, {5, 5}, {-5, 5}};
  m.mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.boundaryCount = 4;
  auto spring = [&](int a, int b) { m.springs.push_back({a, b, distance(m.mesh.vertices[a], m.mesh.vertices[b]), SpringKind::Edge}); };
  spring(0, 1); spring(1, 2); spring(2, 3); spring(3, 0); spring(0, 2);
  m.skinArea = 100.0;
  m.restCentroid = {0, 0};
  return m;
}

// The element's art centred on its outline's centroid and scaled by `scale`, then meshed, as
// packRepulsion prepares library elements.
inline ElementMesh centredElementMesh(const ElementArt& e, double scale, double gap, double spacing) {
  const Vec2 c = centroid(e.outline);
  std::vector<Shape> art = e.shapes;
  for (Shape& s : art)
    for (Subpath& sub : s.subpaths)
      for (Vec2& p : sub.points) p = (p - c) * scale;
  ElementMeshOptions options;
  options.gap = gap;
  options.spacing = spacing;
  return buildElementMesh(art, transformed(e.outline, scale, -c * scale), options);
}

}  // namespace pak::test
