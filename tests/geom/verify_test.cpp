#include "pak/geom/verify.hpp"

#include <gtest/gtest.h>

#include <limits>

using namespace pak;

namespace {

Ring square(double x0, double y0, double side) {
  return {{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}};
}
Region squareRegion(double x0, double y0, double side) { return {Polygon{square(x0, y0, side), {}}}; }

TriMesh twoTriangles() {
  TriMesh mesh;
  mesh.vertices = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

bool mentions(const std::vector<std::string>& problems, const std::string& text) {
  for (const std::string& p : problems)
    if (p.find(text) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST(VerifyMesh, CleanMeshPasses) {
  MeshCheck check = verifyMesh(twoTriangles());
  EXPECT_TRUE(check.ok);
  EXPECT_TRUE(check.problems.empty());
  EXPECT_TRUE(verifyMesh(TriMesh{}).ok);
}

TEST(VerifyMesh, CatchesBadIndex) {
  TriMesh mesh = twoTriangles();
  mesh.triangles[1] = {0, 2, 4};
  MeshCheck check = verifyMesh(mesh);
  EXPECT_FALSE(check.ok);
  ASSERT_EQ(check.problems.size(), 1u);
  EXPECT_EQ(check.problems[0], "triangle 1 has vertex index 4 outside [0, 4)");
  mesh.triangles[1] = {-1, 2, 3};
  EXPECT_FALSE(verifyMesh(mesh).ok);
}

TEST(VerifyMesh, CatchesInvertedTriangle) {
  TriMesh mesh = twoTriangles();
  mesh.triangles[0] = {0, 2, 1};
  MeshCheck check = verifyMesh(mesh);
  EXPECT_FALSE(check.ok);
  ASSERT_EQ(check.problems.size(), 1u);
  EXPECT_EQ(check.problems[0], "triangle 0 is inverted (area -0.5)");
}

TEST(VerifyMesh, CatchesZeroAreaAndRepeatedIndex) {
  TriMesh mesh = twoTriangles();
  mesh.vertices.push_back({2, 2});  // collinear with 0 and 2
  mesh.triangles.push_back({0, 2, 4});
  mesh.triangles.push_back({1, 1, 2});
  MeshCheck check = verifyMesh(mesh);
  EXPECT_FALSE(check.ok);
  ASSERT_EQ(check.problems.size(), 2u);
  EXPECT_TRUE(mentions(check.problems, "triangle 2 has zero area"));
  EXPECT_TRUE(mentions(check.problems, "triangle 3 repeats a vertex"));
  // A sliver below minArea counts as zero area.
  TriMesh sliver;
  sliver.vertices = {{0, 0}, {1, 0}, {0, 1e-6}};
  sliver.triangles = {{0, 1, 2}};
  EXPECT_TRUE(verifyMesh(sliver).ok);
  EXPECT_FALSE(verifyMesh(sliver, 1e-6).ok);
}

TEST(VerifyMesh, CatchesNonFiniteVertex) {
  TriMesh mesh = twoTriangles();
  mesh.vertices[3].y = std::numeric_limits<double>::quiet_NaN();
  MeshCheck check = verifyMesh(mesh);
  EXPECT_FALSE(check.ok);
  EXPECT_TRUE(mentions(check.problems, "vertex 3 has a non-finite coordinate"));
}

TEST(VerifyPacking, CleanPackingPasses) {
  Region container{Polygon{square(0, 0, 10), {square(4, 4, 2)}}};
  // Touching along an edge is not an overlap.
  std::vector<Region> elements{squareRegion(0, 0, 2), squareRegion(2, 0, 2), squareRegion(7, 7, 3)};
  PackingCheck check = verifyPacking(elements, container);
  EXPECT_TRUE(check.ok);
  EXPECT_EQ(check.overlappingPairs, 0);
  EXPECT_EQ(check.elementsOutside, 0);
  EXPECT_TRUE(check.problems.empty());
  EXPECT_TRUE(verifyPacking({}, container).ok);
}

TEST(VerifyPacking, CatchesOverlap) {
  Region container = squareRegion(0, 0, 100);
  std::vector<Region> elements{squareRegion(0, 0, 10), squareRegion(50, 50, 5), squareRegion(20, 20, 5),
                               squareRegion(52.5, 50, 5)};
  PackingCheck check = verifyPacking(elements, container);
  EXPECT_FALSE(check.ok);
  EXPECT_EQ(check.overlappingPairs, 1);
  EXPECT_NEAR(check.overlapArea, 12.5, 1e-9);
  ASSERT_EQ(check.problems.size(), 1u);
  EXPECT_EQ(check.problems[0], "elements 1 and 3 overlap by 12.5");
  // Below the tolerance it is not counted.
  PackingCheckOptions loose;
  loose.areaTolerance = 20.0;
  EXPECT_TRUE(verifyPacking(elements, container, loose).ok);
}

TEST(VerifyPacking, CatchesElementOutsideAndInHole) {
  Region container{Polygon{square(0, 0, 10), {square(4, 4, 2)}}};
  std::vector<Region> elements{squareRegion(9, 0, 2), squareRegion(4.5, 4.5, 1), squareRegion(1, 1, 1)};
  PackingCheck check = verifyPacking(elements, container);
  EXPECT_FALSE(check.ok);
  EXPECT_EQ(check.elementsOutside, 2);
  EXPECT_NEAR(check.outsideArea, 2.0 + 1.0, 1e-9);
  EXPECT_TRUE(mentions(check.problems, "element 0 lies outside the container (or in a hole) by 2"));
  EXPECT_TRUE(mentions(check.problems, "element 1 lies outside"));
  EXPECT_FALSE(mentions(check.problems, "element 2 "));
}

TEST(SelfIntersection, SimpleRingsDoNotCross) {
  EXPECT_FALSE(ringSelfIntersects(square(0, 0, 10)));
  // A concave comb, repeated points and a closing vertex repeated: still simple.
  EXPECT_FALSE(ringSelfIntersects({{0, 0}, {10, 0}, {10, 10}, {7, 10}, {7, 2}, {7, 2}, {3, 2}, {3, 10}, {0, 10}, {0, 0}}));
  // Touching without crossing (a vertex on another edge) is not a crossing.
  EXPECT_FALSE(ringSelfIntersects({{0, 0}, {10, 0}, {10, 10}, {5, 0}, {0, 10}}));
  EXPECT_FALSE(ringSelfIntersects({{0, 0}, {1, 1}}));
}

TEST(SelfIntersection, FigureEightAndFoldedLimbCross) {
  EXPECT_TRUE(ringSelfIntersects({{0, 0}, {10, 10}, {10, 0}, {0, 10}}));
  // A body with a limb folded back over it: the limb's edges cross the body's top edge.
  const Ring folded{{0, 0}, {20, 0}, {20, 10}, {12, 10}, {12, 4}, {6, 4}, {6, 14}, {9, 14}, {9, 10}, {0, 10}};
  EXPECT_TRUE(ringSelfIntersects(folded));
  // The same ring, rotated in its starting point, is found too (the sweep does not depend on it).
  Ring shifted(folded.begin() + 3, folded.end());
  shifted.insert(shifted.end(), folded.begin(), folded.begin() + 3);
  EXPECT_TRUE(ringSelfIntersects(shifted));
}

TEST(SelfIntersection, CheckCountsElementsOnce) {
  PackingCheck check;
  const Ring eight{{0, 0}, {10, 10}, {10, 0}, {0, 10}};
  checkSelfIntersections({{square(0, 0, 5)}, {eight, eight}, {square(20, 0, 5), eight}}, check);
  EXPECT_EQ(check.selfIntersecting, 2);
  EXPECT_FALSE(check.ok);
  ASSERT_EQ(check.problems.size(), 2u);
  EXPECT_EQ(check.problems[0], "element 1's outline crosses itself");
}

TEST(SelfIntersection, RingsDrawnCrossingAreNotFolds) {
  const Ring eight{{0, 0}, {10, 10}, {10, 0}, {0, 10}};
  PackingCheck check;
  // Element 0 was drawn as a figure eight; element 1 was a square and now crosses itself.
  checkSelfIntersections({{eight}, {eight}}, check, {{eight}, {square(0, 0, 10)}});
  EXPECT_EQ(check.selfIntersecting, 1);
  ASSERT_EQ(check.problems.size(), 1u);
  EXPECT_EQ(check.problems[0], "element 1's outline crosses itself");
}

TEST(SelfIntersection, TheCrossingPointIsWhereTwoEdgesMeet) {
  const std::optional<Vec2> at = ringSelfCrossing({{0, 0}, {10, 10}, {10, 0}, {0, 10}});
  ASSERT_TRUE(at.has_value());
  EXPECT_NEAR(at->x, 5.0, 1e-12);
  EXPECT_NEAR(at->y, 5.0, 1e-12);
  EXPECT_FALSE(ringSelfCrossing(square(0, 0, 10)).has_value());
}
