#include "pak/geom/bezier_fit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "pak/error.hpp"
#include "pak/geom/closest_point.hpp"

namespace pak {
namespace {

Vec2 bezierPoint(const CubicBezier& c, double t) {
  const double s = 1.0 - t;
  return c[0] * (s * s * s) + c[1] * (3 * s * s * t) + c[2] * (3 * s * t * t) + c[3] * (t * t * t);
}

// Distance from p to the chain, measured on a fine sampling of every curve.
double distanceToChain(Vec2 p, const std::vector<CubicBezier>& curves) {
  Polyline dense;
  for (const CubicBezier& c : curves)
    for (int k = 0; k <= 400; ++k) dense.push_back(bezierPoint(c, k / 400.0));
  return closestPointOnPolyline(p, dense).distance;
}

void expectChained(const std::vector<CubicBezier>& curves, Vec2 first, Vec2 last) {
  ASSERT_FALSE(curves.empty());
  EXPECT_EQ(curves.front()[0], first);
  EXPECT_EQ(curves.back()[3], last);
  for (std::size_t i = 1; i < curves.size(); ++i) EXPECT_EQ(curves[i][0], curves[i - 1][3]);
  for (const CubicBezier& c : curves)
    for (Vec2 q : c) EXPECT_TRUE(std::isfinite(q.x) && std::isfinite(q.y));
}

TEST(BezierFit, PointsOfOneCubicAreFittedByOneCurve) {
  const CubicBezier truth{Vec2{0, 0}, Vec2{3, 6}, Vec2{8, -4}, Vec2{10, 2}};
  Polyline points;
  // Uneven parameter steps, so chord-length parameters are not already exact.
  for (int k = 0; k <= 100; ++k) points.push_back(bezierPoint(truth, std::pow(k / 100.0, 1.3)));
  const double tolerance = 0.05;  // 0.5% of the curve's size
  const auto curves = fitCubicBeziers(points, tolerance);
  ASSERT_EQ(curves.size(), 1u);
  expectChained(curves, points.front(), points.back());
  for (Vec2 p : points) EXPECT_LE(distanceToChain(p, curves), tolerance);
}

TEST(BezierFit, StraightPolylineGivesStraightChain) {
  Polyline line;
  for (int k = 0; k <= 20; ++k) line.push_back({k * 0.5, k * 0.25});
  const auto curves = fitCubicBeziers(line, 0.01);
  expectChained(curves, line.front(), line.back());
  const Vec2 dir = normalized(line.back() - line.front());
  for (const CubicBezier& c : curves)
    for (Vec2 q : c) EXPECT_NEAR(cross(dir, q - line.front()), 0.0, 1e-9);
  const Polyline flat = flatten(curves, 0.01);
  EXPECT_EQ(flat.front(), line.front());
  EXPECT_EQ(flat.back(), line.back());
}

TEST(BezierFit, ClosedCircleStaysWithinToleranceOfRadius) {
  const double radius = 10.0, tolerance = 0.05;
  Ring circle;
  for (int k = 0; k < 90; ++k) {
    const double a = 2 * std::numbers::pi * k / 90.0;
    circle.push_back({radius * std::cos(a), radius * std::sin(a)});
  }
  const auto curves = fitCubicBeziersClosed(circle, tolerance);
  expectChained(curves, circle.front(), circle.front());
  EXPECT_LE(curves.size(), 12u);  // a circle needs a handful of cubics, not one per vertex
  const Polyline flat = flatten(curves, tolerance / 2);
  ASSERT_GT(flat.size(), 8u);
  for (Vec2 p : flat) EXPECT_NEAR(length(p), radius, tolerance);
  for (Vec2 p : circle) EXPECT_LE(distanceToChain(p, curves), tolerance);
  // Smooth at the start vertex: the first and last curves share a tangent line there.
  const Vec2 out = normalized(curves.front()[1] - curves.front()[0]);
  const Vec2 in = normalized(curves.back()[3] - curves.back()[2]);
  EXPECT_NEAR(dot(out, in), 1.0, 1e-9);
}

TEST(BezierFit, SquareKeepsItsCorners) {
  Ring square;
  for (int k = 0; k < 10; ++k) square.push_back({k * 1.0, 0.0});
  for (int k = 0; k < 10; ++k) square.push_back({10.0, k * 1.0});
  for (int k = 0; k < 10; ++k) square.push_back({10.0 - k, 10.0});
  for (int k = 0; k < 10; ++k) square.push_back({0.0, 10.0 - k});
  const double tolerance = 0.1;
  const auto curves = fitCubicBeziersClosed(square, tolerance, 1.0);
  expectChained(curves, square.front(), square.front());
  // Every corner is a curve endpoint, and the chain hugs the sides.
  for (Vec2 corner : {Vec2{0, 0}, Vec2{10, 0}, Vec2{10, 10}, Vec2{0, 10}}) {
    bool found = false;
    for (const CubicBezier& c : curves) found = found || c[3] == corner;
    EXPECT_TRUE(found) << corner.x << "," << corner.y;
  }
  for (Vec2 p : flatten(curves, 0.01)) {
    const double side = std::min({std::abs(p.x), std::abs(p.y), std::abs(p.x - 10), std::abs(p.y - 10)});
    EXPECT_LE(side, 1e-9);
  }
  // Without corner detection (angle above 90°) the fit must round them off instead.
  const auto rounded = fitCubicBeziersClosed(square, tolerance, 2.0);
  for (Vec2 p : square) EXPECT_LE(distanceToChain(p, rounded), tolerance);
}

TEST(BezierFit, DegenerateInputGivesFiniteCurves) {
  const auto two = fitCubicBeziers({{0, 0}, {3, 4}}, 0.1);
  ASSERT_EQ(two.size(), 1u);
  EXPECT_NEAR(distanceToChain({1.5, 2}, two), 0.0, 1e-9);
  const auto duplicates = fitCubicBeziers({{0, 0}, {0, 0}, {1, 0}, {1, 0}, {1, 0}, {2, 1}, {2, 1}}, 0.01);
  expectChained(duplicates, {0, 0}, {2, 1});
  for (Vec2 p : Polyline{{0, 0}, {1, 0}, {2, 1}}) EXPECT_LE(distanceToChain(p, duplicates), 0.01);
  const auto single = fitCubicBeziers({{5, 5}, {5, 5}}, 0.1);
  ASSERT_EQ(single.size(), 1u);
  EXPECT_EQ(flatten(single, 0.1), (Polyline{Vec2{5, 5}}));
  EXPECT_TRUE(fitCubicBeziers({}, 0.1).empty());
  // A path that reverses on itself (a 180° turn) is split there, not fitted with NaNs.
  const auto back = fitCubicBeziers({{0, 0}, {1, 0}, {2, 0}, {1, 0}, {0, 0}}, 0.01);
  expectChained(back, {0, 0}, {0, 0});
  const auto ringOfTwo = fitCubicBeziersClosed({{0, 0}, {1, 1}, {0, 0}}, 0.1);
  expectChained(ringOfTwo, {0, 0}, {0, 0});
  EXPECT_THROW(fitCubicBeziers({{0, 0}, {1, 0}}, 0.0), InputError);
  EXPECT_THROW(fitCubicBeziers({{0, 0}, {NAN, 0}}, 0.1), InputError);
  EXPECT_THROW(flatten(two, -1.0), InputError);
}

// Known answers: points on a straight chain are 0 from it; a point 0.3 off its middle is 0.3
// away, and one past its end is measured to the end point.
TEST(BezierFit, LargestDistanceToChainHasKnownAnswers) {
  const std::vector<CubicBezier> chain{{Vec2{0, 0}, Vec2{1, 0}, Vec2{2, 0}, Vec2{3, 0}},
                                       {Vec2{3, 0}, Vec2{4, 0}, Vec2{5, 0}, Vec2{6, 0}}};
  EXPECT_DOUBLE_EQ(largestDistanceToChain({{0, 0}, {2.5, 0}, {6, 0}}, chain, 1e-3), 0.0);
  EXPECT_NEAR(largestDistanceToChain({{1, 0}, {3, 0.3}, {5, -0.1}}, chain, 1e-3), 0.3, 1e-12);
  EXPECT_NEAR(largestDistanceToChain({{6.4, 0.3}}, chain, 1e-3), 0.5, 1e-12);
  // A fit keeps within about its tolerance of what it fits.
  std::vector<Vec2> arc;
  for (int i = 0; i <= 60; ++i) arc.push_back({50.0 * std::cos(i * 0.05), 50.0 * std::sin(i * 0.05)});
  const double d = largestDistanceToChain(arc, fitCubicBeziers(arc, 0.1), 1e-3);
  EXPECT_LE(d, 0.1 + 1e-3);
}

}  // namespace
}  // namespace pak

namespace pak {
namespace {

// Known answers, both ways: a chain that bows 1 unit off a straight polygon between its
// points is 0 from every point but 0.75 from the polygon at its middle (a cubic with both
// inner control points 1 unit off reaches 0.75 at t = 1/2).
TEST(BezierFit, FitDeviationMeasuresTheChainAgainstThePolygonToo) {
  const std::vector<Vec2> points{{0, 0}, {3, 0}};
  const std::vector<CubicBezier> bowed{{Vec2{0, 0}, Vec2{1, 1}, Vec2{2, 1}, Vec2{3, 0}}};
  EXPECT_DOUBLE_EQ(largestDistanceToChain(points, bowed, 1e-4), 0.0);
  EXPECT_NEAR(fitDeviation(points, false, bowed, 1e-4), 0.75, 1e-3);
  // A ring counts its closing edge: the square's four sides are 0 from the closed ring, but
  // the fourth side's middle is 1 from the three sides of the open polyline.
  const std::vector<Vec2> square{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  const std::vector<CubicBezier> sides{{Vec2{0, 0}, Vec2{0.5, 0}, Vec2{1.5, 0}, Vec2{2, 0}},
                                       {Vec2{2, 0}, Vec2{2, 0.5}, Vec2{2, 1.5}, Vec2{2, 2}},
                                       {Vec2{2, 2}, Vec2{1.5, 2}, Vec2{0.5, 2}, Vec2{0, 2}},
                                       {Vec2{0, 2}, Vec2{0, 1.5}, Vec2{0, 0.5}, Vec2{0, 0}}};
  EXPECT_NEAR(fitDeviation(square, true, sides, 1e-4), 0.0, 1e-12);
  EXPECT_NEAR(fitDeviation(square, false, sides, 1e-4), 1.0, 1e-3);
}

// A long edge between two sharp-ish turns that are not corners: tangent handles would bow the
// curve far off the edge (a packed element's straight side, once fitted, went 66 units² over
// the container's wall); the fit keeps within its tolerance of the polygon both ways.
TEST(BezierFit, ALongEdgeBetweenTurnsDoesNotBowOffThePolygon) {
  const Ring ring{{0, 0}, {100, 0}, {102, 2}, {102, 40}, {100, 42}, {0, 42}, {-2, 40}, {-2, 2}};
  for (double tolerance : {0.05, 0.1, 0.4}) {
    const std::vector<CubicBezier> curves = fitCubicBeziersClosed(ring, tolerance, 1.0);
    EXPECT_LE(fitDeviation(ring, true, curves, 0.01 * tolerance), tolerance * 1.02) << tolerance;
  }
}

// A chain of three different cubics joined smoothly, densely sampled: Schneider's split at the
// worst point cuts where the error peaks, and needs more curves than reaching each curve as
// far as it fits. Both stay within the tolerance, both ways.
TEST(BezierFit, LongestSpansNeedFewerCurvesThanSplittingAtTheWorstPoint) {
  const std::vector<CubicBezier> truth{{Vec2{0, 0}, Vec2{10, 12}, Vec2{25, 14}, Vec2{35, 4}},
                                       {Vec2{35, 4}, Vec2{42, -3}, Vec2{55, -10}, Vec2{70, -2}},
                                       {Vec2{70, -2}, Vec2{80, 3}, Vec2{86, 15}, Vec2{84, 30}}};
  Polyline points;
  for (const CubicBezier& c : truth)
    for (int k = points.empty() ? 0 : 1; k <= 60; ++k) points.push_back(bezierPoint(c, k / 60.0));
  const double tolerance = 0.02;
  const auto longest = fitCubicBeziers(points, tolerance, 1.0, FitSpans::Longest);
  const auto split = fitCubicBeziers(points, tolerance, 1.0, FitSpans::SplitAtWorst);
  expectChained(longest, points.front(), points.back());
  EXPECT_LE(fitDeviation(points, false, longest, 0.01 * tolerance), 1.02 * tolerance);
  EXPECT_LE(fitDeviation(points, false, split, 0.01 * tolerance), 1.02 * tolerance);
  EXPECT_LT(longest.size(), split.size()) << longest.size() << " against " << split.size();
}

// Three points fit exactly by a curve whose handles are longer than its chord: the curve runs
// past its end, back past its start and forward again, a zigzag along the line that measured
// 1.27 × the tolerance off the polygon on a packed element. Such handles are refused.
TEST(BezierFit, NoHandleLongerThanItsChord) {
  const Polyline zigzag{{560.664, 292.786}, {558.513, 294.323}, {556.266, 295.641}, {554.148, 297.010},
                        {552.110, 298.460}, {550.132, 299.989}, {548.210, 301.603}};
  for (double tolerance : {0.02, 0.0782, 0.2}) {
    const auto curves = fitCubicBeziers(zigzag, tolerance);
    for (const CubicBezier& c : curves) {
      const double chord = distance(c[0], c[3]);
      EXPECT_LE(distance(c[0], c[1]), chord + 1e-9);
      EXPECT_LE(distance(c[3], c[2]), chord + 1e-9);
    }
    EXPECT_LE(fitDeviation(zigzag, false, curves, 0.01 * tolerance), 1.02 * tolerance) << tolerance;
  }
}

}  // namespace
}  // namespace pak
