// The neighbour lists of the spacetime simulation are exact between rebuilds: every other
// element's nearest envelope point within reach is found from the lists, as a search of every
// triangle finds it, while no vertex has moved more than half the margin, however unevenly
// the vertices have moved.
#include "animation/spacetime_neighbours.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "pak/geom/closest_point_triangle.hpp"
#include "pak/geom/rng.hpp"

namespace pak {
namespace {

// Tubes of rings (skin only) wobbling in x, y over t, close enough to touch: `elements` of
// `slices` rings of `ring` vertices each, envelope triangles as SpacetimeSimulation builds them.
struct Tubes {
  static constexpr int kRing = 24, kSlices = 12;
  std::vector<Vec3> positions;
  SpacetimeNeighbours::Layout layout;

  explicit Tubes(int elements) {
    for (int e = 0; e < elements; ++e) {
      const Vec2 centre{300.0 + 95.0 * (e % 4), 300.0 + 95.0 * (e / 4)};
      const int begin = static_cast<int>(positions.size());
      for (int s = 0; s < kSlices; ++s)
        for (int k = 0; k < kRing; ++k) {
          const double angle = 2.0 * std::numbers::pi * k / kRing + 0.1 * s;
          const double r = 50.0 + 6.0 * std::sin(3.0 * angle + 0.4 * e);
          positions.push_back({centre.x + r * std::cos(angle) + 4.0 * std::sin(0.5 * s + e),
                               centre.y + r * std::sin(angle), 10.0 * s});
          layout.vertexElement.push_back(e);
          layout.isSkin.push_back(1);
        }
      for (int s = 0; s + 1 < kSlices; ++s)
        for (int k = 0; k < kRing; ++k) {
          const int a = begin + s * kRing + k, b = begin + s * kRing + (k + 1) % kRing, c = a + kRing, d = b + kRing;
          layout.triangles.push_back({a, b, c});
          layout.triangles.push_back({a, d, c});
          layout.triangleElement.push_back(e);
          layout.triangleElement.push_back(e);
        }
    }
    layout.area.add(Vec3{0, 0, 0});
    layout.area.add(Vec3{1000, 1000, 10.0 * (kSlices - 1)});
    layout.cellSize = 40.0;
    layout.shellReach = 100.0;
    layout.margin = 4.0;
  }
};

// Every element's nearest distance², by brute force over all its triangles.
double nearest2(const Tubes& tubes, const std::vector<Vec3>& x, int v, int element) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < tubes.layout.triangles.size(); ++i) {
    if (tubes.layout.triangleElement[i] != element) continue;
    const auto& c = tubes.layout.triangles[i];
    best = std::min(best, lengthSquared(closestPointOnTriangle(x[v], x[c[0]], x[c[1]], x[c[2]]) - x[v]));
  }
  return best;
}

TEST(SpacetimeNeighbours, ListsFindEveryNearestPointWithinReachUntilStale) {
  constexpr int kElements = 8;
  Tubes tubes(kElements);
  ThreadPool pool(2);
  SpacetimeNeighbours neighbours(tubes.layout, pool);
  neighbours.rebuild(tubes.positions);
  Rng rng(7);
  std::vector<Vec3> moved = tubes.positions;
  int exactHits = 0;
  for (int round = 0; round < 3; ++round) {
    // Each vertex moves by up to just under half the margin from where the lists were built;
    // half of them hardly at all, as late in a run (gather's bounds use each one's move).
    for (std::size_t v = 0; v < moved.size(); ++v) {
      const double angle = rng.uniform(0.0, 2.0 * std::numbers::pi);
      const double reach = rng.uniform(0.0, 1.0) < 0.5 ? rng.uniform(0.0, 0.1) : rng.uniform(0.0, 1.99);
      moved[v] = tubes.positions[v] + Vec3{reach * std::cos(angle), reach * std::sin(angle), 0.0};
    }
    ASSERT_FALSE(neighbours.track(moved));
    for (int v = 0; v < static_cast<int>(moved.size()); ++v) {
      SpacetimeNeighbours::Hits hits;
      neighbours.gather(v, moved, hits);
      const int self = tubes.layout.vertexElement[v];
      for (int e = 0; e < kElements; ++e) {
        if (e == self) continue;
        const double truth = nearest2(tubes, moved, v, e);
        const int k = hits.find(e);
        if (truth < 40.0 * 40.0) {
          ASSERT_GE(k, 0) << "vertex " << v << " missed element " << e;
          ASSERT_TRUE(hits[k].exact);
          ASSERT_EQ(hits[k].d2, truth);
          ++exactHits;
        } else if (k >= 0) {
          ASSERT_FALSE(hits[k].exact);  // beyond reach: at most a shell centre
          ASSERT_LT(hits[k].d2, 100.0 * 100.0);
        }
      }
    }
  }
  EXPECT_GT(exactHits, 1000);  // the tubes do come within reach of each other
  // One vertex a little more than half the margin away: time to rebuild.
  moved = tubes.positions;
  moved[5].x += 2.01;
  EXPECT_TRUE(neighbours.track(moved));
}

TEST(SpacetimeNeighbours, TheSameWithAnyThreadCount) {
  Tubes tubes(8);
  ThreadPool one(1), two(2);
  SpacetimeNeighbours a(tubes.layout, one), b(tubes.layout, two);
  a.rebuild(tubes.positions);
  b.rebuild(tubes.positions);
  for (int v = 0; v < static_cast<int>(tubes.positions.size()); ++v) {
    SpacetimeNeighbours::Hits ha, hb;
    a.gather(v, tubes.positions, ha);
    b.gather(v, tubes.positions, hb);
    ASSERT_EQ(ha.size(), hb.size());
    for (int k = 0; k < ha.size(); ++k) {
      ASSERT_EQ(ha[k].element, hb[k].element);
      ASSERT_EQ(ha[k].d2, hb[k].d2);
      ASSERT_EQ(ha[k].point, hb[k].point);
    }
  }
}

}  // namespace
}  // namespace pak
