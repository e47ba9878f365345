#include "pak/geom/triangulation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <thread>

#include "pak/error.hpp"
#include "pak/geom/blue_noise.hpp"
#include "pak/geom/resample.hpp"
#include "pak/geom/verify.hpp"

using namespace pak;

namespace {

Ring square(double x0, double y0, double side) {
  return {{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}};
}

double meshArea(const TriMesh& mesh) {
  double total = 0.0;
  for (const auto& t : mesh.triangles)
    total += triangleSignedArea(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
  return total;
}

void expectAllCentroidsInside(const TriMesh& mesh, const Polygon& polygon) {
  for (const auto& t : mesh.triangles) {
    const Vec2 c = (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3.0;
    EXPECT_TRUE(pointInPolygon(c, polygon)) << c.x << "," << c.y;
  }
}

void expectEveryVertexUsed(const TriMesh& mesh) {
  std::vector<bool> used(mesh.vertices.size(), false);
  for (const auto& t : mesh.triangles)
    for (int v : t) used[v] = true;
  for (std::size_t v = 0; v < used.size(); ++v) EXPECT_TRUE(used[v]) << v;
}

// No vertex strictly inside any triangle's circumcircle (with a relative tolerance).
void expectDelaunay(const TriMesh& mesh) {
  for (const auto& t : mesh.triangles) {
    const Vec2 a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
      const Vec2 d = mesh.vertices[v];
      const Vec2 ad = a - d, bd = b - d, cd = c - d;
      const double det = lengthSquared(ad) * cross(bd, cd) - lengthSquared(bd) * cross(ad, cd) +
                         lengthSquared(cd) * cross(ad, bd);
      EXPECT_LE(det, 1e-9) << "vertex " << v << " inside a circumcircle";
    }
  }
}

// A boundary resampled at `spacing` plus interior points kept `spacing` away from it:
// every boundary edge's diametral disc is empty, so the Delaunay mesh keeps the boundary.
TriMesh meshOf(Polygon polygon, double spacing, std::uint64_t seed, Polygon* resampledOut = nullptr) {
  Polygon resampled;
  resampled.outer = resampleRing(polygon.outer, spacing);
  for (const Ring& h : polygon.holes) resampled.holes.push_back(resampleRing(h, spacing));
  BlueNoiseOptions options;
  options.radius = spacing;
  options.boundaryMargin = spacing;
  options.seed = seed;
  std::vector<Vec2> interior = blueNoiseSample(Region{resampled}, options);
  if (resampledOut) *resampledOut = resampled;
  return triangulatePolygon(resampled, interior);
}

}  // namespace

TEST(Triangulation, SquareWithCentreSteinerPoint) {
  Polygon p{square(0, 0, 2), {}};
  TriMesh mesh = triangulatePolygon(p, {{1, 1}});
  ASSERT_EQ(mesh.vertices.size(), 5u);
  ASSERT_EQ(mesh.triangles.size(), 4u);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(mesh.vertices[k], p.outer[k]);
  EXPECT_EQ(mesh.vertices[4], (Vec2{1, 1}));
  for (const auto& t : mesh.triangles) {
    EXPECT_DOUBLE_EQ(triangleSignedArea(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]), 1.0);
    EXPECT_TRUE(t[0] == 4 || t[1] == 4 || t[2] == 4);
  }
  EXPECT_DOUBLE_EQ(meshArea(mesh), 4.0);
  EXPECT_TRUE(verifyMesh(mesh).ok);
}

TEST(Triangulation, ClockwiseOuterRingStillGivesCounterClockwiseTriangles) {
  Ring cw = square(0, 0, 2);
  std::reverse(cw.begin(), cw.end());
  TriMesh mesh = triangulatePolygon(Polygon{cw, {}}, {{1, 1}});
  EXPECT_EQ(mesh.triangles.size(), 4u);
  EXPECT_TRUE(verifyMesh(mesh).ok);
  EXPECT_EQ(mesh.vertices[0], cw[0]);
}

TEST(Triangulation, LShapeDropsTheNotchTriangle) {
  Polygon l{Ring{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, {}};
  TriMesh mesh = triangulatePolygon(l);
  EXPECT_EQ(mesh.vertices.size(), 6u);
  EXPECT_EQ(mesh.triangles.size(), 4u);
  EXPECT_NEAR(meshArea(mesh), 3.0, 1e-12);
  expectAllCentroidsInside(mesh, l);
  EXPECT_TRUE(verifyMesh(mesh).ok);
}

TEST(Triangulation, DenseLShapeCoversThePolygonExactly) {
  Polygon l{Ring{{0, 0}, {20, 0}, {20, 10}, {10, 10}, {10, 20}, {0, 20}}, {}};
  Polygon resampled;
  TriMesh mesh = meshOf(l, 1.0, 5, &resampled);
  ASSERT_GT(mesh.triangles.size(), 300u);
  expectAllCentroidsInside(mesh, l);
  EXPECT_NEAR(meshArea(mesh), area(l), 1e-9);
  EXPECT_TRUE(verifyMesh(mesh).ok);
  expectEveryVertexUsed(mesh);
  for (std::size_t k = 0; k < resampled.outer.size(); ++k) EXPECT_EQ(mesh.vertices[k], resampled.outer[k]);
}

TEST(Triangulation, PolygonWithHole) {
  Polygon p{square(0, 0, 10), {square(3, 3, 4)}};
  TriMesh mesh = meshOf(p, 0.5, 9);
  expectAllCentroidsInside(mesh, p);
  EXPECT_NEAR(meshArea(mesh), 84.0, 1e-9);
  MeshCheck check = verifyMesh(mesh);
  EXPECT_TRUE(check.ok) << (check.problems.empty() ? "" : check.problems[0]);
  // The hole is empty: no vertex strictly inside it.
  for (Vec2 v : mesh.vertices) EXPECT_FALSE(v.x > 3 && v.x < 7 && v.y > 3 && v.y < 7);
}

TEST(Triangulation, PointsOutsideThePolygonAreDropped) {
  Polygon p{square(0, 0, 2), {}};
  TriMesh mesh = triangulatePolygon(p, {{1, 1}, {5, 5}});
  EXPECT_EQ(mesh.vertices.size(), 5u);
  EXPECT_EQ(mesh.triangles.size(), 4u);
  for (Vec2 v : mesh.vertices) EXPECT_NE(v, (Vec2{5, 5}));
}

TEST(Triangulation, DegenerateInput) {
  EXPECT_TRUE(triangulatePolygon(Polygon{}).triangles.empty());
  EXPECT_TRUE(triangulatePolygon(Polygon{Ring{{0, 0}, {1, 1}}, {}}).triangles.empty());
  TriMesh collinear = triangulatePolygon(Polygon{Ring{{0, 0}, {1, 1}, {2, 2}}, {}});
  EXPECT_TRUE(collinear.triangles.empty());
  EXPECT_TRUE(collinear.vertices.empty());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(triangulatePolygon(Polygon{Ring{{0, 0}, {1, nan}, {0, 1}}, {}}), InputError);
  EXPECT_THROW(delaunayTriangulation({{0, 0}, {1, 0}, {nan, 1}}), InputError);
}

TEST(Triangulation, DelaunayOfFourNearlyCocircularPoints) {
  // (0, 1.01) lies just outside the circle through the other three, so triangle
  // (0,0) (1,0) (1,1) is Delaunay and the diagonal runs from (0,0) to (1,1).
  std::vector<Vec2> points{{0, 0}, {1, 0}, {1, 1}, {0, 1.01}};
  TriMesh mesh = delaunayTriangulation(points);
  EXPECT_EQ(mesh.vertices, points);
  ASSERT_EQ(mesh.triangles.size(), 2u);
  EXPECT_NEAR(meshArea(mesh), 1.005, 1e-12);
  for (const auto& t : mesh.triangles) {
    const bool hasDiagonal = (std::count(t.begin(), t.end(), 0) == 1) && (std::count(t.begin(), t.end(), 2) == 1);
    EXPECT_TRUE(hasDiagonal);
  }
  EXPECT_TRUE(verifyMesh(mesh).ok);
  expectDelaunay(mesh);
  // Exactly cocircular: either diagonal, still two triangles covering the square.
  TriMesh exact = delaunayTriangulation({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  EXPECT_EQ(exact.triangles.size(), 2u);
  EXPECT_DOUBLE_EQ(meshArea(exact), 1.0);
}

TEST(Triangulation, DelaunayMergesDuplicatesOntoFirstOccurrence) {
  std::vector<Vec2> points{{0, 0}, {1, 0}, {0, 1}, {1, 0}, {1, 1}};
  TriMesh mesh = delaunayTriangulation(points);
  EXPECT_EQ(mesh.vertices.size(), 5u);
  EXPECT_EQ(mesh.triangles.size(), 2u);
  for (const auto& t : mesh.triangles)
    for (int v : t) EXPECT_NE(v, 3);
  EXPECT_TRUE(delaunayTriangulation({{0, 0}, {1, 0}}).triangles.empty());
  EXPECT_TRUE(delaunayTriangulation({{0, 0}, {1, 0}, {2, 0}, {3, 0}}).triangles.empty());
}

TEST(Triangulation, RandomPointsAreDelaunay) {
  Region square10{Polygon{square(0, 0, 10), {}}};
  BlueNoiseOptions options;
  options.radius = 0.7;
  std::vector<Vec2> points = blueNoiseSample(square10, options);
  TriMesh mesh = delaunayTriangulation(points);
  EXPECT_TRUE(verifyMesh(mesh).ok);
  expectDelaunay(mesh);
  // Euler: a triangulation of n points with h on the hull has 2n - 2 - h triangles.
  EXPECT_LT(mesh.triangles.size(), 2 * points.size());
  EXPECT_GT(mesh.triangles.size(), points.size());
}

TEST(Triangulation, SafeFromSeveralThreads) {
  Polygon p{square(0, 0, 10), {square(3, 3, 4)}};
  const TriMesh reference = meshOf(p, 0.5, 9);
  std::vector<TriMesh> results(4);
  std::vector<std::thread> threads;
  for (int k = 0; k < 4; ++k)
    threads.emplace_back([&, k] {
      for (int repeat = 0; repeat < 5; ++repeat) results[k] = meshOf(p, 0.5, 9);
    });
  for (std::thread& t : threads) t.join();
  for (const TriMesh& r : results) {
    EXPECT_EQ(r.vertices, reference.vertices);
    EXPECT_EQ(r.triangles, reference.triangles);
  }
}
