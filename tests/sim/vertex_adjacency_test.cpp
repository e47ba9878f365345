#include "sim/vertex_adjacency.hpp"

#include <gtest/gtest.h>

#include <array>
#include <utility>
#include <vector>

using namespace pak;

namespace {

std::vector<int> listAt(const VertexAdjacency<int>& a, std::size_t v) {
  return {a.of(v).begin(), a.of(v).end()};
}

}  // namespace

TEST(VertexAdjacency, EdgesOfASmallGraphAtBothEnds) {
  // Path 0–1–2 plus edge 0–3; vertex 4 has none. Each vertex lists its neighbours in edge order.
  const std::vector<std::pair<int, int>> edges = {{0, 1}, {1, 2}, {3, 0}};
  const VertexAdjacency<int> a = buildVertexAdjacency<int>(5, [&](auto&& emit) {
    for (auto [u, w] : edges) {
      emit(u, w);
      emit(w, u);
    }
  });
  EXPECT_EQ(a.start, (std::vector<int>{0, 2, 4, 5, 6, 6}));
  EXPECT_EQ(a.entries, (std::vector<int>{1, 3, 0, 2, 1, 0}));
  EXPECT_EQ(listAt(a, 0), (std::vector<int>{1, 3}));
  EXPECT_EQ(listAt(a, 1), (std::vector<int>{0, 2}));
  EXPECT_TRUE(a.of(4).empty());
  EXPECT_EQ(a.vertexCount(), 5u);
}

TEST(VertexAdjacency, TrianglesByVertex) {
  // Two triangles sharing the edge 1–2.
  const std::vector<std::array<int, 3>> triangles = {{0, 1, 2}, {2, 1, 3}};
  const VertexAdjacency<int> a = buildVertexAdjacency<int>(4, [&](auto&& emit) {
    for (int t = 0; t < 2; ++t)
      for (int v : triangles[t]) emit(v, t);
  });
  EXPECT_EQ(listAt(a, 0), (std::vector<int>{0}));
  EXPECT_EQ(listAt(a, 1), (std::vector<int>{0, 1}));
  EXPECT_EQ(listAt(a, 2), (std::vector<int>{0, 1}));
  EXPECT_EQ(listAt(a, 3), (std::vector<int>{1}));
}
