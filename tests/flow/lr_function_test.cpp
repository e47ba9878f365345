#include "pak/flow/lr_function.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "pak/error.hpp"

namespace pak {
namespace {

Region rectangle(double x0, double y0, double x1, double y1) {
  return {Polygon{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}}};
}

// The asymmetric triangle of the reflection tests: L(a) = 2(1 - a/4), R(a) = 1 - a/4 about
// the spine (0,0)-(4,0).
Region triangle() { return {Polygon{{{0, -1}, {4, 0}, {0, 2}}, {}}}; }

Region mapped(const Region& region, Vec2 (*f)(Vec2)) {
  Region out = region;
  for (Polygon& p : out)
    for (Vec2& v : p.outer) v = f(v);
  normalizeOrientation(out);
  return out;
}

TEST(LRFunction, RectangleAboutItsMidlineIsHalfHeightEverywhere) {
  const double w = 6.0, h = 2.0;
  LRFunction f = elementLRFunction(rectangle(1, -h / 2, 1 + w, h / 2), {0, 0}, {1, 0}, 100);
  ASSERT_EQ(f.left.size(), 100u);
  EXPECT_NEAR(f.length, w, 1e-12);
  for (int i = 0; i < 100; ++i) {
    EXPECT_NEAR(f.left[i], h / 2, 1e-12);
    EXPECT_NEAR(f.right[i], h / 2, 1e-12);
    EXPECT_NEAR(f.normalisedLeft[i], 1.0, 1e-12);
    EXPECT_NEAR(f.normalisedRight[i], 1.0, 1e-12);
  }
  EXPECT_NEAR(f.maxLeft, h / 2, 1e-12);
}

TEST(LRFunction, TiltedSpineMeasuresInItsOwnFrame) {
  // The same rectangle turned by 30 degrees with its spine: same function.
  const double c = std::cos(0.5236), s = std::sin(0.5236);
  Region r = rectangle(0, -1, 6, 1);
  for (Vec2& v : r[0].outer) v = {c * v.x - s * v.y + 3, s * v.x + c * v.y - 2};
  LRFunction f = elementLRFunction(r, {3, -2}, {3 + c, -2 + s}, 50);
  EXPECT_NEAR(f.length, 6.0, 1e-9);
  for (int i = 0; i < 50; ++i) {
    EXPECT_NEAR(f.left[i], 1.0, 1e-9);
    EXPECT_NEAR(f.right[i], 1.0, 1e-9);
  }
}

TEST(LRFunction, HalfDiscIsOneSidedWithTheCircleAsItsLeftFunction) {
  const double r = 5.0;
  const int n = 512;
  Ring ring;
  for (int k = 0; k <= n; ++k) {  // upper half: left of the +x spine
    double t = std::numbers::pi * k / n;
    ring.push_back({r * std::cos(t), r * std::sin(t)});
  }
  LRFunction f = elementLRFunction({Polygon{ring, {}}}, {-r, 0}, {r, 0}, 100);
  EXPECT_NEAR(f.length, 2 * r, 1e-9);
  for (int i = 0; i < 100; ++i) {
    double a = -r + (i + 0.5) / 100 * 2 * r;
    EXPECT_NEAR(f.left[i], std::sqrt(r * r - a * a), 1e-3 * r) << i;
    EXPECT_EQ(f.right[i], 0.0);
    EXPECT_EQ(f.normalisedRight[i], 0.0);
  }
  EXPECT_EQ(f.maxRight, 0.0);
  EXPECT_NEAR(f.maxLeft, r, 1e-3 * r);
}

TEST(LRFunction, HoleIsInsideTheExtentAndTheFarthestCrossingCounts) {
  // A ring with a hole still extends to its outer boundary.
  Region r = rectangle(0, -2, 4, 2);
  r[0].holes.push_back({{1, -1}, {1, 1}, {3, 1}, {3, -1}});
  LRFunction f = elementLRFunction(r, {0, 0}, {4, 0}, 10);
  for (int i = 0; i < 10; ++i) {
    EXPECT_NEAR(f.left[i], 2.0, 1e-12);
    EXPECT_NEAR(f.right[i], 2.0, 1e-12);
  }
}

TEST(LRFunction, FourReflectionsOfAnAsymmetricElementDiffer) {
  const int n = 40;
  LRFunction f = elementLRFunction(triangle(), {0, 0}, {4, 0}, n);
  for (int i = 0; i < n; ++i) {
    double a = (i + 0.5) / n * 4;
    EXPECT_NEAR(f.left[i], 2 * (1 - a / 4), 1e-12);
    EXPECT_NEAR(f.right[i], 1 - a / 4, 1e-12);
  }
  const Reflection all[] = {Reflection::None, Reflection::AcrossSpine, Reflection::AlongSpine, Reflection::Both};
  for (Reflection a : all)
    for (Reflection b : all) {
      double cost = matchCost(f, a, reflected(f, b));
      if (a == b) EXPECT_NEAR(cost, 0.0, 1e-20);
      else EXPECT_GT(cost, 1.0);  // distinct functions, by a clear margin
    }
  LRFunction along = reflected(f, Reflection::AlongSpine);
  EXPECT_DOUBLE_EQ(along.left.front(), f.left.back());
  LRFunction across = reflected(f, Reflection::AcrossSpine);
  EXPECT_EQ(across.left, f.right);
  EXPECT_EQ(across.maxLeft, f.maxRight);
}

TEST(LRFunction, BestMatchFindsTheReflectedElementInItsOwnShapeAsABlob) {
  const int n = 100;
  std::vector<LRFunction> candidates = {elementLRFunction(rectangle(0, -1, 4, 1), {0, 0}, {4, 0}, n),
                                        elementLRFunction(triangle(), {0, 0}, {4, 0}, n)};
  Polyline streamline = {{0, 0}, {1.5, 0}, {4, 0}};
  struct Case { Reflection reflection; Vec2 (*map)(Vec2); };
  const Case cases[] = {
      {Reflection::None, [](Vec2 p) { return p; }},
      {Reflection::AcrossSpine, [](Vec2 p) { return Vec2{p.x, -p.y}; }},
      {Reflection::AlongSpine, [](Vec2 p) { return Vec2{4 - p.x, p.y}; }},
      {Reflection::Both, [](Vec2 p) { return Vec2{4 - p.x, -p.y}; }},
  };
  for (const Case& c : cases) {
    LRFunction blob = blobLRFunction(mapped(triangle(), c.map), streamline, n);
    LRMatch match = bestMatch(candidates, blob);
    EXPECT_EQ(match.candidate, 1);
    EXPECT_EQ(match.reflection, c.reflection);
    EXPECT_LT(match.cost, 1e-12);
  }
  // Ties go to the lower index and the first reflection: a symmetric rectangle matches itself
  // in all four ways.
  LRMatch tie = bestMatch({candidates[0], candidates[0]}, candidates[0]);
  EXPECT_EQ(tie.candidate, 0);
  EXPECT_EQ(tie.reflection, Reflection::None);
  EXPECT_EQ(bestMatch({}, candidates[0]).candidate, -1);
}

TEST(LRFunction, MatchCostResamplesWhenCountsDiffer) {
  LRFunction coarse = elementLRFunction(triangle(), {0, 0}, {4, 0}, 25);
  LRFunction fine = elementLRFunction(triangle(), {0, 0}, {4, 0}, 100);
  // Linear functions resample exactly; what remains is the two normalisations (each by its
  // own first sample) and the clamped ends: about 1e-2, against ~16 for a wrong reflection.
  EXPECT_LT(matchCost(coarse, Reflection::None, fine), 0.05);
  EXPECT_GT(matchCost(coarse, Reflection::AcrossSpine, fine), 1.0);
}

TEST(LRFunction, RectangleBlobAroundACentredStreamlineHasHalfHeightOnBothSides) {
  Region blob = rectangle(-1, -1.5, 11, 1.5);
  LRFunction f = blobLRFunction(blob, {{0, 0}, {4, 0}, {10, 0}}, 100);
  EXPECT_NEAR(f.length, 10.0, 1e-12);
  for (int i = 0; i < 100; ++i) {
    EXPECT_NEAR(f.left[i], 1.5, 1e-12);
    EXPECT_NEAR(f.right[i], 1.5, 1e-12);
  }
  // An off-centre streamline, and one half outside the blob (zero where outside).
  LRFunction off = blobLRFunction(blob, {{0, 0.5}, {10, 0.5}}, 10);
  EXPECT_NEAR(off.left[3], 1.0, 1e-12);
  EXPECT_NEAR(off.right[3], 2.0, 1e-12);
  LRFunction half = blobLRFunction(blob, {{5, 0}, {17, 0}}, 10);
  EXPECT_NEAR(half.left[2], 1.5, 1e-12);
  EXPECT_EQ(half.left[8], 0.0);
  EXPECT_EQ(half.right[8], 0.0);
}

TEST(LRFunction, AnnulusSectorAroundACircularArc) {
  const double inner = 8, outer = 13, middle = 10;  // left (towards the centre) 2, right 3
  const int n = 2000;
  Ring ring;
  for (int k = 0; k <= n; ++k) {
    double t = 0.5 * std::numbers::pi * k / n;
    ring.push_back({outer * std::cos(t), outer * std::sin(t)});
  }
  for (int k = n; k >= 0; --k) {
    double t = 0.5 * std::numbers::pi * k / n;
    ring.push_back({inner * std::cos(t), inner * std::sin(t)});
  }
  Polyline arc;  // counter-clockwise: the left normal points at the centre
  for (int k = 0; k <= 400; ++k) {
    double t = 0.05 + 1.4 * k / 400;
    arc.push_back({middle * std::cos(t), middle * std::sin(t)});
  }
  LRFunction f = blobLRFunction({Polygon{ring, {}}}, arc, 100);
  for (int i = 0; i < 100; ++i) {
    EXPECT_NEAR(f.left[i], middle - inner, 1e-3);
    EXPECT_NEAR(f.right[i], outer - middle, 1e-3);
  }
}

TEST(LRFunction, BadInputThrows) {
  EXPECT_THROW(elementLRFunction(triangle(), {0, 0}, {0, 0}), InputError);
  EXPECT_THROW(elementLRFunction(triangle(), {0, 0}, {1, 0}, 0), InputError);
  EXPECT_THROW(elementLRFunction({}, {0, 0}, {1, 0}), InputError);
  EXPECT_THROW(blobLRFunction(triangle(), {{1, 1}, {1, 1}}), InputError);
  EXPECT_THROW(blobLRFunction(triangle(), {{1, 1}, {2, 1}}, -3), InputError);
}

}  // namespace
}  // namespace pak
