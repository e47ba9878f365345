// The spacetime simulation's hard constraints (thesis 5.5.2), determinism and checkpoints.
#include "animation/spacetime_simulation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <numbers>

#include "animation/animation_fixtures.hpp"
#include "sim/canonical_frame.hpp"

namespace pak {
namespace {

// The fixtures' five-pointed star, centred and three times as large, meshed with `symmetry`.
ElementMesh starMesh(int symmetry = 1) {
  std::vector<Shape> art = test::starElement("star").shapes;
  for (Shape& s : art)
    for (Vec2& p : s.subpaths[0].points) p = (p - Vec2{50, 50}) * 3.0;
  ElementMeshOptions meshOptions;
  meshOptions.gap = 8.0;
  meshOptions.spacing = 25.0;
  meshOptions.symmetry = symmetry;
  return buildElementMesh(art, {Polygon{art[0].subpaths[0].points, {}}}, meshOptions);
}

// Two elements of one star mesh in a disc; element 0 loops to element 1 and 1 to 0.
struct TwoTubes {
  ElementMesh mesh;
  Region container{Polygon{test::discRing({500, 500}, 450), {}}};
  RegionIndex index{container, 10.0};
  ThreadPool pool;
  SpacetimeSimulation sim;
  static constexpr int kSlices = 6;

  explicit TwoTubes(int threads, double timeStrength = 4.0, bool crossLoop = true,
                    double growthSpeedCap = SpacetimeParameters{}.growthSpeedCap)
      : pool(threads),
        sim(index, area(container), kSlices, parameters(), spacetime(timeStrength, growthSpeedCap), pool) {
    mesh = starMesh();
    for (Vec2 at : {Vec2{420, 500}, Vec2{600, 500}}) {
      SpacetimeElementSetup setup;
      setup.mesh = &mesh;
      for (int s = 0; s < kSlices; ++s) {
        for (Vec2 p : mesh.mesh.vertices) setup.reference.push_back(at + rotated(p, 0.2 * s) + Vec2{10.0 * s, 0});
        setup.referenceCentre.push_back(at + Vec2{10.0 * s, 0});
      }
      setup.initialGrowth = 0.5;
      sim.addElement(setup);
    }
    if (crossLoop) {
      sim.addLoop(0, 1, {1.0, 0.0});
      sim.addLoop(1, 0, {1.0, 0.0});
    }
    sim.finalize(Box{{0, 0}, {1000, 1000}});
  }
  static SimulationParameters parameters() {
    SimulationParameters p = AnimationOptions{}.simulation;
    p.growthRate = 0.05;
    return p;
  }
  static SpacetimeParameters spacetime(double timeStrength, double growthSpeedCap) {
    SpacetimeParameters p;
    p.timeStrength = timeStrength;
    p.growthSpeedCap = growthSpeedCap;
    return p;
  }
};

TEST(SpacetimeSimulation, SliceConstraintsHoldAfterEveryStep) {
  TwoTubes tubes(1);
  const int n = tubes.sim.verticesPerSlice(0);
  const double T = SpacetimeParameters{}.timeLength;
  for (int step = 0; step < 40; ++step) {
    tubes.sim.step();
    const auto& x = tubes.sim.positions();
    for (int e = 0; e < 2; ++e) {
      const int begin = tubes.sim.vertexBegin(e);
      for (int s = 0; s < TwoTubes::kSlices; ++s) {
        const double t0 = x[begin + s * n].t;
        if (s == 0) { ASSERT_EQ(t0, 0.0); }  // end-to-end
        if (s == TwoTubes::kSlices - 1) { ASSERT_EQ(t0, T); }
        for (int v = 0; v < n; ++v) ASSERT_EQ(x[begin + s * n + v].t, t0) << "simultaneity, slice " << s;
      }
    }
    // Loops: element 0's last slice on element 1's first and the other way round.
    const int last = (TwoTubes::kSlices - 1) * n;
    for (int v = 0; v < n; ++v) {
      EXPECT_EQ(spatial(x[tubes.sim.vertexBegin(0) + last + v]), spatial(x[tubes.sim.vertexBegin(1) + v]));
      EXPECT_EQ(spatial(x[tubes.sim.vertexBegin(1) + last + v]), spatial(x[tubes.sim.vertexBegin(0) + v]));
    }
  }
}

TEST(SpacetimeSimulation, LoopWithATurnJoinsTheSlicesUpToThatTurn) {
  // Element 0's reference turns by 0.2 rad per slice: its last slice is its first turned by
  // 1 rad, and the loop must keep exactly that relation (not squeeze the shape).
  TwoTubes tubes(1, 4.0, false);
  const int n = tubes.sim.verticesPerSlice(0);
  std::vector<Vec2> first, last;
  for (int v = 0; v < n; ++v) {
    first.push_back(rotated(tubes.mesh.mesh.vertices[v], 0.0));
    last.push_back(rotated(tubes.mesh.mesh.vertices[v], 0.2 * (TwoTubes::kSlices - 1)));
  }
  const Vec2 turn = SpacetimeSimulation::loopTurn(first.data(), last.data(), n);
  EXPECT_NEAR(turn.x, std::cos(1.0), 1e-12);
  EXPECT_NEAR(turn.y, std::sin(1.0), 1e-12);
}

TEST(SpacetimeSimulation, SymmetricMeshJoinsATurnedLoopPointForPoint) {
  // A five-pointed star with a mesh of its symmetry, turned by 72° over the loop and pressed
  // against the container's wall: the last slice's vertex i joins the first slice's vertex at
  // its place, so the two slices are one outline in the container. The turned join of a plain
  // loop keeps the first slice's dents turned by 72° instead.
  constexpr int kSlices = 6;
  const ElementMesh mesh = starMesh(5);
  ASSERT_EQ(mesh.symmetry, 5);
  const int n = static_cast<int>(mesh.mesh.vertices.size());
  const Vec2 at{860, 500};
  std::vector<Vec2> reference;
  for (int s = 0; s < kSlices; ++s)
    for (Vec2 p : mesh.mesh.vertices) reference.push_back(at + rotated(p, 0.4 * std::numbers::pi * s / (kSlices - 1)));
  const Vec2* first = reference.data();
  const Vec2* last = first + (kSlices - 1) * n;
  const std::vector<int> partner = SpacetimeSimulation::loopPartners(first, last, n);
  ASSERT_EQ(static_cast<int>(partner.size()), n);
  for (int i = 0; i < n; ++i) EXPECT_NEAR(distance(first[partner[i]], last[i]), 0.0, 1e-9);
  const Vec2 left = SpacetimeSimulation::loopTurn(first, last, n, partner.data());
  EXPECT_NEAR(left.x, 1.0, 1e-12);  // nothing of the turn is left
  EXPECT_NEAR(left.y, 0.0, 1e-12);

  // The largest distance between the last slice's vertex i and the first slice's partner[i]
  // after 40 steps, with the loop joined by partners or by the turn.
  auto apart = [&](bool byPartner) {
    Region container{Polygon{test::discRing({500, 500}, 450), {}}};
    RegionIndex index{container, 10.0};
    ThreadPool pool(1);
    SimulationParameters parameters = AnimationOptions{}.simulation;
    parameters.growthRate = 0.05;
    SpacetimeParameters spacetime;
    spacetime.growthSpeedCap = 0.0;  // the growth at 0.05 presses the star on the wall in 40 steps
    SpacetimeSimulation sim(index, area(container), kSlices, parameters, spacetime, pool);
    SpacetimeElementSetup setup;
    setup.mesh = &mesh;
    setup.reference = reference;
    setup.referenceCentre.assign(kSlices, at);
    setup.initialGrowth = 0.5;
    sim.addElement(setup);
    if (byPartner)
      sim.addLoop(0, 0, left, {}, partner);
    else
      sim.addLoop(0, 0, SpacetimeSimulation::loopTurn(first, last, n));
    sim.finalize(Box{{0, 0}, {1000, 1000}});
    for (int step = 0; step < 40; ++step) sim.step();
    double most = 0.0;
    for (int i = 0; i < n; ++i)
      most = std::max(most, distance(spatial(sim.positions()[(kSlices - 1) * n + i]), spatial(sim.positions()[partner[i]])));
    return most;
  };
  EXPECT_LT(apart(true), 1e-9);
  EXPECT_GT(apart(false), 0.1);
}

TEST(SpacetimeSimulation, LoopPartnersNeedTheTurnsSymmetry) {
  // The same star's plain mesh, turned by 72°: some vertex has no partner, so the loop keeps
  // the turned join. With no turn every vertex is its own partner: no table either.
  ElementArt star = test::starElement("star");
  ElementMeshOptions meshOptions;
  meshOptions.gap = 8.0;
  meshOptions.spacing = 10.0;
  const ElementMesh mesh = buildElementMesh(star.shapes, star.outline, meshOptions);
  std::vector<Vec2> first, last;
  for (Vec2 p : mesh.mesh.vertices) first.push_back(p), last.push_back(rotated(p, 0.4 * std::numbers::pi));
  const int n = static_cast<int>(first.size());
  EXPECT_TRUE(SpacetimeSimulation::loopPartners(first.data(), last.data(), n).empty());
  EXPECT_TRUE(SpacetimeSimulation::loopPartners(first.data(), first.data(), n).empty());
}

TEST(SpacetimeSimulation, GrowsFreeSlicesAndKeepsTubesApart) {
  TwoTubes tubes(1, 4.0, false);
  const double before = tubes.sim.minGrowth();
  for (int step = 0; step < 50; ++step) tubes.sim.step();
  EXPECT_GT(tubes.sim.minGrowth(), before);
  EXPECT_EQ(tubes.sim.overlappingSlices(), 0);
  for (const Vec3& p : tubes.sim.positions()) ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.t));
}

TEST(SpacetimeSimulation, GrowthMovesALargeSkinNoFasterThanTheSpeedCap) {
  // The star's skin lies about 100 units from its centre: at k_g = 0.05 a step of growth
  // would move it about 0.5, past the velocity cap's 0.2 a step.
  const SimulationParameters p = TwoTubes::parameters();
  const double cap = 1.2;
  TwoTubes capped(1, 4.0, false, cap), uncapped(1, 4.0, false, 0.0);
  const ElementMesh& mesh = capped.mesh;
  double radius = 0.0;
  for (int v = 0; v < mesh.boundaryCount; ++v) radius += length(mesh.mesh.vertices[v]);
  radius /= mesh.boundaryCount;
  ASSERT_GT(p.growthRate * radius, cap * p.velocityCap);  // the cap binds
  const double g0 = capped.sim.growth()[0];
  capped.sim.step();
  uncapped.sim.step();
  // Slice 0 of element 0 is free: one step of growth, at the capped rate or the common one.
  EXPECT_NEAR(capped.sim.growth()[0] - g0, cap * p.velocityCap / radius * p.timeStep, 1e-12);
  EXPECT_NEAR(uncapped.sim.growth()[0] - g0, p.growthRate * p.timeStep, 1e-12);
  // The skin moved by the growth step times its distance, at most cap × v_max Δt.
  EXPECT_LE((capped.sim.growth()[0] - g0) * radius, cap * p.velocityCap * p.timeStep + 1e-12);
}

TEST(SpacetimeSimulation, SameResultWithOneOrTwoThreads) {
  TwoTubes one(1), two(2);
  for (int step = 0; step < 30; ++step) one.sim.step(), two.sim.step();
  ASSERT_EQ(one.sim.positions().size(), two.sim.positions().size());
  for (std::size_t v = 0; v < one.sim.positions().size(); ++v) ASSERT_EQ(one.sim.positions()[v], two.sim.positions()[v]);
  EXPECT_EQ(one.sim.growth(), two.sim.growth());
}

TEST(SpacetimeSimulation, RestoredStateContinuesBitIdentically) {
  TwoTubes straight(1), resumed(1);
  for (int step = 0; step < 15; ++step) straight.sim.step();
  resumed.sim.restoreState(straight.sim.iteration(), straight.sim.positions(), straight.sim.velocities(), straight.sim.growth(),
                           straight.sim.previousGrowth(), straight.sim.neighbourOrigin());
  for (int step = 0; step < 15; ++step) straight.sim.step(), resumed.sim.step();
  EXPECT_EQ(resumed.sim.iteration(), straight.sim.iteration());
  for (std::size_t v = 0; v < straight.sim.positions().size(); ++v)
    ASSERT_EQ(straight.sim.positions()[v], resumed.sim.positions()[v]);
}

TEST(SpacetimeSimulation, StiffTimeSpringsKeepConsecutiveSlicesCloser) {
  // Thesis Fig. 5.21: stronger time springs, smoother motion. Measured as the mean jump of a
  // vertex between consecutive slices relative to the reference motion.
  auto jitter = [](double k) {
    TwoTubes tubes(1, k);
    for (int step = 0; step < 60; ++step) tubes.sim.step();
    const int n = tubes.sim.verticesPerSlice(0);
    const auto& x = tubes.sim.positions();
    double sum = 0.0;
    for (int s = 1; s + 1 < TwoTubes::kSlices; ++s)
      for (int v = 0; v < n; ++v) {
        const Vec2 a = spatial(x[s * n + v] - x[(s - 1) * n + v]), b = spatial(x[(s + 1) * n + v] - x[s * n + v]);
        sum += length(b - a);  // second difference: how much the motion changes between slices
      }
    return sum;
  };
  EXPECT_LT(jitter(40.0), jitter(0.05));
}

#ifndef NDEBUG  // assert() is on (PAK_ASSERTIONS, or a debug build)
TEST(SpacetimeSimulationDeathTest, AssertsTheOrderAddFinalizeStep) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const Region container{Polygon{test::discRing({500, 500}, 450), {}}};
  const RegionIndex index(container, 10.0);
  ThreadPool pool(1);
  SpacetimeSimulation unfinished(index, area(container), 4, SimulationParameters{.cellSize = 40.0}, SpacetimeParameters{}, pool);
  EXPECT_DEATH(unfinished.step(), "step only after finalize");
  TwoTubes tubes(1);  // finalized
  SpacetimeElementSetup setup;
  setup.mesh = &tubes.mesh;
  EXPECT_DEATH(tubes.sim.addElement(setup), "added before finalize");
}

TEST(SpacetimeSimulationDeathTest, AssertsFinitePositionsAfterAStep) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  TwoTubes tubes(1);
  std::vector<Vec3> positions = tubes.sim.positions();
  positions[3].x = std::numeric_limits<double>::quiet_NaN();
  tubes.sim.restoreState(0, positions, tubes.sim.velocities(), tubes.sim.growth(), tubes.sim.previousGrowth(),
                         tubes.sim.neighbourOrigin());
  EXPECT_DEATH(tubes.sim.step(), "non-finite position");
}
#endif

}  // namespace
}  // namespace pak
