#pragma once
// Delaunay triangulation of a polygon with interior Steiner points.
#include <vector>

#include "pak/geom/polygon.hpp"
#include "pak/geom/tri_mesh.hpp"

namespace pak {

// Delaunay triangulation of the polygon's vertices (outer ring and holes) plus the given
// interior points; triangles whose centroid lies outside the polygon are dropped, as are
// vertices no triangle uses. Triangles are counter-clockwise. The first vertices of the
// result are the outer ring's, in order, whenever they are all used.
TriMesh triangulatePolygon(const Polygon& polygon, const std::vector<Vec2>& interiorPoints = {});

// Plain Delaunay triangulation of a point set (covers the convex hull). Vertex order is
// the input's; duplicate points are merged onto the first occurrence.
TriMesh delaunayTriangulation(const std::vector<Vec2>& points);

}  // namespace pak
