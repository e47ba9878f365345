#include "repulsion/packing_simulation.hpp"

#include <gtest/gtest.h>

using namespace pak;

namespace {

// A 10 × 10 square mesh centred at the origin: 4 boundary vertices, 2 triangles, 5 springs.
ElementMesh squareMesh() {
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

Region box(double size) { return {Polygon{{{0, 0}, {size, 0}, {size, size}, {0, size}}, {}}}; }

Box area(double size) {
  Box b;
  b.add(Vec2{-size * 0.2, -size * 0.2});
  b.add(Vec2{size * 1.2, size * 1.2});
  return b;
}

}  // namespace

TEST(PackingSimulation, LoneMeshGrowsByRateTimesStep) {
  Region container = box(100);
  RegionIndex index(container, 5.0);
  ThreadPool pool(1);
  SimulationParameters p;
  p.cellSize = 20.0;
  PackingSimulation sim(index, 10000.0, p, pool);
  sim.addMesh(squareMesh(), 0, {50, 50}, 0.0, 0.5);
  sim.finalize(area(100));
  EXPECT_NEAR(sim.fill(), 0.0025, 1e-12);  // (10 × 0.5)² / 100²
  sim.step();
  EXPECT_NEAR(sim.meshes()[0].growth, 0.5 + p.growthRate * p.timeStep, 1e-12);
  EXPECT_EQ(sim.growingCount(), 1);
}

TEST(PackingSimulation, GrowthIsBlockedWhileOverlapping) {
  Region container = box(100);
  RegionIndex index(container, 5.0);
  ThreadPool pool(1);
  SimulationParameters p;
  p.cellSize = 20.0;
  PackingSimulation sim(index, 10000.0, p, pool);
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

TEST(PackingSimulation, BoundaryForcePushesOutsideVertexIn) {
  Region container = box(100);
  RegionIndex index(container, 5.0);
  ThreadPool pool(1);
  SimulationParameters p;
  p.cellSize = 20.0;
  PackingSimulation sim(index, 10000.0, p, pool);
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
  Region container = box(100);
  RegionIndex index(container, 5.0);
  ThreadPool pool(1);
  SimulationParameters p;
  p.cellSize = 20.0;
  p.growthRate = 0.0;
  PackingSimulation sim(index, 10000.0, p, pool);
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
  Region container = box(100);
  RegionIndex index(container, 5.0);
  ThreadPool pool(1);
  SimulationParameters p;
  p.cellSize = 20.0;
  PackingSimulation sim(index, 10000.0, p, pool);
  sim.addMesh(squareMesh(), 0, {40, 50}, 0.0, 1.0, /*frozen=*/true);
  sim.addMesh(squareMesh(), 0, {52, 50}, 0.0, 1.0);
  sim.finalize(area(100));
  std::vector<Vec2> frozen(sim.positions().begin(), sim.positions().begin() + 4);
  for (int i = 0; i < 30; ++i) sim.step();
  for (int v = 0; v < 4; ++v) EXPECT_EQ(sim.positions()[v], frozen[v]);
  EXPECT_DOUBLE_EQ(sim.meshes()[0].growth, 1.0);
  EXPECT_GT(sim.meshes()[1].growth, 1.0);
}
