#include "pak/geom/resample.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "pak/error.hpp"

using namespace pak;

namespace {

Ring square(double side) { return {{0, 0}, {side, 0}, {side, side}, {0, side}}; }

bool onSquareBoundary(Vec2 p, double side) {
  const double eps = 1e-9;
  const bool inX = p.x > -eps && p.x < side + eps, inY = p.y > -eps && p.y < side + eps;
  return inX && inY &&
         (std::abs(p.x) < eps || std::abs(p.x - side) < eps || std::abs(p.y) < eps || std::abs(p.y - side) < eps);
}

}  // namespace

TEST(Resample, SquareOfPerimeter40AtSpacing1) {
  Ring r = resampleRing(square(10), 1.0);
  ASSERT_EQ(r.size(), 40u);
  EXPECT_EQ(r[0], (Vec2{0, 0}));
  for (std::size_t k = 0; k < r.size(); ++k) {
    EXPECT_TRUE(onSquareBoundary(r[k], 10)) << k;
    // Consecutive points are exactly one apart along the boundary, including the wrap.
    EXPECT_NEAR(distance(r[k], r[(k + 1) % r.size()]), 1.0, 1e-9) << k;
  }
  EXPECT_NEAR(r[10].x, 10.0, 1e-12);  // the corners are hit exactly at multiples of 10
  EXPECT_NEAR(r[20].y, 10.0, 1e-12);
}

TEST(Resample, CountIsRoundedPerimeterOverSpacingAndAtLeastThree) {
  EXPECT_EQ(resampleRing(square(10), 3.0).size(), 13u);   // 40 / 3 = 13.33
  EXPECT_EQ(resampleRing(square(10), 2.9).size(), 14u);   // 13.79
  EXPECT_EQ(resampleRing(square(1), 100.0).size(), 3u);
  Ring r = resampleRing(square(10), 3.0);
  const double step = 40.0 / 13.0;
  // Arclength between consecutive points is constant (straight runs give step exactly).
  EXPECT_NEAR(distance(r[0], r[1]), step, 1e-9);
  EXPECT_NEAR(distance(r[1], r[2]), step, 1e-9);
}

TEST(Resample, CircleSamplesAreEquallySpacedOnTheCircle) {
  Ring circle;
  for (int k = 0; k < 1000; ++k) {
    const double a = 2.0 * M_PI * k / 1000.0;
    circle.push_back({5.0 * std::cos(a), 5.0 * std::sin(a)});
  }
  Ring r = resampleRing(circle, 0.5);
  EXPECT_EQ(r.size(), static_cast<std::size_t>(std::round(perimeter(circle) / 0.5)));
  for (Vec2 p : r) EXPECT_NEAR(length(p), 5.0, 1e-4);
}

TEST(Resample, Polyline) {
  Polyline line{{0, 0}, {10, 0}, {10, 5}};
  Polyline r = resamplePolyline(line, 1.0);
  ASSERT_EQ(r.size(), 16u);  // 15 segments of length 1
  EXPECT_EQ(r.front(), (Vec2{0, 0}));
  EXPECT_EQ(r.back(), (Vec2{10, 5}));
  EXPECT_NEAR(r[10].x, 10.0, 1e-12);
  for (std::size_t k = 1; k < r.size(); ++k) EXPECT_NEAR(distance(r[k - 1], r[k]), 1.0, 1e-9);
  // Not a multiple: 15 / 4 -> 4 segments of 3.75, never longer than the spacing.
  Polyline coarse = resamplePolyline(line, 4.0);
  ASSERT_EQ(coarse.size(), 5u);
  EXPECT_NEAR(coarse[1].x, 3.75, 1e-12);
  EXPECT_EQ(coarse.back(), (Vec2{10, 5}));
}

TEST(Resample, PointAtArclengthWraps) {
  Ring s = square(10);
  EXPECT_EQ(pointAtArclength(s, 0.0), (Vec2{0, 0}));
  Vec2 p = pointAtArclength(s, 15.0);
  EXPECT_NEAR(p.x, 10.0, 1e-12);
  EXPECT_NEAR(p.y, 5.0, 1e-12);
  Vec2 q = pointAtArclength(s, 55.0);  // 55 - 40
  EXPECT_NEAR(q.x, 10.0, 1e-12);
  EXPECT_NEAR(q.y, 5.0, 1e-12);
  Vec2 n = pointAtArclength(s, -5.0);  // 35: on the left side going down
  EXPECT_NEAR(n.x, 0.0, 1e-12);
  EXPECT_NEAR(n.y, 5.0, 1e-12);
}

TEST(Resample, DegenerateAndBadInput) {
  EXPECT_TRUE(resampleRing(Ring{}, 1.0).empty());
  EXPECT_TRUE(resampleRing(Ring{{1, 1}, {1, 1}, {1, 1}}, 1.0).empty());
  EXPECT_TRUE(resamplePolyline(Polyline{}, 1.0).empty());
  EXPECT_EQ(resamplePolyline(Polyline{{2, 2}, {2, 2}}, 1.0).size(), 1u);
  EXPECT_EQ(pointAtArclength(Ring{}, 3.0), (Vec2{}));
  EXPECT_THROW(resampleRing(square(1), 0.0), InputError);
  EXPECT_THROW(resampleRing(square(1), -1.0), InputError);
  EXPECT_THROW(resampleRing(square(1e6), 1e-9), InputError);  // far too many points
  EXPECT_THROW(resamplePolyline({{0, 0}, {1, 0}}, std::numeric_limits<double>::quiet_NaN()), InputError);
  EXPECT_THROW(resampleRing(Ring{{0, 0}, {std::numeric_limits<double>::infinity(), 0}, {0, 1}}, 1.0), InputError);
}
