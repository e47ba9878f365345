#include "repulsion/mesh_fixtures.hpp"
#include "repulsion/packing_simulation.hpp"
#include "repulsion/thesis_parameters.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace pak;

namespace {

using test::squareMesh;

Region box(double size) { return {Polygon{{{0, 0}, {size, 0}, {size, size}, {0, size}}, {}}}; }

Box area(double size) {
  Box b;
  b.add(Vec2{-size * 0.2, -size * 0.2});
  b.add(Vec2{size * 1.2, size * 1.2});
  return b;
}

// The thesis's constants with a 20-unit neighbour cell.
SimulationParameters boxParameters() {
  SimulationParameters p = test::thesisParameters();
  p.cellSize = 20.0;
  return p;
}

// A simulation in the 100 × 100 box, on one thread.
struct BoxSimulation {
  explicit BoxSimulation(const SimulationParameters& p = boxParameters())
      : parameters(p), sim(index, 10000.0, parameters, pool) {}
  Region container = box(100);
  RegionIndex index{container, 5.0};
  ThreadPool pool{1};
  SimulationParameters parameters;
  PackingSimulation sim;
};

}  // namespace

TEST(PackingSimulation, LoneMeshGrowsByRateTimesStep) {
  BoxSimulation scene;
  const SimulationParameters& p = scene.parameters;
  PackingSimulation& sim = scene.sim;
  sim.addMesh(squareMesh(), 0, {50, 50}, 0.0, 0.5);
  sim.finalize(area(100));
  EXPECT_NEAR(sim.fill(), 0.0025, 1e-12);  // (10 × 0.5)² / 100²
  sim.step();
  EXPECT_NEAR(sim.meshes()[0].growth, 0.5 + p.growthRate * p.timeStep, 1e-12);
  EXPECT_EQ(sim.growingCount(), 1);
}

TEST(PackingSimulation, GrowthIsBlockedWhileOverlapping) {
  BoxSimulation scene;
  PackingSimulation& sim = scene.sim;
  sim.addMesh(squareMesh(), 0, {50, 50}, 0.0, 1.0);
  sim.addMesh(squareMesh(), 0, {57, 51}, 0.0, 1.0);  // overlaps the first by 3 × 9 units
  sim.finalize(area(100));
  sim.step();
  EXPECT_TRUE(sim.meshes()[0].overlapping);
  EXPECT_TRUE(sim.meshes()[1].overlapping);
  EXPECT_DOUBLE_EQ(sim.meshes()[0].growth, 1.0);
  EXPECT_DOUBLE_EQ(sim.meshes()[1].growth, 1.0);
  EXPECT_EQ(sim.growingCount(), 0);
  // Mesh 0's corner (55, 55) lies inside mesh 1 (x 52..62, y 46..56); its corner (55, 45) does not.
  EXPECT_TRUE(sim.vertexInsideOther(2));
  EXPECT_FALSE(sim.vertexInsideOther(1));
}

TEST(PackingSimulation, PressNeitherGrowsNorShrinksAndBulgesAMeshWithRoom) {
  SimulationParameters p = boxParameters();
  p.pocketPressure = 50.0;
  p.pocketClearance = 5.0;
  BoxSimulation scene(p);
  PackingSimulation& sim = scene.sim;
  sim.addMesh(squareMesh(), 0, {30, 50}, 0.0, 0.5);      // room all around: it could grow
  sim.addMesh(squareMesh(), 0, {70, 50}, 0.0, 1.0);
  sim.addMesh(squareMesh(), 0, {77, 51}, 0.0, 1.0);      // 3 units deep into the previous one
  sim.finalize(area(100));
  const double restArea = sim.meshes()[0].area;
  sim.press(1.0);
  for (int i = 0; i < 20; ++i) sim.step();
  EXPECT_DOUBLE_EQ(sim.meshes()[0].growth, 0.5);
  EXPECT_DOUBLE_EQ(sim.meshes()[1].growth, 1.0);  // deep, but pressing shrinks nothing
  EXPECT_DOUBLE_EQ(sim.meshes()[2].growth, 1.0);
  // Growing, a mesh with room feels no pocket pressure; pressed, it bulges into the room.
  EXPECT_GT(sim.meshes()[0].area, 1.02 * restArea);
  sim.settle(1.0, 0.5);
  sim.step();
  EXPECT_LT(sim.meshes()[1].growth, 1.0);  // the clean-up shrinks what pressing did not
}

TEST(PackingSimulation, BoundaryForcePushesOutsideVertexIn) {
  BoxSimulation scene;
  PackingSimulation& sim = scene.sim;
  sim.addMesh(squareMesh(), 0, {98, 50}, 0.0, 1.0);  // right edge at x = 103
  sim.finalize(area(100));
  sim.step();
  EXPECT_TRUE(sim.vertexOutsideContainer(1));
  EXPECT_LT(sim.forces()[1].x, 0.0);  // pulled back toward x = 100
  EXPECT_DOUBLE_EQ(sim.meshes()[0].growth, 1.0);  // no room: no growth
  for (int i = 0; i < 400; ++i) sim.step();
  for (Vec2 v : sim.positions()) EXPECT_LE(v.x, 100.0 + 1e-6);
}

TEST(PackingSimulation, RepulsionPushesNeighboursApart) {
  SimulationParameters still = boxParameters();
  still.growthRate = 0.0;
  BoxSimulation scene(still);
  PackingSimulation& sim = scene.sim;
  sim.addMesh(squareMesh(), 0, {40, 50}, 0.0, 1.0);
  sim.addMesh(squareMesh(), 0, {52, 50}, 0.0, 1.0);  // 2 units apart
  sim.finalize(area(100));
  double before = sim.positions()[4].x - sim.positions()[1].x;
  for (int i = 0; i < 50; ++i) sim.step();
  double after = sim.positions()[4].x - sim.positions()[1].x;
  EXPECT_GT(after, before);
  EXPECT_LT(sim.forces()[1].x, 0.0 + 1e-9);  // mesh 0's right side is pushed left (or at rest)
}

TEST(PackingSimulation, FrozenMeshDoesNotMove) {
  BoxSimulation scene;
  PackingSimulation& sim = scene.sim;
  sim.addMesh(squareMesh(), 0, {40, 50}, 0.0, 1.0, /*frozen=*/true);
  sim.addMesh(squareMesh(), 0, {52, 50}, 0.0, 1.0);
  sim.finalize(area(100));
  std::vector<Vec2> frozen(sim.positions().begin(), sim.positions().begin() + 4);
  for (int i = 0; i < 30; ++i) sim.step();
  for (int v = 0; v < 4; ++v) EXPECT_EQ(sim.positions()[v], frozen[v]);
  EXPECT_DOUBLE_EQ(sim.meshes()[0].growth, 1.0);
  EXPECT_GT(sim.meshes()[1].growth, 1.0);
}

TEST(PackingSimulation, ReflexCornersOfAnLShapePointInward) {
  // L-shape: one reflex corner at (50, 50); it points into the region, away from the missing
  // quadrant (x > 50, y > 50), along (-1, -1)/√2.
  Region l = {Polygon{{{0, 0}, {100, 0}, {100, 50}, {50, 50}, {50, 100}, {0, 100}}, {}}};
  auto corners = PackingSimulation::reflexCorners(l);
  ASSERT_EQ(corners.size(), 1u);
  EXPECT_EQ(corners[0].position, (Vec2{50, 50}));
  EXPECT_NEAR(corners[0].inward.x, -std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(corners[0].inward.y, -std::sqrt(0.5), 1e-12);
  // A convex square has none; a square hole's four corners all point into the region.
  EXPECT_TRUE(PackingSimulation::reflexCorners(box(100)).empty());
  Region withHole = {Polygon{{{0, 0}, {100, 0}, {100, 100}, {0, 100}}, {{{40, 40}, {60, 40}, {60, 60}, {40, 60}}}}};
  EXPECT_EQ(PackingSimulation::reflexCorners(withHole).size(), 4u);
}

TEST(PackingSimulation, ReflexCornerInsideAMeshPushesItOffAndBlocksGrowth) {
  Region l = {Polygon{{{0, 0}, {100, 0}, {100, 50}, {50, 50}, {50, 100}, {0, 100}}, {}}};
  RegionIndex index(l, 5.0);
  ThreadPool pool(1);
  SimulationParameters p = test::thesisParameters();
  p.cellSize = 20.0;
  PackingSimulation sim(index, area(l), p, pool);
  ElementMesh diamond;
  diamond.mesh.vertices = {{0, -8}, {8, 0}, {0, 8}, {-8, 0}};
  diamond.mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  diamond.boundaryCount = 4;
  for (auto [a, b] : {std::pair{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 2}})
    diamond.springs.push_back({a, b, distance(diamond.mesh.vertices[a], diamond.mesh.vertices[b]), SpringKind::Edge});
  diamond.skinArea = 128.0;
  // Centred at (47, 47): vertices (47, 39), (55, 47), (47, 55), (39, 47) are all inside the L,
  // but the edge from (55, 47) to (47, 55) passes outside, around the corner (50, 50).
  sim.addMesh(diamond, 0, {47, 47}, 0.0, 1.0);
  sim.setContainerCorners(PackingSimulation::reflexCorners(l));
  sim.finalize(area(100));
  for (int v = 0; v < 4; ++v) EXPECT_TRUE(pointInRegion(sim.positions()[v], l));
  sim.step();
  EXPECT_TRUE(sim.meshes()[0].outside);           // growth blocked
  EXPECT_DOUBLE_EQ(sim.meshes()[0].growth, 1.0);
  EXPECT_LT(sim.forces()[1].x + sim.forces()[2].x, 0.0);  // the crossing edge is pushed back
  for (int i = 0; i < 300; ++i) sim.step();
  // Pushed off: the corner is no longer inside the mesh.
  Ring skin(sim.positions().begin(), sim.positions().begin() + 4);
  EXPECT_FALSE(pointInRing({50, 50}, skin));
}

TEST(PackingSimulation, ProjectInsideMovesOnlyOutsideVerticesOfMovingMeshes) {
  BoxSimulation scene;
  PackingSimulation& sim = scene.sim;
  sim.addMesh(squareMesh(), 0, {97, 50}, 0.0, 1.0);  // x 92..102: two corners 2 units outside
  sim.addMesh(squareMesh(), 0, {50, 2}, 0.0, 1.0);   // y -3..7: outside too, but frozen
  sim.meshes()[1].frozen = true;
  sim.finalize(area(100));
  const std::vector<Vec2> before = sim.positions();
  EXPECT_EQ(sim.projectInside(), 2);
  const MeshInstance& moving = sim.meshes()[0];
  for (int v = 0; v < static_cast<int>(before.size()); ++v) {
    const Vec2 now = sim.positions()[static_cast<std::size_t>(v)], was = before[static_cast<std::size_t>(v)];
    if (v < moving.vertexBegin + moving.vertexCount && was.x > 100.0) {
      EXPECT_LT(now.x, 100.0);  // on the wall, a hair inside
      EXPECT_GT(now.x, 100.0 - 2e-3);
      EXPECT_DOUBLE_EQ(now.y, was.y);
      EXPECT_EQ(sim.velocities()[static_cast<std::size_t>(v)], Vec2{});
    } else {
      EXPECT_EQ(now, was) << v;
    }
  }
  EXPECT_EQ(sim.projectInside(), 0);  // nothing left outside
}

TEST(PackingSimulation, RestoreRestShapeGivesTheRestShapeFittedToTheVertices) {
  BoxSimulation scene;
  PackingSimulation& sim = scene.sim;
  sim.addMesh(squareMesh(), 0, {50, 50}, 0.0, 2.0);  // x, y 40..60
  sim.finalize(area(100));
  // Turn the square by 90° about (50, 50) and fold one corner across the opposite edge.
  std::vector<Vec2>& x = sim.positions();
  for (Vec2& v : x) v = Vec2{50.0 - (v.y - 50.0), 50.0 + (v.x - 50.0)};
  x[2] = Vec2{30.0, 65.0};
  const double inf = std::numeric_limits<double>::infinity();
  sim.restoreRestShape(0, 0.0, Vec2{}, inf);
  // A square of side 20 (rest 10 at growth 2) again, about the vertices' mean.
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(distance(x[k], x[(k + 1) % 4]), 20.0, 1e-9) << k;
  EXPECT_NEAR(distance(x[0], x[2]), 20.0 * std::sqrt(2.0), 1e-9);
  Vec2 mean;
  for (Vec2 v : x) mean += v / 4.0;
  EXPECT_NEAR(mean.x, 47.5, 1e-9);  // where the four were: (60 + 60 + 30 + 40) / 4
  EXPECT_NEAR(mean.y, 51.25, 1e-9);
  EXPECT_EQ(sim.velocities()[0], Vec2{});
}

TEST(PackingSimulation, RestoreRestShapeLeavesVerticesBeyondTheRadius) {
  BoxSimulation scene;
  PackingSimulation& sim = scene.sim;
  sim.addMesh(squareMesh(), 0, {50, 50}, 0.0, 1.0);  // x, y 45..55
  sim.finalize(area(100));
  std::vector<Vec2>& x = sim.positions();
  x[2] = Vec2{58.0, 58.0};  // pulled out of shape
  const std::vector<Vec2> before = x;
  sim.restoreRestShape(0, 0.5, Vec2{58.0, 58.0}, 6.0);  // only vertex 2 is within 6
  for (int k : {0, 1, 3}) EXPECT_EQ(x[k], before[k]) << k;
  // Vertex 2 alone has no rotation to fit: it goes halfway to its rest offset from itself,
  // which is where it is.
  EXPECT_NEAR(distance(x[2], before[2]), 0.0, 1e-9);
  sim.restoreRestShape(0, 0.5, Vec2{58.0, 58.0}, 16.0);  // now 1 and 3 (13.3 away) count too
  EXPECT_EQ(x[0], before[0]);
  EXPECT_LT(distance(x[2], Vec2{55.0, 55.0}), distance(before[2], Vec2{55.0, 55.0}));
}

TEST(PackingSimulation, HoldRestShapesMovesOnlyTheHeldMeshAndReleaseThawsTheRest) {
  BoxSimulation scene;
  PackingSimulation& sim = scene.sim;
  sim.addMesh(squareMesh(), 0, {44, 50}, 0.0, 1.0);                   // held: overlaps mesh 1
  sim.addMesh(squareMesh(), 0, {52, 50}, 0.0, 1.0);                   // stands still
  sim.addMesh(squareMesh(), 0, {20, 20}, 0.0, 1.0, /*frozen=*/true);  // frozen before, and after
  sim.finalize(area(100));
  sim.positions()[2] = Vec2{51.0, 57.0};  // mesh 0's corner pulled out of shape
  const std::vector<Vec2> before = sim.positions();
  sim.holdRestShapes({1, 0, 0}, 1.0);
  for (int i = 0; i < 30; ++i) sim.step();
  for (int v = 4; v < 12; ++v) EXPECT_EQ(sim.positions()[v], before[v]) << v;
  EXPECT_TRUE(sim.meshes()[1].frozen);
  // Held toward its square: the corner is nearer its rest place (49, 55) than it was.
  EXPECT_LT(distance(sim.positions()[2], sim.positions()[1] + Vec2{0.0, 10.0}),
            distance(before[2], before[1] + Vec2{0.0, 10.0}));
  sim.releaseHolds();
  EXPECT_FALSE(sim.meshes()[1].frozen);
  EXPECT_TRUE(sim.meshes()[2].frozen);
}

#ifndef NDEBUG  // assert() is on (PAK_ASSERTIONS, or a debug build)
TEST(PackingSimulationDeathTest, AssertsTheOrderAddFinalizeStep) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  Region container = box(100);
  RegionIndex index(container, 5.0);
  ThreadPool pool(1);
  SimulationParameters p;
  p.cellSize = 20.0;
  PackingSimulation sim(index, 10000.0, p, pool);
  sim.addMesh(squareMesh(), 0, {50, 50}, 0.0, 1.0);
  EXPECT_DEATH(sim.step(), "step only after finalize");
  sim.finalize(area(100));
  EXPECT_DEATH(sim.addMesh(squareMesh(), 0, {20, 20}, 0.0, 1.0), "added before finalize");
}

TEST(PackingSimulationDeathTest, AssertsFinitePositionsAfterAStep) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  Region container = box(100);
  RegionIndex index(container, 5.0);
  ThreadPool pool(1);
  SimulationParameters p;
  p.cellSize = 20.0;
  PackingSimulation sim(index, 10000.0, p, pool);
  sim.addMesh(squareMesh(), 0, {50, 50}, 0.0, 1.0);
  sim.finalize(area(100));
  sim.positions()[2].x = std::numeric_limits<double>::quiet_NaN();
  EXPECT_DEATH(sim.step(), "non-finite position");
}
#endif
