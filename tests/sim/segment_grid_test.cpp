#include "sim/segment_grid.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

using namespace pak;

namespace {
// A grid of 10-unit cells over [0, 100]², holding the segments ends[2s] → ends[2s + 1] of p.
SegmentGrid gridOver(const std::vector<Vec2>& p, const std::vector<int>& ends) {
  const std::size_t segments = ends.size() / 2;
  SegmentGrid grid;
  Box area;
  area.add(Vec2{0, 0});
  area.add(Vec2{100, 100});
  grid.configure(area, 10.0, segments);
  grid.rebuild(p.data(), ends.data(), segments);
  return grid;
}
}  // namespace

TEST(SegmentGrid, FindsExactlyTheSegmentsInTheWindow) {
  std::vector<Vec2> p = {{5, 5}, {8, 5}, {55, 55}, {58, 58}, {95, 5}, {95, 15}};
  std::vector<int> ends = {0, 1, 2, 3, 4, 5};
  SegmentGrid grid = gridOver(p, ends);
  std::set<int> near;
  grid.forEachNear({12, 12}, 1, [&](int s) { near.insert(s); });
  EXPECT_EQ(near, std::set<int>({0}));
  near.clear();
  grid.forEachNear({50, 50}, 1, [&](int s) { near.insert(s); });
  EXPECT_EQ(near, std::set<int>({1}));
  near.clear();
  // Segment 2 spans two cells vertically; either cell's window finds it.
  grid.forEachNear({95, 25}, 0, [&](int s) { near.insert(s); });
  EXPECT_TRUE(near.empty());
  grid.forEachNear({95, 12}, 0, [&](int s) { near.insert(s); });
  EXPECT_EQ(near, std::set<int>({2}));
  // Points outside the area are clamped to border cells.
  near.clear();
  grid.forEachNear({-50, -50}, 0, [&](int s) { near.insert(s); });
  EXPECT_EQ(near, std::set<int>({0}));
}

TEST(SegmentGrid, RebuildFollowsMovedSegments) {
  std::vector<Vec2> p = {{5, 5}, {6, 6}};
  std::vector<int> ends = {0, 1};
  SegmentGrid grid = gridOver(p, ends);
  p = {{75, 75}, {76, 76}};
  grid.rebuild(p.data(), ends.data(), 1);
  int hits = 0;
  grid.forEachNear({5, 5}, 1, [&](int) { ++hits; });
  EXPECT_EQ(hits, 0);
  grid.forEachNear({75, 75}, 0, [&](int) { ++hits; });
  EXPECT_EQ(hits, 1);
}

TEST(SegmentGrid, VisitsASegmentSpanningSeveralCellsOnceInScanOrder) {
  // Segment 0 spans 3 × 3 cells; segment 1 lies in one cell below-right of its first one.
  std::vector<Vec2> p = {{5, 5}, {25, 25}, {35, 35}, {36, 36}};
  std::vector<int> ends = {0, 1, 2, 3};
  SegmentGrid grid = gridOver(p, ends);
  for (Vec2 at : {Vec2{15, 15}, Vec2{25, 25}, Vec2{5, 25}, Vec2{35, 35}}) {
    std::vector<int> seen;
    grid.forEachNear(at, 1, [&](int s) { seen.push_back(s); });
    const int zeros = static_cast<int>(std::count(seen.begin(), seen.end(), 0));
    EXPECT_EQ(zeros, 1) << at.x << "," << at.y;
  }
  std::vector<int> seen;
  grid.forEachNear({30, 30}, 1, [&](int s) { seen.push_back(s); });
  EXPECT_EQ(seen, (std::vector<int>{0, 1}));  // row 2 holds segment 0 before row 3 holds 1
}
