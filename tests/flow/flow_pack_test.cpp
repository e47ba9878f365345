// packFlow end to end on small scenes built in code: no overlaps, everything inside, fixed
// elements and fixed spines respected, refinement keeps or raises the element area, and a
// seed reproduces the packing.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>

#include "pak/error.hpp"
#include "pak/flow/flow.hpp"
#include "pak/geom/clipping.hpp"
#include "pak/geom/verify.hpp"

namespace pak {
namespace {

Ring box(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

Ring circle(Vec2 c, double r, int n = 64) {
  Ring ring;
  for (int i = 0; i < n; ++i) {
    double a = 2.0 * M_PI * i / n;
    ring.push_back(c + Vec2{r * std::cos(a), r * std::sin(a)});
  }
  return ring;
}

// A lens-shaped element 100 long and 30 wide along the x axis, drawn in one colour.
ElementArt lens() {
  ElementArt e;
  e.source = "lens.svg";
  e.name = "lens";
  Ring ring;
  for (int i = 0; i <= 20; ++i) ring.push_back({5.0 * i, 15.0 * std::sin(M_PI * i / 20.0)});
  for (int i = 19; i >= 1; --i) ring.push_back({5.0 * i, -15.0 * std::sin(M_PI * i / 20.0)});
  Shape s;
  s.subpaths.push_back({ring, true});
  s.fill = Color{20, 100, 140, 1.0};
  e.shapes.push_back(s);
  e.outline = filledRegion(s);
  e.spine = std::array<Vec2, 2>{Vec2{0, 0}, Vec2{100, 0}};
  return e;
}

// A half-lens: one-sided, entirely left of (above, y up) its spine.
ElementArt halfLens() {
  ElementArt e = lens();
  e.source = "half.svg";
  e.name = "half";
  Ring ring;
  for (int i = 0; i <= 20; ++i) ring.push_back({5.0 * i, 20.0 * std::sin(M_PI * i / 20.0)});
  e.shapes[0].subpaths[0].points = ring;
  e.shapes[0].fill = Color{200, 80, 40, 1.0};
  e.outline = filledRegion(e.shapes[0]);
  return e;
}

Scene rectangleScene() {
  Scene scene;
  scene.source = "test";
  scene.container = Region{Polygon{box(0, 0, 400, 200), {}}};
  scene.guides.push_back({{10, 100}, {390, 100}});
  return scene;
}

FlowOptions quickOptions() {
  FlowOptions o;
  o.gap = 70.0;  // canonical: l_canvas is 1000, so this is 28 input units here
  o.minLength = 100.0;
  o.maxLength = 400.0;
  o.iterations = 3;
  o.fieldResolution = 64;
  o.blobResolution = 200;
  o.shiftNeighbours = 40;
  return o;
}

std::vector<Region> outlines(const FlowPacking& p) {
  std::vector<Region> r;
  for (const FlowElement& e : p.elements) r.push_back(e.outline);
  for (const FlowElement& e : p.gapElements) r.push_back(e.outline);
  if (!p.fixedArt.empty()) r.push_back(p.fixedArt);
  return r;
}

void expectValidPacking(const FlowPacking& p) {
  PackingCheckOptions check;
  check.areaTolerance = 1e-6 * area(p.container);
  PackingCheck result = verifyPacking(outlines(p), p.container, check);
  EXPECT_TRUE(result.ok) << (result.problems.empty() ? "" : result.problems.front());
  for (const FlowElement& e : p.elements) {
    EXPECT_GT(e.area, 0.0);
    EXPECT_NEAR(e.area, area(e.outline), 1e-9 * e.area);
    EXPECT_FALSE(e.art.empty());
  }
}

TEST(FlowPack, RectangleIsFilledWithoutOverlapsAndRefinementKeepsTheArea) {
  Library library{lens(), halfLens()};
  FlowPacking p = packFlow(rectangleScene(), library, quickOptions());
  ASSERT_GE(p.elements.size(), 4u);
  expectValidPacking(p);
  ASSERT_EQ(p.areaPerIteration.size(), 4u);  // after placement and each of 3 iterations
  EXPECT_GE(p.areaPerIteration.back(), p.areaPerIteration.front());
  EXPECT_GT(flowFill(p), 0.2);
  EXPECT_LT(flowFill(p), 1.0);
}

TEST(FlowPack, TheTimeLimitAndAStopRequestEndRefinementWithACleanPacking) {
  Library library{lens(), halfLens()};
  FlowOptions o = quickOptions();
  o.iterations = 1000;
  o.timeLimit = 1e-9;  // spent before the first wave
  FlowPacking limited = packFlow(rectangleScene(), library, o);
  EXPECT_EQ(limited.stopReason, StopReason::TimeLimit);
  EXPECT_EQ(limited.iterations, 0);
  ASSERT_GE(limited.elements.size(), 4u);  // the placement is kept
  expectValidPacking(limited);

  const std::atomic<bool> stop{true};
  o.timeLimit = 0.0;
  o.run.stopRequest = &stop;
  FlowPacking interrupted = packFlow(rectangleScene(), library, o);
  EXPECT_EQ(interrupted.stopReason, StopReason::Interrupted);
  EXPECT_EQ(interrupted.iterations, 0);
  expectValidPacking(interrupted);
  EXPECT_EQ(packFlow(rectangleScene(), library, quickOptions()).stopReason, StopReason::IterationCap);
}

TEST(FlowPack, WithToleranceOneTheAreaNeverFalls) {
  FlowOptions o = quickOptions();
  o.growthTolerance = 1.0;
  FlowPacking p = packFlow(rectangleScene(), Library{lens()}, o);
  for (std::size_t k = 1; k < p.areaPerIteration.size(); ++k)
    EXPECT_GE(p.areaPerIteration[k], p.areaPerIteration[k - 1] * (1.0 - 1e-12)) << "iteration " << k;
}

TEST(FlowPack, ASeedReproducesThePackingExactly) {
  Library library{lens(), halfLens()};
  FlowPacking a = packFlow(rectangleScene(), library, quickOptions());
  FlowPacking b = packFlow(rectangleScene(), library, quickOptions());
  ASSERT_EQ(a.elements.size(), b.elements.size());
  for (std::size_t i = 0; i < a.elements.size(); ++i) {
    ASSERT_EQ(a.elements[i].streamline.size(), b.elements[i].streamline.size());
    for (std::size_t k = 0; k < a.elements[i].streamline.size(); ++k)
      EXPECT_EQ(a.elements[i].streamline[k], b.elements[i].streamline[k]);
    EXPECT_EQ(a.elements[i].area, b.elements[i].area);
  }
}

// The refinement runs on several threads with the sequential loop's result.
TEST(FlowPack, AnyThreadCountGivesTheSamePacking) {
  Library library{lens(), halfLens()};
  FlowOptions o = quickOptions();
  o.iterations = 4;
  o.infillEvery = 2;  // pockets filled between the waves too
  o.run.threads = 1;
  const FlowPacking one = packFlow(rectangleScene(), library, o);
  for (int threads : {2, 3}) {
    o.run.threads = threads;
    const FlowPacking many = packFlow(rectangleScene(), library, o);
    ASSERT_EQ(one.elements.size(), many.elements.size()) << threads << " threads";
    EXPECT_EQ(one.placementsTried, many.placementsTried);
    EXPECT_EQ(one.placementsAccepted, many.placementsAccepted);
    for (std::size_t i = 0; i < one.elements.size(); ++i) {
      EXPECT_EQ(one.elements[i].streamline, many.elements[i].streamline) << "element " << i;
      EXPECT_EQ(one.elements[i].area, many.elements[i].area) << "element " << i;
      EXPECT_EQ(one.elements[i].libraryIndex, many.elements[i].libraryIndex) << "element " << i;
    }
  }
}

// The rectangle with a fixed disc, the sun, in its middle.
Scene rectangleWithSun() {
  Scene scene = rectangleScene();
  Shape sun;
  sun.subpaths.push_back({circle({200, 100}, 30), true});
  sun.fill = Color{240, 180, 50, 1.0};
  scene.fixed.push_back(sun);
  return scene;
}

TEST(FlowPack, FixedElementsAndFixedSpinesAreRespected) {
  Scene scene = rectangleWithSun();
  scene.spines.push_back({{40, 30}, {140, 30}});
  FlowPacking p = packFlow(scene, Library{lens()}, quickOptions());
  expectValidPacking(p);  // fixedArt counts as one more element: nothing overlaps it
  int onSpine = 0;
  for (const FlowElement& e : p.elements)
    if (e.fixedSpine) {
      ++onSpine;
      // The spine is kept where the artist drew it.
      EXPECT_EQ(e.streamline.front(), (Vec2{40, 30}));
      EXPECT_EQ(e.streamline.back(), (Vec2{140, 30}));
    }
  EXPECT_EQ(onSpine, 1);
}

// Streamlines stop short of the disc in the middle of the rectangle and leave pockets there
// and in the corners; the infill puts elements in them, between the refinement iterations.
TEST(FlowPack, InfillPutsElementsInThePocketsTheStreamlinesLeave) {
  const Scene scene = rectangleWithSun();
  Library library{lens()};
  FlowOptions o = quickOptions();
  o.infillEvery = 0;
  const FlowPacking without = packFlow(scene, library, o);
  EXPECT_EQ(without.infilled, 0);
  o.infillEvery = 1;
  const FlowPacking with = packFlow(scene, library, o);
  expectValidPacking(with);
  EXPECT_GE(with.infilled, 1);
  EXPECT_GT(flowFill(with), flowFill(without));
}

// A fixed spine with a hairpin turn tighter than the lens is wide: bent along it, the lens
// folds over itself. Pak refuses that placement unless asked to keep folds (the thesis).
TEST(FlowPack, AnElementIsNotPlacedWhereItWouldFoldOverItself) {
  Scene scene = rectangleScene();
  Polyline hairpin;
  for (int i = 0; i <= 8; ++i) hairpin.push_back({60.0 + 10.0 * i, 40.0});
  for (int i = 1; i < 12; ++i) {
    const double a = -M_PI / 2 + M_PI * i / 12;
    hairpin.push_back(Vec2{140, 46} + Vec2{6 * std::cos(a), 6 * std::sin(a)});
  }
  for (int i = 8; i >= 0; --i) hairpin.push_back({60.0 + 10.0 * i, 52.0});
  scene.spines.push_back(hairpin);
  auto folded = [](const FlowPacking& p) {
    int n = 0;
    for (const FlowElement& e : p.elements)
      for (const Polygon& polygon : e.outline) n += ringSelfIntersects(polygon.outer) ? 1 : 0;
    return n;
  };
  FlowOptions o = quickOptions();
  o.keepFolds = true;
  const FlowPacking kept = packFlow(scene, Library{lens()}, o);
  EXPECT_GE(folded(kept), 1) << "the test's hairpin no longer folds the lens";
  o.keepFolds = false;
  const FlowPacking refused = packFlow(scene, Library{lens()}, o);
  EXPECT_EQ(folded(refused), 0);
  expectValidPacking(refused);
}

TEST(FlowPack, MirrorReflectsTheLeftHalf) {
  FlowOptions o = quickOptions();
  o.mirror = MirrorLine::vertical(200.0);
  FlowPacking p = packFlow(rectangleScene(), Library{lens()}, o);
  ASSERT_EQ(p.elements.size() % 2, 0u);
  const std::size_t half = p.elements.size() / 2;
  for (std::size_t i = 0; i < half; ++i) {
    EXPECT_LE(bounds(p.elements[i].outline).max.x, 200.0);
    EXPECT_NEAR(area(p.elements[i].outline), area(p.elements[i + half].outline), 1e-9 * p.elements[i].area);
    EXPECT_NEAR(bounds(p.elements[i + half].outline).min.x, 400.0 - bounds(p.elements[i].outline).max.x, 1e-9);
  }
  expectValidPacking(p);
}

// Any line: the square's diagonal, walked from its bottom-left corner to its top-right (y
// down, so up the screen), packs the upper-left half; every element there has its reflection
// in the other.
TEST(FlowPack, MirrorAcrossAnObliqueLineReflectsEveryElement) {
  Scene scene;
  scene.source = "test";
  scene.container = Region{Polygon{box(0, 0, 200, 200), {}}};
  scene.guides.push_back({{20, 180}, {180, 20}});
  FlowOptions o = quickOptions();
  o.mirror = MirrorLine{{0, 200}, {200, 0}};
  FlowPacking p = packFlow(scene, Library{lens()}, o);
  ASSERT_GE(p.elements.size(), 2u);
  ASSERT_EQ(p.elements.size() % 2, 0u);
  const std::size_t half = p.elements.size() / 2;
  for (std::size_t i = 0; i < half; ++i) {
    const FlowElement &packed = p.elements[i], &twin = p.elements[i + half];
    for (const Vec2 q : packed.outline.front().outer) EXPECT_LE(q.x + q.y, 200.0 + 1e-6);  // above the diagonal
    EXPECT_NEAR(area(packed.outline), area(twin.outline), 1e-9 * packed.area);
    const Vec2 mirrored = o.mirror->reflect(packed.streamline.front());
    EXPECT_NEAR(twin.streamline.front().x, mirrored.x, 1e-9);
    EXPECT_NEAR(twin.streamline.front().y, mirrored.y, 1e-9);
  }
  expectValidPacking(p);
}

TEST(FlowPack, FillGapsAddsShapesOnlyInTheNegativeSpace) {
  FlowOptions o = quickOptions();
  o.fillGaps = true;
  FlowPacking p = packFlow(rectangleScene(), Library{lens()}, o);
  EXPECT_FALSE(p.gapElements.empty());
  expectValidPacking(p);
}

TEST(FlowPack, AContainerWithoutAGuideIsAnInputError) {
  Scene scene = rectangleScene();
  scene.guides.clear();
  EXPECT_THROW(packFlow(scene, Library{lens()}, quickOptions()), InputError);
  EXPECT_THROW(packFlow(rectangleScene(), Library{}, quickOptions()), InputError);
  FlowOptions bad = quickOptions();
  bad.minLength = 500.0;
  bad.maxLength = 100.0;
  EXPECT_THROW(packFlow(rectangleScene(), Library{lens()}, bad), InputError);
}

}  // namespace
}  // namespace pak
