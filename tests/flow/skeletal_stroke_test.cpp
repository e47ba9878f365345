#include "pak/flow/skeletal_stroke.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <numbers>

#include "pak/error.hpp"
#include "pak/geom/clipping.hpp"
#include "pak/geom/closest_point.hpp"

namespace pak {
namespace {

Region rectangle(double x0, double y0, double x1, double y1) {
  return {Polygon{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}}};
}

// An asymmetric element about the spine (0,0)-(4,0), with a hole.
Region element() {
  Region r = {Polygon{{{0, -1}, {4, 0}, {3, 1.5}, {0, 2}}, {}}};
  r[0].holes.push_back({{1, 0.5}, {2, 0.2}, {1.5, 1}});
  normalizeOrientation(r);
  return r;
}

Polyline straight(Vec2 a, Vec2 b, int pieces) {
  Polyline line;
  for (int k = 0; k <= pieces; ++k) line.push_back(a + (static_cast<double>(k) / pieces) * (b - a));
  return line;
}

Polyline arc(double radius, double t0, double t1, int pieces) {
  Polyline line;
  for (int k = 0; k <= pieces; ++k) {
    double t = t0 + (t1 - t0) * k / pieces;
    line.push_back({radius * std::cos(t), radius * std::sin(t)});
  }
  return line;
}

TEST(SkeletalStroke, FrameSpansTheOutlineAlongItsSpine) {
  StrokeFrame frame = strokeFrameFor(element(), {1, 0}, {2, 0});
  EXPECT_DOUBLE_EQ(frame.alongMin, -1.0);
  EXPECT_DOUBLE_EQ(frame.alongMax, 3.0);
  // Turned by 90 degrees about the spine's midpoint (1.5, 0), the y extent [-1, 2] lies along it.
  StrokeFrame turned = strokeFrameFor(element(), {1, 0}, {2, 0}, std::numbers::pi / 2);
  EXPECT_NEAR(turned.alongMin, -2.0 + 0.5, 1e-12);
  EXPECT_NEAR(turned.alongMax, 1.0 + 0.5, 1e-12);
}

TEST(SkeletalStroke, RotatedFrameBendsTheRotatedElementOverTheWholeStreamline) {
  const double r = 10 * std::numbers::pi / 180;
  StrokeFrame frame = strokeFrameFor(element(), {1, 0}, {2, 0}, r);
  Region turned = rotatedElement(element(), frame);
  // Turned about (1.5, 0): the point (1.5, 0) stays; (0, 2) moves.
  StrokeFrame plain = strokeFrameFor(turned, {1, 0}, {2, 0});
  EXPECT_DOUBLE_EQ(plain.alongMin, frame.alongMin);
  EXPECT_DOUBLE_EQ(plain.alongMax, frame.alongMax);
  Polyline line = straight({0, 0}, {10, 0}, 5);
  Region a = bendRegion(element(), frame, line, 0.2), b = bendRegion(turned, plain, line, 0.2);
  ASSERT_EQ(a[0].outer.size(), b[0].outer.size());
  Box box = bounds(a);
  EXPECT_NEAR(box.min.x, 0.0, 1e-9);  // spans the streamline exactly
  EXPECT_NEAR(box.max.x, 10.0, 1e-9);
  for (std::size_t k = 0; k < a[0].outer.size(); ++k) EXPECT_LT(distance(a[0].outer[k], b[0].outer[k]), 1e-9);
}

TEST(SkeletalStroke, StraightStreamlineReproducesTheElementUpToScale) {
  StrokeFrame frame = strokeFrameFor(element(), {0, 0}, {4, 0});
  frame.widthScale = 0.7;
  // Streamline of length 10 along the direction (3, 4) / 5, with uneven vertices.
  const Vec2 start{2, -1}, u{0.6, 0.8}, n{-0.8, 0.6};
  Polyline line = {start, start + 3.0 * u, start + 3.5 * u, start + 10.0 * u};
  const double lengthScale = 10.0 / 4.0;
  for (const Ring& ring : {element()[0].outer, element()[0].holes[0]}) {
    Ring bent = bendRing(ring, frame, line, 1e9);  // no subdivision: vertex for vertex
    ASSERT_EQ(bent.size(), ring.size());
    for (std::size_t k = 0; k < ring.size(); ++k) {
      Vec2 expected = start + (ring[k].x * lengthScale) * u + (ring[k].y * frame.widthScale) * n;
      EXPECT_NEAR(bent[k].x, expected.x, 1e-9);
      EXPECT_NEAR(bent[k].y, expected.y, 1e-9);
    }
  }
  // Subdivided edges stay on the mapped edges, and the area scales by both scales.
  Region bent = bendRegion(element(), frame, line, 0.1);
  EXPECT_GT(bent[0].outer.size(), 100u);
  EXPECT_NEAR(area(bent), area(element()) * lengthScale * frame.widthScale, 1e-9);
  EXPECT_GT(signedArea(bent[0].outer), 0.0);
  EXPECT_LT(signedArea(bent[0].holes[0]), 0.0);
}

TEST(SkeletalStroke, ReflectionsMirrorTheResultAndKeepOrientation) {
  StrokeFrame frame = strokeFrameFor(element(), {0, 0}, {4, 0});
  Polyline line = straight({0, 0}, {8, 0}, 4);
  Ring plain = bendRing(element()[0].outer, frame, line, 1e9);
  const Reflection reflections[] = {Reflection::AcrossSpine, Reflection::AlongSpine, Reflection::Both};
  for (Reflection r : reflections) {
    frame.reflection = r;
    Ring mirrored = bendRing(element()[0].outer, frame, line, 1e9);
    EXPECT_GT(signedArea(mirrored), 0.0);  // still counter-clockwise
    EXPECT_NEAR(signedArea(mirrored), signedArea(plain), 1e-9);
    for (Vec2 p : plain) {  // every point has its mirror image among the reflected ones
      Vec2 image = {r == Reflection::AcrossSpine ? p.x : 8 - p.x, r == Reflection::AlongSpine ? p.y : -p.y};
      double best = 1e9;
      for (Vec2 q : mirrored) best = std::min(best, distance(q, image));
      EXPECT_LT(best, 1e-9);
    }
  }
}

TEST(SkeletalStroke, BentElementHasTheReflectedLRFunctionTheMatchChose) {
  // What matchCost assumes of a reflection is what the bend does: bent along a straight
  // streamline (scaled 2 along, 1.5 across), the element's own shape, read as a blob, has the
  // element's reflected function.
  const int n = 64;
  LRFunction original = elementLRFunction(element(), {0, 0}, {4, 0}, n);
  Polyline line = straight({3, 1}, {11, 1}, 4);
  const Reflection all[] = {Reflection::None, Reflection::AcrossSpine, Reflection::AlongSpine, Reflection::Both};
  for (Reflection r : all) {
    StrokeFrame frame = strokeFrameFor(element(), {0, 0}, {4, 0});
    frame.reflection = r;
    frame.widthScale = 1.5;
    Region bent = bendRegion(Region{Polygon{element()[0].outer, {}}}, frame, line, 0.05);
    LRFunction asBlob = blobLRFunction(bent, line, n);
    LRFunction expected = reflected(elementLRFunction(Region{Polygon{element()[0].outer, {}}}, {0, 0}, {4, 0}, n), r);
    for (int i = 0; i < n; ++i) {
      EXPECT_NEAR(asBlob.left[i], 1.5 * expected.left[i], 1e-9);
      EXPECT_NEAR(asBlob.right[i], 1.5 * expected.right[i], 1e-9);
    }
    EXPECT_LT(matchCost(original, r, asBlob), matchCost(original, r == Reflection::None ? Reflection::Both : Reflection::None, asBlob));
  }
}

TEST(SkeletalStroke, CircularArcCarriesTheSpineOntoTheArcAndOffsetsRadially) {
  const double radius = 20, s = 1.3;
  const int pieces = 400;
  Polyline line = arc(radius, 0.2, 1.4, pieces);  // counter-clockwise: left is towards the centre
  StrokeFrame frame = strokeFrameFor(element(), {0, 0}, {4, 0});
  frame.widthScale = s;
  // Worst radial error of the polygonal arc: its chords' sagitta.
  const double sagitta = radius * (1 - std::cos(0.5 * 1.2 / pieces));
  Ring spinePoints = {{0, 0}, {1, 0}, {2.5, 0}, {4, 0}};
  for (Vec2 p : bendRing(spinePoints, frame, line, 0.01)) {
    EXPECT_NEAR(length(p), radius, sagitta + 1e-9);
    double along = std::atan2(p.y, p.x);  // on the arc, evenly: exactly at the vertices
    EXPECT_GE(along, 0.2 - 1e-12);
    EXPECT_LE(along, 1.4 + 1e-12);
  }
  for (Vec2 p : bendRing({{0, 0}, {2, 0}, {4, 0}}, frame, line, 1e9)) {
    double along = std::atan2(p.y, p.x);
    EXPECT_TRUE(std::abs(along - 0.2) < 1e-9 || std::abs(along - 0.8) < 1e-9 || std::abs(along - 1.4) < 1e-9);
  }
  const Region shape = element();
  for (Vec2 p : shape[0].outer) {
    Vec2 q = bendRing({p}, frame, line, 1.0)[0];
    EXPECT_NEAR(length(q), radius - s * p.y, sagitta + 1e-9);
    // And along the arc: the angle is proportional to the position along the spine (up to
    // the normal's turn within a chord: an end vertex's normal is its chord's).
    EXPECT_NEAR(std::atan2(q.y, q.x), 0.2 + 1.2 * p.x / 4, 1.2 / pieces);
  }
}

TEST(SkeletalStroke, ShapesKeepPaintAndScaleStrokes) {
  Shape shape;
  shape.subpaths.push_back({{{0, -1}, {4, -1}, {4, 1}, {0, 1}}, true});
  shape.subpaths.push_back({{{1, 0}, {3, 0}}, false});
  shape.fill = Color{10, 20, 30, 0.5};
  shape.stroke = Color{1, 2, 3, 1.0};
  shape.strokeWidth = 0.2;
  shape.fillRule = FillRule::EvenOdd;
  StrokeFrame frame = strokeFrameFor(rectangle(0, -1, 4, 1), {0, 0}, {4, 0});
  frame.widthScale = 2.0;
  frame.reflection = Reflection::AcrossSpine;
  std::vector<Shape> bent = bendShapes({shape}, frame, straight({0, 0}, {8, 0}, 2), 0.5);
  ASSERT_EQ(bent.size(), 1u);
  EXPECT_EQ(bent[0].fill, shape.fill);
  EXPECT_EQ(bent[0].stroke, shape.stroke);
  EXPECT_EQ(bent[0].fillRule, FillRule::EvenOdd);
  EXPECT_NEAR(bent[0].strokeWidth, 0.2 * std::sqrt(2.0 * 2.0), 1e-12);
  EXPECT_FALSE(bent[0].subpaths[1].closed);
  EXPECT_GT(signedArea(bent[0].subpaths[0].points), 0.0);
  EXPECT_NEAR(signedArea(bent[0].subpaths[0].points), 8 * 4, 1e-9);
  EXPECT_NEAR(area(filledRegion(bent[0])), 32, 1e-6);
}

TEST(SkeletalStroke, NonzeroFillWithACounterWoundHoleSurvivesEveryReflection) {
  Shape shape;
  shape.subpaths.push_back({{{0, -1}, {4, -1}, {4, 1}, {0, 1}}, true});              // counter-clockwise
  shape.subpaths.push_back({{{1, -0.5}, {1, 0.5}, {3, 0.5}, {3, -0.5}}, true});      // clockwise: a hole
  shape.fill = Color{};
  const double expected = (8 - 2) * 2.0 * 0.5;  // area × lengthScale × widthScale
  StrokeFrame frame = strokeFrameFor(rectangle(0, -1, 4, 1), {0, 0}, {4, 0});
  frame.widthScale = 0.5;
  const Reflection all[] = {Reflection::None, Reflection::AcrossSpine, Reflection::AlongSpine, Reflection::Both};
  for (Reflection r : all) {
    frame.reflection = r;
    Shape bent = bendShapes({shape}, frame, straight({0, 0}, {8, 0}, 3), 0.3)[0];
    EXPECT_NEAR(area(filledRegion(bent)), expected, 1e-6);
    EXPECT_GT(signedArea(bent.subpaths[0].points), 0.0);
    EXPECT_LT(signedArea(bent.subpaths[1].points), 0.0);
  }
}

TEST(SkeletalStroke, FitWidthScaleFillsARectangularBlob) {
  const double h = 1.0, blobHalfHeight = 1.5;
  Region outline = rectangle(0, -h / 2, 4, h / 2);
  StrokeFrame frame = strokeFrameFor(outline, {0, 0}, {4, 0});
  Polyline line = straight({1, 0}, {9, 0}, 8);
  Region blob = rectangle(0.5, -blobHalfHeight, 9.5, blobHalfHeight);
  double s = fitWidthScale(outline, frame, line, blob, 0.25, 100.0);
  EXPECT_NEAR(s, blobHalfHeight / (h / 2), 1e-3 * 3.0);
  EXPECT_LE(s, 3.0);
  frame.widthScale = s;
  Region bent = bendRegion(outline, frame, line, 0.25);
  // Inside, or on the boundary (the fit may touch it: 3 is the exact answer here).
  for (Vec2 p : bent[0].outer)
    EXPECT_TRUE(pointInRegion(p, blob) || closestPointOnBoundary(p, blob).distance < 1e-9) << p.x << " " << p.y;
  EXPECT_LT(area(subtract(bent, blob)), 1e-9 * area(bent));
  // Capped by maxScale; nothing fits in a blob beside the streamline.
  EXPECT_DOUBLE_EQ(fitWidthScale(outline, frame, line, blob, 0.25, 2.0), 2.0);
  EXPECT_EQ(fitWidthScale(outline, frame, line, rectangle(0, 5, 10, 8), 0.25, 10.0), 0.0);
}

TEST(SkeletalStroke, FitWidthScaleOnAnArcInAnAnnulusSector) {
  // A one-sided element (left of its spine) on a counter-clockwise arc of radius 10 in the
  // annulus 8..13: its left side faces the centre, 2 away; reflected across, 3.
  Region outline = {Polygon{{{0, 0}, {4, 0}, {4, 1}, {0, 1}}, {}}};
  Polyline line = arc(10, 0.2, 1.3, 200);
  Ring ring;
  for (int k = 0; k <= 600; ++k) ring.push_back({13 * std::cos(1.5 * k / 600), 13 * std::sin(1.5 * k / 600)});
  for (int k = 600; k >= 0; --k) ring.push_back({8 * std::cos(1.5 * k / 600), 8 * std::sin(1.5 * k / 600)});
  Region blob = {Polygon{ring, {}}};
  StrokeFrame frame = strokeFrameFor(outline, {0, 0}, {4, 0});
  auto start = std::chrono::steady_clock::now();
  double inward = fitWidthScale(outline, frame, line, blob, 0.1, 100.0);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_NEAR(inward, 2.0, 0.01);
  frame.reflection = Reflection::AcrossSpine;
  EXPECT_NEAR(fitWidthScale(outline, frame, line, blob, 0.1, 100.0), 3.0, 0.01);
  frame.widthScale = fitWidthScale(outline, frame, line, blob, 0.1, 100.0);
  Region bent = bendRegion(outline, frame, line, 0.1);
  EXPECT_LT(area(subtract(bent, blob)), 1e-6 * area(bent));
  EXPECT_LT(seconds, 0.5);
}

TEST(SkeletalStroke, FitWidthScaleSeesABlobHoleInsideTheElement) {
  Region outline = rectangle(0, -0.5, 4, 0.5);
  StrokeFrame frame = strokeFrameFor(outline, {0, 0}, {4, 0});
  Region blob = rectangle(-1, -3, 11, 3);
  blob[0].holes.push_back({{5, 0.8}, {5.2, 0.8}, {5.2, 1.0}, {5, 1.0}});  // a small obstacle above
  normalizeOrientation(blob);
  double s = fitWidthScale(outline, frame, straight({0, 0}, {10, 0}, 10), blob, 0.25, 100.0);
  EXPECT_NEAR(s, 0.8 / 0.5, 2e-3);
}

// A bar in a blob twice as roomy on its left past x = 2 of the streamline: the left
// side widens there, smoothly, up to the cap, and stays in the blob; the right side keeps
// the uniform width.
TEST(SkeletalStroke, FitWideningWidensEachSideWhereTheBlobLeavesRoom) {
  const Region outline = rectangle(0, -0.5, 4, 0.5);
  const Polyline line = straight({0, 0}, {10, 0}, 10);
  Region blob = {Polygon{{{-1, -1}, {11, -1}, {11, 2}, {2, 2}, {2, 1}, {-1, 1}}, {}}};
  normalizeOrientation(blob);
  StrokeFrame frame = strokeFrameFor(outline, {0, 0}, {4, 0});
  frame.widthScale = fitWidthScale(outline, frame, line, blob, 0.25, 100.0);
  ASSERT_NEAR(frame.widthScale, 2.0, 2e-3);
  const double uniformArea = area(bendRegion(outline, frame, line, 0.25));

  fitWidening(outline, frame, line, blob, 0.0, 0.25, 1.0);
  EXPECT_TRUE(frame.widenLeft.empty() && frame.widenRight.empty());  // 1: the thesis's uniform width

  fitWidening(outline, frame, line, blob, 0.0, 0.25, 1.5);
  ASSERT_EQ(frame.widenLeft.size(), frame.widenRight.size());
  ASSERT_FALSE(frame.widenLeft.empty());
  for (double w : frame.widenRight) EXPECT_NEAR(w, 1.0, 1e-3);  // the uniform fit is to 5e-4
  EXPECT_NEAR(frame.widenLeft.front(), 1.0, 1e-3);
  EXPECT_GT(frame.widenLeft.back(), 1.45);
  for (std::size_t i = 0; i < frame.widenLeft.size(); ++i) {
    EXPECT_LE(frame.widenLeft[i], 1.5);
    if (i > 0) {
      EXPECT_LE(std::abs(frame.widenLeft[i] - frame.widenLeft[i - 1]), 0.03 + 1e-12);
    }
  }
  const Region widened = bendRegion(outline, frame, line, 0.25);
  EXPECT_LT(area(subtract(widened, blob)), 1e-9 * area(widened));
  EXPECT_GT(area(widened), 1.05 * uniformArea);

  // Up to the room, not past it: past x = 2 the left has 2 of room against a uniform half-width
  // of 1 (the slope limit allows about 1.7 by the end). Inset by a margin of 0.5 it has 1.5 there,
  // and 0.5 before (less than 1: no widening).
  fitWidening(outline, frame, line, blob, 0.0, 0.25, 3.0);
  const std::vector<double> full = frame.widenLeft;
  EXPECT_GT(full.back(), 1.6);
  EXPECT_LE(full.back(), 2.0 + 1e-3);
  fitWidening(outline, frame, line, blob, 0.5, 0.25, 3.0);
  for (double w : frame.widenRight) EXPECT_NEAR(w, 1.0, 1e-3);
  EXPECT_NEAR(frame.widenLeft.front(), 1.0, 1e-3);
  EXPECT_NEAR(frame.widenLeft.back(), 1.5, 0.01);
  for (std::size_t i = 0; i < full.size(); ++i) EXPECT_LE(frame.widenLeft[i], full[i] + 1e-12);
}

TEST(SkeletalStroke, BadInputThrows) {
  StrokeFrame frame = strokeFrameFor(element(), {0, 0}, {4, 0});
  Polyline line = straight({0, 0}, {8, 0}, 2);
  EXPECT_THROW(strokeFrameFor(element(), {1, 1}, {1, 1}), InputError);
  EXPECT_THROW(strokeFrameFor({}, {0, 0}, {1, 0}), InputError);
  EXPECT_THROW(bendRegion(element(), frame, line, 0.0), InputError);
  EXPECT_THROW(bendRegion(element(), frame, {{1, 1}}, 0.5), InputError);
  frame.widthScale = -1;
  EXPECT_THROW(bendRegion(element(), frame, line, 0.5), InputError);
  frame.widthScale = 1;
  EXPECT_THROW(bendRing({{0, 0}, {std::nan(""), 1}, {1, 1}}, frame, line, 0.5), InputError);
  EXPECT_THROW(fitWidthScale(element(), frame, line, rectangle(0, -5, 8, 5), 0.5, 0.0), InputError);
}

}  // namespace
}  // namespace pak
