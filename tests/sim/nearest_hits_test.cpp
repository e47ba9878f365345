#include "sim/nearest_hits.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

using namespace pak;

namespace {

struct TestHit {
  int element;
  double d2;
  int key() const { return element; }
  bool nearerThan(const TestHit& other) const { return d2 < other.d2; }
};

std::vector<int> elementsOf(const NearestHitList<TestHit, 3>& hits) {
  std::vector<int> elements;
  for (const TestHit& h : hits) elements.push_back(h.element);
  std::sort(elements.begin(), elements.end());
  return elements;
}

}  // namespace

TEST(NearestHitList, KeepsTheNearestHitOfEachElement) {
  NearestHitList<TestHit, 3> hits;
  hits.offer({7, 9.0});
  hits.offer({7, 4.0});
  hits.offer({7, 6.0});
  hits.offer({2, 1.0});
  ASSERT_EQ(hits.size(), 2);
  EXPECT_EQ(hits[hits.find(7)].d2, 4.0);
  EXPECT_EQ(hits[hits.find(2)].d2, 1.0);
  EXPECT_EQ(hits.find(5), -1);
}

TEST(NearestHitList, WhenFullANearerElementReplacesTheFarthest) {
  NearestHitList<TestHit, 3> hits;
  hits.offer({1, 5.0});
  hits.offer({2, 9.0});
  hits.offer({3, 7.0});
  EXPECT_TRUE(hits.full());
  hits.offer({4, 8.0});  // nearer than element 2's 9
  EXPECT_EQ(elementsOf(hits), (std::vector<int>{1, 3, 4}));
  hits.offer({5, 20.0});  // farther than all: dropped
  EXPECT_EQ(elementsOf(hits), (std::vector<int>{1, 3, 4}));
  hits.offer({6, 0.5});  // replaces element 4 (8), now the farthest
  EXPECT_EQ(elementsOf(hits), (std::vector<int>{1, 3, 6}));
  EXPECT_EQ(hits.size(), 3);
}

TEST(NearestHitList, OrderDecidesWhatNearerMeans) {
  // AnimationPak's order: an exact hit beats any approximate one.
  struct Ranked {
    int element;
    double d2;
    bool exact;
    int key() const { return element; }
    bool nearerThan(const Ranked& o) const { return (exact && !o.exact) || (exact == o.exact && d2 < o.d2); }
  };
  NearestHitList<Ranked, 2> hits;
  hits.offer({1, 1.0, false});
  hits.offer({2, 50.0, true});
  hits.offer({3, 60.0, true});  // full: replaces the approximate hit of element 1
  EXPECT_EQ(hits.find(1), -1);
  EXPECT_GE(hits.find(3), 0);
  hits.offer({2, 0.1, false});  // approximate: does not replace element 2's exact hit
  EXPECT_EQ(hits[hits.find(2)].d2, 50.0);
}
