#include "pak/repulsion/shape_matching.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "pak/geom/closest_point.hpp"
#include "pak/geom/verify.hpp"
#include "pak/io/packing_drawing.hpp"
#include "pak/io/svg_writer.hpp"
#include "pak/repulsion/repulsion.hpp"

using namespace pak;

namespace {

constexpr double kPi = std::numbers::pi;

Ring circle(Vec2 centre, double radius, int n) {
  Ring r;
  for (int i = 0; i < n; ++i) r.push_back(centre + Vec2{std::cos(2 * kPi * i / n), std::sin(2 * kPi * i / n)} * radius);
  return r;
}

// A regular star with `points` tips, counter-clockwise, first tip straight up.
Ring star(Vec2 centre, double outer, double inner, int points = 5) {
  Ring r;
  for (int i = 0; i < 2 * points; ++i) {
    double a = kPi / 2 + kPi * i / points;
    r.push_back(centre + Vec2{std::cos(a), std::sin(a)} * (i % 2 == 0 ? outer : inner));
  }
  return r;
}

// An equilateral triangle (circumradius `radius`) with a vertex at angle `rotation`.
Ring equilateral(Vec2 centre, double radius, double rotation = kPi / 2) {
  Ring r;
  for (int i = 0; i < 3; ++i) {
    double a = rotation + 2 * kPi * i / 3;
    r.push_back(centre + Vec2{std::cos(a), std::sin(a)} * radius);
  }
  return r;
}

Shape filledShape(const Ring& ring) {
  Shape s;
  s.subpaths.push_back({ring, true});
  s.fill = Color{40, 90, 160};
  return s;
}

ElementArt element(const Ring& ring, const std::string& name) {
  ElementArt e;
  e.source = name;
  e.name = name;
  e.shapes = {filledShape(ring)};
  e.outline = {Polygon{ring, {}}};
  return e;
}

}  // namespace

TEST(ShapeDescriptor, CircleHasConstantCurvatureAndEqualArclengths) {
  const double radius = 100.0, tau = 0.5;
  // Sampled at its own edge length, so the samples are the polygon's vertices.
  const Ring ring = circle({0, 0}, radius, 314);
  RingDescriptors d = describeRing(ring, perimeter(ring) / 314, tau, 5);
  ASSERT_EQ(d.samples.size(), 314u);
  for (double k : d.curvature) EXPECT_NEAR(k, 1.0 / radius, 1e-4 / radius);
  EXPECT_NEAR(d.cumulative.back(), 2 * kPi, 1e-9);  // total absolute turn of a convex ring
  // Equal τ steps on constant curvature: every arclength is τ_obj · R.
  for (int s : {0, 17, 200}) {
    const double* v = d.descriptor(s);
    for (int k = 0; k < 10; ++k) EXPECT_NEAR(v[k], tau * radius, 0.5) << "sample " << s << " entry " << k;
  }
}

TEST(ShapeDescriptor, SquareCornerHoldsAQuarterTurn) {
  const double side = 200.0, delta = 2.0;
  Ring square{{0, 0}, {side, 0}, {side, side}, {0, side}};
  RingDescriptors d = describeRing(square, delta, 1.0, 5);
  ASSERT_EQ(d.samples.size(), 400u);
  // Sample 100 is the corner (side, 0): the integral across it is π/2, along a side 0.
  EXPECT_NEAR(d.cumulative[103] - d.cumulative[97], kPi / 2, 1e-9);
  EXPECT_NEAR(d.cumulative[60] - d.cumulative[40], 0.0, 1e-9);
  EXPECT_NEAR(d.cumulative.back(), 2 * kPi, 1e-9);
  // From the middle of the bottom side with τ_obj = 1 rad (< π/2): r_1 reaches into the next
  // corner (half a side), r_2 crosses the rest of that corner and the next side (one side),
  // r_3 ends inside the same corner (2 < 3 < π), whose turn the trapezoid rule spreads over
  // the two steps either side of it; the left walk mirrors it.
  const double* v = d.descriptor(50);
  EXPECT_NEAR(v[5], side / 2, delta);   // r_1
  EXPECT_NEAR(v[6], side, delta);       // r_2
  EXPECT_NEAR(v[7], 0.0, 2 * delta);    // r_3
  EXPECT_NEAR(v[4], side / 2, delta);   // l_1
  EXPECT_NEAR(v[3], side, delta);       // l_2
  EXPECT_NEAR(v[2], 0.0, 2 * delta);    // l_3
  // The descriptor's points follow the walked arclengths along the ring.
  std::vector<Vec2> points = d.descriptorPoints(50);
  ASSERT_EQ(points.size(), 11u);
  EXPECT_NEAR(distance(points[5], Vec2{side / 2, 0}), 0.0, 1e-9);
  EXPECT_NEAR(distance(points[6], Vec2{side, 0}), 0.0, delta);
  EXPECT_NEAR(distance(points[4], Vec2{0, 0}), 0.0, delta);
}

TEST(SalientCorners, FindsTheFiveTipsOfAStarAndNothingOnADisc) {
  Ring s = star({500, 500}, 450, 180);
  RingDescriptors d = describeRing(s, 2.0, 1.0, 5);
  std::vector<SalientCorner> corners = salientCorners({d}, 0.3, 200.0);
  ASSERT_EQ(corners.size(), 5u);
  for (int tip = 0; tip < 5; ++tip) {
    double nearest = 1e9;
    for (const SalientCorner& c : corners) nearest = std::min(nearest, distance(c.position, s[2 * tip]));
    EXPECT_LT(nearest, 3.0) << "tip " << tip;
  }
  for (const SalientCorner& c : corners) {
    EXPECT_GT(c.turn, 0.3);
    // The bisector points from the tip towards the star's centre.
    EXPECT_GT(dot(c.inward, normalized(Vec2{500, 500} - c.position)), 0.99);
  }
  RingDescriptors disc = describeRing(circle({500, 500}, 450, 400), 2.0, 1.0, 5);
  EXPECT_TRUE(salientCorners({disc}, 0.3, 200.0).empty());
}

TEST(SalientCorners, TriangleInAnyUnitsHasThreeCornersAtItsVertices) {
  Ring t = equilateral({5, 5}, 4);  // tiny units: detection runs in the canonical frame
  std::vector<SalientCorner> corners = salientContainerCorners({Polygon{t, {}}});
  ASSERT_EQ(corners.size(), 3u);
  for (const Vec2& v : t) {
    double nearest = 1e9;
    for (const SalientCorner& c : corners) nearest = std::min(nearest, distance(c.position, v));
    EXPECT_LT(nearest, 0.02);  // 2.5 canonical units
  }
}

TEST(ShapeMatching, TriangleCornerPicksTheTriangleTippedElementOverADisc) {
  Region container{Polygon{equilateral({500, 430}, 560), {}}};
  // Same area for both: a small equilateral triangle and a disc.
  Ring tipped = equilateral({0, 0}, 90, 0.3);
  const double discRadius = std::sqrt(std::abs(signedArea(tipped)) / kPi);
  std::vector<Ring> skins{circle({0, 0}, discRadius, 200), tipped};
  ShapeMatch match = matchCorners(container, skins, 1.0);
  ASSERT_EQ(match.corners.size(), 3u);
  ASSERT_EQ(match.matches.size(), 3u);
  for (const CornerMatch& m : match.matches) {
    EXPECT_EQ(m.element, 1) << "corner " << m.corner;
    // The matched tip lands on the corner, and the whole element is inside.
    Vec2 tip = rotated(m.elementTip, m.angle) * m.scale + m.translation;
    EXPECT_LT(distance(tip, match.corners[m.corner].position), 10.0);
    for (Vec2 p : tipped) EXPECT_TRUE(pointInRegion(rotated(p, m.angle) * m.scale * 0.98 + m.translation, container));
    EXPECT_GT(m.quality, 0.0);
  }
}

TEST(ShapeMatching, FitScoreFollowsEquation410) {
  const double mu = 0.5 * std::sqrt(2.0) * 1000.0;
  EXPECT_DOUBLE_EQ(fitScore(0.0, 1.0, 0.001, mu), 1.0);
  EXPECT_DOUBLE_EQ(fitScore(5.0, 1.0, 0.001, mu), -5.0);
  EXPECT_NEAR(fitScore(-std::sqrt(500.0), 1.0, 0.001, mu), std::exp(-1.0), 1e-12);  // μ²β = 500
  EXPECT_LT(fitScore(-100.0, 1.0, 0.001, mu), 1e-6);
}

namespace {

Scene starScene() {
  Scene scene;
  scene.source = "star";
  scene.container = {Polygon{star({0, 0}, 100, 42), {}}};
  return scene;
}

Library triangleAndDisc() {
  return {element(equilateral({0, 0}, 10, 0.2), "triangle"), element(circle({0, 0}, 6, 60), "disc")};
}

RepulsionOptions starOptions() {
  RepulsionOptions options;
  options.count = 10;
  options.gap = 12.0;
  options.stop.targetFill = 0.5;
  options.stop.maxIterations = 1500;
  options.run.seed = 2;
  options.shapeMatching.enabled = true;
  return options;
}

}  // namespace

TEST(ShapeMatching, DockedRunIsTheSameWhateverTheThreadCount) {
  RepulsionOptions options = starOptions();
  options.stop.maxIterations = 300;
  options.run.threads = 1;
  std::string one = toSvgString(packingDrawing(SceneLayout{}, packRepulsion(starScene(), triangleAndDisc(), options)));
  options.run.threads = 3;
  std::string three = toSvgString(packingDrawing(SceneLayout{}, packRepulsion(starScene(), triangleAndDisc(), options)));
  EXPECT_EQ(one, three);
}

TEST(ShapeMatching, DockedElementsReachEveryCornerOfAStarWithoutOverlaps) {
  Scene scene = starScene();
  Library library = triangleAndDisc();
  RepulsionOptions options = starOptions();
  Packing packing = packRepulsion(scene, library, options);
  ASSERT_EQ(packing.salientCorners.size(), 5u);
  EXPECT_EQ(packing.dockedElements, 5);
  std::vector<Region> outlines = artOutlines(packing);
  PackingCheckOptions check;
  check.areaTolerance = 1e-5 * area(packing.container);
  PackingCheck verdict = verifyPacking(outlines, packing.container, check);
  EXPECT_TRUE(verdict.ok) << (verdict.problems.empty() ? "" : verdict.problems.front());
  // Every tip has art within 15 canonical units (1.5 % of the container's size; measured:
  // 0.2–4.5 with matching, 120–210 without).
  for (Vec2 c : packing.salientCorners) {
    double nearest = 1e9;
    for (const Region& r : outlines) nearest = std::min(nearest, closestPointOnBoundary(c, r).distance);
    EXPECT_LT(nearest * packing.canonicalScale, 15.0) << "corner " << c.x << "," << c.y;
  }
}
