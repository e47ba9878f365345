// As-rigid-as-possible deformation (Igarashi et al. 2005) on small grid meshes.
#include "animation/arap.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "pak/error.hpp"

namespace pak {
namespace {

// A columns × rows grid of unit cells from (0, 0), two counter-clockwise triangles a cell.
// Vertex (i, j) is j·(columns + 1) + i.
TriMesh grid(int columns, int rows, double cell = 1.0) {
  TriMesh mesh;
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i <= columns; ++i) mesh.vertices.push_back({i * cell, j * cell});
  auto at = [&](int i, int j) { return j * (columns + 1) + i; };
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return mesh;
}

std::vector<Vec2> restPositions(const TriMesh& mesh, const std::vector<int>& handles) {
  std::vector<Vec2> positions;
  for (int h : handles) positions.push_back(mesh.vertices[h]);
  return positions;
}

double maxDistance(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  double worst = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, distance(a[i], b[i]));
  return worst;
}

TEST(Arap, HandlesAtRestKeepTheMesh) {
  const TriMesh mesh = grid(6, 3);
  const std::vector<int> handles{0, 6, 27, 21, 10};
  const ArapDeformation arap(mesh, handles);
  std::vector<Vec2> out;
  arap.deform(restPositions(mesh, handles), out);
  ASSERT_EQ(out.size(), mesh.vertices.size());
  EXPECT_LT(maxDistance(out, mesh.vertices), 1e-9);
}

TEST(Arap, OneHandleTranslatesRigidly) {
  const TriMesh mesh = grid(5, 4);
  const ArapDeformation arap(mesh, {7});
  std::vector<Vec2> out;
  const Vec2 shift{3.5, -2.0};
  arap.deform({mesh.vertices[7] + shift}, out);
  std::vector<Vec2> expected = mesh.vertices;
  for (Vec2& p : expected) p += shift;
  EXPECT_LT(maxDistance(out, expected), 1e-6);  // scale and rotation are the regulariser's choice: ~1e-8 relative
}

TEST(Arap, TwoHandlesRotatedRotateTheMesh) {
  const TriMesh mesh = grid(8, 4);  // 8 × 4, centre (4, 2)
  const std::vector<int> handles{2 * 9 + 0, 2 * 9 + 8};  // middle of the left and right sides
  const ArapDeformation arap(mesh, handles);
  const Vec2 centre{4, 2};
  const double angle = std::numbers::pi / 2;
  std::vector<Vec2> moved;
  for (Vec2 p : restPositions(mesh, handles)) moved.push_back(centre + rotated(p - centre, angle));
  std::vector<Vec2> out;
  arap.deform(moved, out);
  std::vector<Vec2> expected;
  for (Vec2 p : mesh.vertices) expected.push_back(centre + rotated(p - centre, angle));
  EXPECT_LT(maxDistance(out, expected), 1e-8);
}

TEST(Arap, BentStripKeepsItsEdgeLengths) {
  // A 20 × 2 strip held at both ends; its right end is carried a quarter turn round a circle
  // whose arc along the centre line has the strip's length.
  const int columns = 20, rows = 2;
  const TriMesh mesh = grid(columns, rows);
  std::vector<int> handles;
  for (int j = 0; j <= rows; ++j) handles.push_back(j * (columns + 1)), handles.push_back(j * (columns + 1) + columns);
  const ArapDeformation arap(mesh, handles);
  const double radius = columns / (std::numbers::pi / 2);
  const Vec2 centre{0.0, 1.0 + radius};  // the centre line y = 1 bends up round it
  std::vector<Vec2> moved;
  for (int h : handles) {
    const Vec2 p = mesh.vertices[h];
    if (p.x == 0.0) {
      moved.push_back(p);
    } else {  // the end at arc length 20: a quarter turn, the strip's width kept radial
      const double r = radius - (p.y - 1.0);
      moved.push_back(centre + Vec2{r, 0.0});
    }
  }
  std::vector<Vec2> out;
  arap.deform(moved, out);

  double worst = 0.0, sum = 0.0;
  int count = 0;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const int i = t[k], j = t[(k + 1) % 3];
      const double rest = distance(mesh.vertices[i], mesh.vertices[j]);
      const double now = distance(out[i], out[j]);
      const double change = std::abs(now - rest) / rest;
      worst = std::max(worst, change);
      sum += change;
      ++count;
    }
  // The inner and outer fibres must shorten and lengthen by about 1/radius ≈ 8 %.
  EXPECT_LT(worst, 0.15);
  EXPECT_LT(sum / count, 0.05);
  // And it did bend: the middle of the centre line left the x axis.
  EXPECT_GT(out[1 * (columns + 1) + columns / 2].y, 3.0);
  // The triangles keep their orientation (no fold-over).
  for (const auto& t : mesh.triangles) EXPECT_GT(triangleSignedArea(out[t[0]], out[t[1]], out[t[2]]), 0.0);
}

TEST(Arap, UnconnectedVerticesFollowTheNearestHandle) {
  TriMesh mesh = grid(2, 2);
  mesh.vertices.push_back({-5, 0});   // in no triangle, nearest handle: vertex 0
  mesh.vertices.push_back({12, 12});  // nearest handle: vertex 8 (2, 2)
  const std::vector<int> handles{0, 8};
  const ArapDeformation arap(mesh, handles);
  std::vector<Vec2> out;
  arap.deform({Vec2{1, 1}, Vec2{3, 3}}, out);  // both handles move by (1, 1)
  EXPECT_LT(distance(out[9], Vec2{-4, 1}), 1e-6);
  EXPECT_LT(distance(out[10], Vec2{13, 13}), 1e-6);
  EXPECT_LT(distance(out[4], Vec2{2, 2}), 1e-6);
}

TEST(Arap, MovedSolverStillWorks) {
  const TriMesh mesh = grid(3, 3);
  ArapDeformation first(mesh, {0, 15});
  ArapDeformation second = std::move(first);
  EXPECT_EQ(second.handles(), (std::vector<int>{0, 15}));
  std::vector<Vec2> out;
  second.deform({Vec2{1, 0}, Vec2{4, 3}}, out);
  EXPECT_LT(distance(out[5], Vec2{2, 1}), 1e-6);
}

TEST(Arap, RejectsBadHandles) {
  const TriMesh mesh = grid(2, 2);
  auto message = [&](std::vector<int> handles) {
    try {
      ArapDeformation arap(mesh, std::move(handles));
    } catch (const InputError& error) {
      return std::string(error.what());
    }
    return std::string("(no error)");
  };
  EXPECT_NE(message({}).find("at least one handle"), std::string::npos);
  EXPECT_NE(message({0, 9}).find("handle vertex 9"), std::string::npos);
  EXPECT_NE(message({0, -1}).find("handle vertex -1"), std::string::npos);
  EXPECT_NE(message({4, 0, 4}).find("vertex 4 is a handle twice"), std::string::npos);
}

}  // namespace
}  // namespace pak
