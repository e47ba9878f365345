// Parser tests on small hand-written SVG documents whose geometry is known exactly.
#include "pak/io/svg_reader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "pak/error.hpp"

namespace pak {
namespace {

constexpr double kPi = std::numbers::pi;

std::string svg(const std::string& body, const std::string& rootAttributes = R"~(viewBox="0 0 100 100")~") {
  return R"~(<svg xmlns="http://www.w3.org/2000/svg" xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape" )~" +
         rootAttributes + ">" + body + "</svg>";
}

SvgDocument read(const std::string& body, const std::string& rootAttributes = R"~(viewBox="0 0 100 100")~") {
  return readSvgString(svg(body, rootAttributes), "test.svg");
}

// Area of the fill of the only shape of a one-shape document.
double fillArea(const std::string& body) {
  SvgDocument document = read(body);
  EXPECT_EQ(document.shapes.size(), 1u) << body;
  if (document.shapes.empty()) return 0.0;
  return area(filledRegion(document.shapes.front()));
}

std::vector<Vec2> pointsOf(const std::string& body) {
  SvgDocument document = read(body);
  EXPECT_EQ(document.shapes.size(), 1u) << body;
  if (document.shapes.empty() || document.shapes.front().subpaths.empty()) return {};
  return document.shapes.front().subpaths.front().points;
}

void expectSamePoints(const std::vector<Vec2>& a, const std::vector<Vec2>& b, double tolerance = 1e-9) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_NEAR(a[i].x, b[i].x, tolerance) << "point " << i;
    EXPECT_NEAR(a[i].y, b[i].y, tolerance) << "point " << i;
  }
}

std::string errorOf(const std::string& text, const std::string& name = "bad.svg") {
  try {
    readSvgString(text, name);
  } catch (const InputError& error) {
    return error.what();
  }
  return "(no error)";
}

// ---- path commands -----------------------------------------------------------------------

TEST(SvgReaderPath, AbsoluteLinesAndClose) {
  EXPECT_NEAR(fillArea(R"~(<path d="M10 10 L30 10 L30 20 L10 20 Z"/>)~"), 200.0, 1e-9);
}

TEST(SvgReaderPath, RelativeLinesAndClose) {
  EXPECT_NEAR(fillArea(R"~(<path d="m10 10 l20 0 l0 10 l-20 0 z"/>)~"), 200.0, 1e-9);
}

TEST(SvgReaderPath, HorizontalAndVertical) {
  EXPECT_NEAR(fillArea(R"~(<path d="M10 10 H30 V20 H10 Z"/>)~"), 200.0, 1e-9);
  EXPECT_NEAR(fillArea(R"~(<path d="M10 10 h20 v10 h-20 z"/>)~"), 200.0, 1e-9);
  expectSamePoints(pointsOf(R"~(<path d="M10 10 h20 v10 H10 z"/>)~"), {{10, 10}, {30, 10}, {30, 20}, {10, 20}});
}

TEST(SvgReaderPath, ImplicitRepeats) {
  // Pairs after M are line-tos; after m they are relative line-tos; repeated L and l.
  expectSamePoints(pointsOf(R"~(<path d="M10 10 30 10 30 20 10 20z"/>)~"), {{10, 10}, {30, 10}, {30, 20}, {10, 20}});
  expectSamePoints(pointsOf(R"~(<path d="m10 10 20 0 0 10 -20 0z"/>)~"), {{10, 10}, {30, 10}, {30, 20}, {10, 20}});
  expectSamePoints(pointsOf(R"~(<path d="M10 10 L30 10 30 20 10 20z"/>)~"), {{10, 10}, {30, 10}, {30, 20}, {10, 20}});
  expectSamePoints(pointsOf(R"~(<path d="M10 10 l20 0 0 10 -20 0z"/>)~"), {{10, 10}, {30, 10}, {30, 20}, {10, 20}});
}

TEST(SvgReaderPath, CompactNumbers) {
  // "1.5.5" is 1.5 then .5; exponents; signs as separators.
  expectSamePoints(pointsOf(R"~(<path d="M0,0L1.5.5L1e1-2e-1"/>)~"), {{0, 0}, {1.5, 0.5}, {10, -0.2}});
  expectSamePoints(pointsOf(R"~(<path d="M0 0L1e-3 0 1E+1 5"/>)~"), {{0, 0}, {0.001, 0}, {10, 5}});
}

TEST(SvgReaderPath, SubpathAfterCloseStartsAtTheClosedStart) {
  SvgDocument document = read(R"~(<path d="M0 0 L10 0 L10 10 Z L0 -10 L10 -10"/>)~");
  ASSERT_EQ(document.shapes.size(), 1u);
  ASSERT_EQ(document.shapes[0].subpaths.size(), 2u);
  expectSamePoints(document.shapes[0].subpaths[1].points, {{0, 0}, {0, -10}, {10, -10}});
  EXPECT_TRUE(document.shapes[0].subpaths[0].closed);
  EXPECT_FALSE(document.shapes[0].subpaths[1].closed);
}

TEST(SvgReaderPath, FullCircleFromTwoArcs) {
  const double expected = kPi * 20 * 20;
  EXPECT_NEAR(fillArea(R"~(<path d="M50 30 A20 20 0 1 0 50 70 A20 20 0 1 0 50 30 Z"/>)~"), expected, expected * 2e-3);
  EXPECT_NEAR(fillArea(R"~(<path d="m50 30 a20 20 0 1 0 0 40 a20 20 0 1 0 0 -40 z"/>)~"), expected, expected * 2e-3);
}

// What an editor would show as Bézier points: 1 per move or line, 3 per cubic (quadratics and
// arcs become cubics, an arc one per quarter turn at most), nothing for Z.
TEST(SvgReaderPath, CountsThePointsAShapeWasDrawnWith) {
  auto drawn = [](const std::string& body) {
    SvgDocument document = read(body);
    EXPECT_EQ(document.shapes.size(), 1u) << body;
    return document.shapes.empty() ? -1 : document.shapes[0].drawnPoints;
  };
  EXPECT_EQ(drawn(R"~(<path d="M10 10 L40 10 C50 10 50 30 40 30 Q30 40 10 30 Z"/>)~"), 1 + 1 + 3 + 3);
  // Two half circles: two cubics each at least, three when rounding puts a half turn just
  // over two quarter turns.
  const int circle = drawn(R"~(<path d="M50 30 A20 20 0 1 0 50 70 A20 20 0 1 0 50 30 Z"/>)~");
  EXPECT_GE(circle, 1 + 4 * 3);
  EXPECT_LE(circle, 1 + 6 * 3);
  EXPECT_EQ(drawn(R"~(<path d="M10 10 h20 v20 h-20 z M60 60 l5 5"/>)~"), 4 + 2);
}

TEST(SvgReaderPath, ArcFlagsPickTheRightHalf) {
  // A half disc of radius 10 closed by its diameter: small/large and sweep both give a half.
  const double half = kPi * 100 / 2;
  EXPECT_NEAR(fillArea(R"~(<path d="M40 50 A10 10 0 0 1 60 50 Z"/>)~"), half, half * 2e-3);
  // An arc of radius 20 spanning a chord of 20: the small segment vs the large one.
  const double r = 20, theta = 2 * std::asin(10.0 / 20.0);
  const double smallSegment = r * r / 2 * (theta - std::sin(theta));
  const double largeSegment = kPi * r * r - smallSegment;
  EXPECT_NEAR(fillArea(R"~(<path d="M40 50 A20 20 0 0 1 60 50 Z"/>)~"), smallSegment, smallSegment * 1e-2);
  EXPECT_NEAR(fillArea(R"~(<path d="M40 50 A20 20 0 1 1 60 50 Z"/>)~"), largeSegment, largeSegment * 2e-3);
}

TEST(SvgReaderPath, ArcRadiiTooSmallAreScaledUp) {
  // SVG scales radii up until the arc fits: a half circle of radius 10.
  const double half = kPi * 100 / 2;
  EXPECT_NEAR(fillArea(R"~(<path d="M40 50 A1 1 0 0 1 60 50 Z"/>)~"), half, half * 2e-3);
}

// SVG's special cases (OpenMoji draws square corners as `a0,0,0,0,1,0,0`): an arc to its own
// start is nothing, a zero radius is a line.
TEST(SvgReaderPath, DegenerateArcsAsSvgSpecifies) {
  EXPECT_NEAR(fillArea(R"~(<path d="M0 0 H10 a0,0,0,0,1,0,0 V10 H0 Z"/>)~"), 100.0, 1e-9);
  EXPECT_NEAR(fillArea(R"~(<path d="M0 0 H10 a5 5 0 0 1 0 0 V10 H0 Z"/>)~"), 100.0, 1e-9);
  EXPECT_NEAR(fillArea(R"~(<path d="M0 0 H10 a0 5 0 0 1 0 10 H0 Z"/>)~"), 100.0, 1e-9);
  EXPECT_NEAR(fillArea(R"~(<path d="M0 0 H10 A5 0 0 0 1 10 10 H0 Z"/>)~"), 100.0, 1e-9);
}

TEST(SvgReaderPath, QuadraticCurveArea) {
  // A parabolic segment: 2/3 of base × height; the curve peaks at half the control height.
  const double segment = 2.0 / 3.0 * 20 * 10;
  EXPECT_NEAR(fillArea(R"~(<path d="M10 50 Q20 70 30 50 Z"/>)~"), segment, segment * 1e-3);
  EXPECT_NEAR(fillArea(R"~(<path d="m10 50 q10 20 20 0 z"/>)~"), segment, segment * 1e-3);
}

TEST(SvgReaderPath, SmoothQuadraticReflectsTheControlPoint) {
  expectSamePoints(pointsOf(R"~(<path d="M10 50 Q20 70 30 50 T50 50"/>)~"),
                   pointsOf(R"~(<path d="M10 50 Q20 70 30 50 Q40 30 50 50"/>)~"));
  expectSamePoints(pointsOf(R"~(<path d="M10 50 q10 20 20 0 t20 0"/>)~"),
                   pointsOf(R"~(<path d="M10 50 Q20 70 30 50 Q40 30 50 50"/>)~"));
}

TEST(SvgReaderPath, CubicQuarterCircle) {
  // The classic cubic approximation of a quarter circle (k = 0.5523) differs from the true
  // quarter disc by less than 0.03 %.
  const double k = 0.55228474983 * 10;
  const std::string d = "M0 0 L10 0 C10 " + std::to_string(k) + " " + std::to_string(k) + " 10 0 10 Z";
  const double quarter = kPi * 100 / 4;
  EXPECT_NEAR(fillArea(R"~(<path d=")~" + d + R"~("/>)~"), quarter, quarter * 1e-3);
  const std::string relative = "m0 0 l10 0 c0 " + std::to_string(k) + " " + std::to_string(k - 10) + " 10 -10 10 z";
  EXPECT_NEAR(fillArea(R"~(<path d=")~" + relative + R"~("/>)~"), quarter, quarter * 1e-3);
}

TEST(SvgReaderPath, SmoothCubicReflectsTheControlPoint) {
  expectSamePoints(pointsOf(R"~(<path d="M0 50 C0 60 10 60 10 50 S20 40 20 50"/>)~"),
                   pointsOf(R"~(<path d="M0 50 C0 60 10 60 10 50 C10 40 20 40 20 50"/>)~"));
  expectSamePoints(pointsOf(R"~(<path d="M0 50 c0 10 10 10 10 0 s10 -10 10 0"/>)~"),
                   pointsOf(R"~(<path d="M0 50 C0 60 10 60 10 50 C10 40 20 40 20 50"/>)~"));
}

TEST(SvgReaderPath, FlatteningHonoursTheTolerance) {
  // Every flattened vertex of a circle lies on it, and chords stay within the tolerance
  // (flatness × viewBox size = 1e-4 × 100).
  SvgDocument document = read(R"~(<circle cx="50" cy="50" r="40"/>)~");
  ASSERT_EQ(document.shapes.size(), 1u);
  const auto& points = document.shapes[0].subpaths[0].points;
  EXPECT_GT(points.size(), 40u);
  EXPECT_LT(points.size(), 2000u);
  for (std::size_t i = 0; i < points.size(); ++i) {
    // Cubic arcs deviate from the true circle by ~2.7e-4 r; the tolerance adds 0.01.
    EXPECT_NEAR(distance(points[i], {50, 50}), 40.0, 40 * 3e-4 + 0.011);
    const Vec2 mid = (points[i] + points[(i + 1) % points.size()]) * 0.5;
    EXPECT_GT(distance(mid, {50, 50}), 40.0 - 40 * 3e-4 - 0.011);
  }
}

// ---- basic shapes ------------------------------------------------------------------------

TEST(SvgReaderShapes, Rect) {
  EXPECT_NEAR(fillArea(R"~(<rect x="10" y="10" width="20" height="30"/>)~"), 600.0, 1e-9);
}

// Chords cut inside curves by at most the flattening tolerance (1e-4 × the 100-wide
// viewBox), so a curved boundary of length L loses at most L × 0.01 of area.
constexpr double kTolerance = 0.01;

TEST(SvgReaderShapes, RoundedRect) {
  const double expected = 20 * 30 - (4 - kPi) * 4 * 4;
  const double corners = 2 * kPi * 4;
  EXPECT_NEAR(fillArea(R"~(<rect x="10" y="10" width="20" height="30" rx="4"/>)~"), expected, corners * kTolerance);
  // ry alone also rounds with rx = ry.
  EXPECT_NEAR(fillArea(R"~(<rect x="10" y="10" width="20" height="30" ry="4"/>)~"), expected, corners * kTolerance);
  // Elliptical corners: (4 − π) rx ry.
  EXPECT_NEAR(fillArea(R"~(<rect x="10" y="10" width="20" height="30" rx="4" ry="2"/>)~"),
              20 * 30 - (4 - kPi) * 4 * 2, corners * kTolerance);
  EXPECT_LT(fillArea(R"~(<rect x="10" y="10" width="20" height="30" rx="4"/>)~"), expected);
}

TEST(SvgReaderShapes, CircleAndEllipse) {
  EXPECT_NEAR(fillArea(R"~(<circle cx="50" cy="50" r="10"/>)~"), kPi * 100, 2 * kPi * 10 * kTolerance);
  // The ellipse's perimeter is below 2π × 20.
  EXPECT_NEAR(fillArea(R"~(<ellipse cx="50" cy="50" rx="20" ry="10"/>)~"), kPi * 200, 2 * kPi * 20 * kTolerance);
}

TEST(SvgReaderShapes, LinePolylinePolygon) {
  SvgDocument document = read(R"~(<line x1="0" y1="0" x2="10" y2="5" stroke="black"/>
      <polyline points="0,0 10,0 10,10" fill="none" stroke="black"/>
      <polygon points="0,0 10,0 10,10 0,10"/>)~");
  ASSERT_EQ(document.shapes.size(), 3u);
  EXPECT_EQ(document.shapes[0].tag, "line");
  EXPECT_FALSE(document.shapes[0].subpaths[0].closed);
  expectSamePoints(document.shapes[0].subpaths[0].points, {{0, 0}, {10, 5}});
  EXPECT_EQ(document.shapes[1].tag, "polyline");
  EXPECT_FALSE(document.shapes[1].subpaths[0].closed);
  EXPECT_EQ(document.shapes[1].subpaths[0].points.size(), 3u);
  EXPECT_EQ(document.shapes[2].tag, "polygon");
  EXPECT_TRUE(document.shapes[2].subpaths[0].closed);
  EXPECT_NEAR(area(filledRegion(document.shapes[2])), 100.0, 1e-9);
}

TEST(SvgReaderShapes, ZeroSizeShapesDrawNothing) {
  SvgDocument document = read(R"~(<rect x="1" y="1" width="0" height="10"/><circle cx="5" cy="5" r="0"/>)~");
  EXPECT_TRUE(document.shapes.empty());
}

// ---- transforms and units ----------------------------------------------------------------

TEST(SvgReaderTransform, NestedTransformsMapCoordinatesExactly) {
  SvgDocument document = read(R"~(<g transform="translate(10,20)"><g transform="scale(2)">
      <path transform="rotate(90)" d="M1 0 L2 0 L2 1 Z"/></g></g>)~");
  ASSERT_EQ(document.shapes.size(), 1u);
  // rotate(90): (x, y) → (−y, x); scale 2; translate (10, 20).
  expectSamePoints(document.shapes[0].subpaths[0].points, {{10, 22}, {10, 24}, {8, 24}}, 1e-12);
}

TEST(SvgReaderTransform, TransformListAndMatrix) {
  SvgDocument document = read(R"~(<path transform="translate(5 5) matrix(1 0 0 -1 0 0) skewX(0)" d="M1 2 L3 2 L3 4 Z"/>)~");
  ASSERT_EQ(document.shapes.size(), 1u);
  expectSamePoints(document.shapes[0].subpaths[0].points, {{6, 3}, {8, 3}, {8, 1}}, 1e-12);
}

TEST(SvgReaderTransform, StrokeWidthScalesWithTheTransform) {
  SvgDocument document = read(R"~(<g transform="scale(3)"><path d="M0 0 L10 0" stroke="red" stroke-width="2"/></g>)~");
  ASSERT_EQ(document.shapes.size(), 1u);
  EXPECT_NEAR(document.shapes[0].strokeWidth, 6.0, 1e-12);
}

TEST(SvgReaderUnits, ViewBoxKeepsUserUnitsAndSizeResolvesMillimetres) {
  SvgDocument document = read(R"~(<rect x="10" y="10" width="20" height="20"/>)~",
                              R"~(width="100mm" height="50mm" viewBox="0 0 200 100")~");
  EXPECT_NEAR(document.width, 100 * 96 / 25.4, 1e-9);
  EXPECT_NEAR(document.height, 50 * 96 / 25.4, 1e-9);
  EXPECT_DOUBLE_EQ(document.viewBox.min.x, 0);
  EXPECT_DOUBLE_EQ(document.viewBox.width(), 200);
  EXPECT_DOUBLE_EQ(document.viewBox.height(), 100);
  // Shapes stay in viewBox coordinates.
  ASSERT_EQ(document.shapes.size(), 1u);
  EXPECT_NEAR(area(filledRegion(document.shapes[0])), 400.0, 1e-9);
}

// The size as written, for outputs to keep: when it sizes the document (a viewBox, or both
// sides), not when the drawing's bounds make the box.
TEST(SvgReaderUnits, SizeIsKeptAsWritten) {
  SvgDocument mm = read("<rect width=\"1\" height=\"1\"/>", R"~(width="100mm" height="50mm" viewBox="0 0 200 100")~");
  EXPECT_EQ(mm.widthText, "100mm");
  EXPECT_EQ(mm.heightText, "50mm");
  SvgDocument percent = read("<rect width=\"1\" height=\"1\"/>", R"~(width="100%" viewBox="0 0 200 100")~");
  EXPECT_EQ(percent.widthText, "100%");
  EXPECT_EQ(percent.heightText, "");
  SvgDocument noBox = read("<rect width=\"1\" height=\"1\"/>", R"~(width="8.5in")~");
  EXPECT_EQ(noBox.widthText, "");
  EXPECT_EQ(read("<rect width=\"1\" height=\"1\"/>", R"~(width="8.5in" height="11in")~").heightText, "11in");
}

TEST(SvgReaderUnits, SizeWithoutViewBoxDefinesIt) {
  SvgDocument document = read(R"~(<rect x="0" y="0" width="1" height="1"/>)~", R"~(width="10mm" height="2.54cm")~");
  EXPECT_NEAR(document.viewBox.width(), 10 * 96 / 25.4, 1e-9);
  EXPECT_NEAR(document.viewBox.height(), 96, 1e-9);
}

TEST(SvgReaderUnits, AllAbsoluteUnitsAndPercent) {
  for (const char* size : {"1in", "72pt", "6pc", "2.54cm", "25.4mm", "96px", "96"}) {
    SvgDocument document = read(R"~(<rect width="1" height="1"/>)~",
                                std::string("width=\"") + size + "\" height=\"" + size + "\"");
    EXPECT_NEAR(document.width, 96, 1e-9) << size;
  }
  SvgDocument document = read(R"~(<rect width="50%" height="10%"/>)~", R"~(width="50%" viewBox="0 0 200 100")~");
  EXPECT_NEAR(document.width, 100, 1e-9);
  ASSERT_EQ(document.shapes.size(), 1u);
  // A rect 50 % × 10 % of the 200 × 100 viewBox.
  EXPECT_NEAR(area(filledRegion(document.shapes[0])), 100 * 10, 1e-9);
}

TEST(SvgReaderUnits, NestedSvgMapsItsViewBox) {
  SvgDocument document = read(R"~(<svg x="10" y="10" width="20" height="20" viewBox="0 0 10 10">
      <rect x="0" y="0" width="10" height="10"/></svg>)~");
  ASSERT_EQ(document.shapes.size(), 1u);
  const Box box = bounds(document.shapes[0]);
  EXPECT_NEAR(box.min.x, 10, 1e-12);
  EXPECT_NEAR(box.max.x, 30, 1e-12);
}

// ---- paint -------------------------------------------------------------------------------

TEST(SvgReaderPaint, DefaultFillIsBlackAndNoStroke) {
  SvgDocument document = read(R"~(<rect width="1" height="1"/>)~");
  ASSERT_EQ(document.shapes.size(), 1u);
  ASSERT_TRUE(document.shapes[0].fill);
  EXPECT_EQ(*document.shapes[0].fill, (Color{0, 0, 0, 1.0}));
  EXPECT_FALSE(document.shapes[0].stroke);
}

TEST(SvgReaderPaint, ColoursFromAttributesStyleAndGroups) {
  SvgDocument document = read(R"~(
      <rect id="attr" width="1" height="1" fill="#ff8000" stroke="rgb(1,2,3)" stroke-width="3"/>
      <rect id="style" width="1" height="1" fill="red" style="fill:#00ff00;stroke:blue"/>
      <g fill="navy" stroke="#abc" style="stroke-width:2"><rect id="inherited" width="1" height="1"/>
        <g fill="none"><rect id="none" width="1" height="1" stroke="none"/></g></g>
      <g color="#123456"><rect id="current" width="1" height="1" fill="currentColor"/></g>)~");
  ASSERT_EQ(document.shapes.size(), 5u);
  const SvgShape& attr = document.shapes[0];
  EXPECT_EQ(attr.id, "attr");
  EXPECT_EQ(*attr.fill, (Color{255, 128, 0, 1.0}));
  EXPECT_EQ(*attr.stroke, (Color{1, 2, 3, 1.0}));
  EXPECT_DOUBLE_EQ(attr.strokeWidth, 3.0);
  const SvgShape& style = document.shapes[1];
  EXPECT_EQ(*style.fill, (Color{0, 255, 0, 1.0}));
  EXPECT_EQ(*style.stroke, (Color{0, 0, 255, 1.0}));
  const SvgShape& inherited = document.shapes[2];
  EXPECT_EQ(*inherited.fill, (Color{0, 0, 128, 1.0}));
  EXPECT_EQ(*inherited.stroke, (Color{0xaa, 0xbb, 0xcc, 1.0}));
  EXPECT_DOUBLE_EQ(inherited.strokeWidth, 2.0);
  const SvgShape& none = document.shapes[3];
  EXPECT_FALSE(none.fill);
  EXPECT_FALSE(none.stroke);
  EXPECT_EQ(*document.shapes[4].fill, (Color{0x12, 0x34, 0x56, 1.0}));
}

// Inkscape writes rgb() with decimal components (CSS Color 4); they round to the nearest
// integer instead of being refused, in attributes, style and stylesheets alike.
TEST(SvgReaderPaint, RgbWithDecimalComponentsRounds) {
  SvgDocument document = read(
      R"~(<style>.s { stroke: rgb(0.4, 254.6, 9e1) }</style>)~"
      R"~(<rect width="10" height="10" fill="rgb(12.5, 100.2, 200)"/>)~"
      R"~(<rect width="10" height="10" class="s" style="fill:RGB(300.7, -2.2, 10.49)"/>)~"
      R"~(<rect width="10" height="10" fill="rgb(10%, 50.5%, 100%)"/>)~");
  ASSERT_EQ(document.shapes.size(), 3u);
  EXPECT_EQ(*document.shapes[0].fill, (Color{13, 100, 200, 1.0}));
  EXPECT_EQ(*document.shapes[1].fill, (Color{255, 0, 10, 1.0}));  // clamped to 0-255
  EXPECT_EQ(*document.shapes[1].stroke, (Color{0, 255, 90, 1.0}));
  EXPECT_EQ(*document.shapes[2].fill, (Color{25, 128, 255, 1.0}));  // percentages as before
  EXPECT_TRUE(document.warnings.empty()) << (document.warnings.empty() ? "" : document.warnings.front().message);
}

TEST(SvgReaderPaint, OpacitiesMultiplyDownTheTree) {
  SvgDocument document = read(R"~(<g opacity="0.5"><g style="opacity:0.5">
      <rect width="1" height="1" opacity="0.8" fill-opacity="0.25" stroke="red" stroke-opacity="0.75"/></g></g>)~");
  ASSERT_EQ(document.shapes.size(), 1u);
  const SvgShape& shape = document.shapes[0];
  EXPECT_NEAR(shape.opacity, 0.2, 1e-12);
  EXPECT_NEAR(shape.fill->alpha, 0.25, 1e-12);
  EXPECT_NEAR(shape.stroke->alpha, 0.75, 1e-12);
}

TEST(SvgReaderPaint, GradientBecomesTheMeanOfItsStops) {
  SvgDocument document = read(R"~(<defs>
      <linearGradient id="stops"><stop offset="0" stop-color="#ff0000"/>
        <stop offset="1" style="stop-color:#0000ff;stop-opacity:0.5"/></linearGradient>
      <linearGradient id="g" xlink:href="#stops" xmlns:xlink="http://www.w3.org/1999/xlink"/></defs>
      <rect width="10" height="10" fill="url(#g)"/>
      <rect width="10" height="10" fill="url(#missing) #00ff00"/>)~");
  ASSERT_EQ(document.shapes.size(), 2u);
  EXPECT_EQ(document.shapes[0].fill->r, 128);
  EXPECT_EQ(document.shapes[0].fill->g, 0);
  EXPECT_EQ(document.shapes[0].fill->b, 128);
  EXPECT_NEAR(document.shapes[0].fill->alpha, 0.75, 1e-12);
  EXPECT_EQ(*document.shapes[1].fill, (Color{0, 255, 0, 1.0}));
  EXPECT_FALSE(document.warnings.empty());
}

// A paint server that is not in the file paints nothing, as in a browser (flag-icons' sh-ac
// refers to gradients it lacks); one that is there but not supported (a pattern) is grey.
TEST(SvgReaderPaint, MissingPaintServerPaintsNothing) {
  SvgDocument document = read(R"~(<defs><pattern id="dots" width="2" height="2"/></defs>
      <rect id="lost" width="10" height="10" fill="url(#nowhere)" stroke="url(#dots)"/>)~");
  ASSERT_EQ(document.shapes.size(), 1u);
  EXPECT_FALSE(document.shapes[0].fill.has_value());
  EXPECT_EQ(*document.shapes[0].stroke, (Color{128, 128, 128, 1.0}));
  ASSERT_EQ(document.warnings.size(), 2u);
  EXPECT_NE(document.warnings[0].message.find("#nowhere does not exist; not painted"), std::string::npos);
  EXPECT_NE(document.warnings[1].message.find("#dots is not supported; painted grey"), std::string::npos);
}

TEST(SvgReaderPaint, StylesheetClassesLikeIllustratorWrites) {
  SvgDocument document = read(R"~(<defs><style><![CDATA[
        /* Illustrator's internal CSS */
        .cls-1 { fill: #ff0000; }  #special{fill:#00ff00}
        rect{stroke:#0000ff} g .ignored{fill:#123456} @media print { .cls-1 { fill: black } }
        .cls-2, .cls-3 { fill-opacity: 0.5 }]]></style></defs>
      <rect id="a" class="cls-1" width="1" height="1"/>
      <rect id="special" class="cls-1" width="1" height="1"/>
      <rect id="inline" class="cls-1" width="1" height="1" style="fill:#0000ff"/>
      <rect id="attribute" class="cls-1 cls-3" width="1" height="1" fill="#ffff00"/>
      <circle id="plain" class="ignored" r="1"/>)~");
  ASSERT_EQ(document.shapes.size(), 5u);
  EXPECT_EQ(*document.shapes[0].fill, (Color{255, 0, 0, 1.0}));
  EXPECT_EQ(*document.shapes[0].stroke, (Color{0, 0, 255, 1.0}));
  EXPECT_EQ(*document.shapes[1].fill, (Color{0, 255, 0, 1.0}));  // #id beats .class
  EXPECT_EQ(*document.shapes[2].fill, (Color{0, 0, 255, 1.0}));  // style="…" beats the sheet
  EXPECT_EQ(*document.shapes[3].fill, (Color{255, 0, 0, 0.5}));  // the sheet beats fill="…"
  EXPECT_EQ(*document.shapes[4].fill, (Color{0, 0, 0, 1.0}));    // descendant selectors ignored
  EXPECT_FALSE(document.shapes[4].stroke);
}

// ---- visibility, fill rules, structure ---------------------------------------------------

TEST(SvgReaderVisibility, HiddenThingsAreSkipped) {
  SvgDocument document = read(R"~(
      <rect id="shown" width="1" height="1"/>
      <rect id="a" width="1" height="1" display="none"/>
      <rect id="b" width="1" height="1" style="display:none"/>
      <g style="display:none"><rect id="c" width="1" height="1" style="display:inline"/></g>
      <rect id="d" width="1" height="1" visibility="hidden"/>
      <g visibility="hidden"><rect id="e" width="1" height="1"/>
        <rect id="shown-again" width="1" height="1" visibility="visible"/></g>)~");
  ASSERT_EQ(document.shapes.size(), 2u);
  EXPECT_EQ(document.shapes[0].id, "shown");
  EXPECT_EQ(document.shapes[1].id, "shown-again");
}

TEST(SvgReaderVisibility, DefinitionsAreNotDrawn) {
  SvgDocument document = read(R"~(
      <defs><rect id="in-defs" width="1" height="1"/></defs>
      <clipPath id="clip"><rect width="1" height="1"/></clipPath>
      <mask id="mask"><rect width="1" height="1"/></mask>
      <symbol id="symbol"><rect width="1" height="1"/></symbol>
      <rect id="drawn" width="1" height="1"/>)~");
  ASSERT_EQ(document.shapes.size(), 1u);
  EXPECT_EQ(document.shapes[0].id, "drawn");
}

TEST(SvgReaderVisibility, TextAndImageAreSkippedWithAWarning) {
  SvgDocument document = read(R"~(<rect id="r" width="1" height="1"/>
      <text x="1" y="1">Hello <tspan>world</tspan></text>
      <image width="10" height="10" href="cat.png"/>)~");
  EXPECT_EQ(document.shapes.size(), 1u);
  int skipped = 0;
  for (const Warning& warning : document.warnings)
    if (warning.message.find("not supported") != std::string::npos) ++skipped;
  EXPECT_EQ(skipped, 2);
}

// Inkscape's flowed text (<flowRoot>, in its examples) is text to the artist, and the warning
// names the element itself, not the shape read before it.
TEST(SvgReaderVisibility, FlowedTextIsSkippedAsText) {
  SvgDocument document = read(R"~(<rect id="before" width="1" height="1"/>
      <flowRoot id="note"><flowRegion><rect width="50" height="50"/></flowRegion><flowPara>Hi</flowPara></flowRoot>)~");
  EXPECT_EQ(document.shapes.size(), 1u);
  ASSERT_EQ(document.warnings.size(), 1u);
  EXPECT_EQ(document.warnings[0].where, "test.svg: <flowRoot id=\"note\">");
  EXPECT_NE(document.warnings[0].message.find("(flowed text) is not supported"), std::string::npos);
}

// ---- <use> ---------------------------------------------------------------------------------

int warningsContaining(const SvgDocument& document, const std::string& text) {
  int n = 0;
  for (const Warning& warning : document.warnings)
    if (warning.message.find(text) != std::string::npos) ++n;
  return n;
}

// A use draws a copy of what it references, moved by x/y after its own transform; the
// original in <defs> stays undrawn; href and xlink:href both work.
TEST(SvgReaderUse, CopiesTheReferencedShapeMovedByXYAfterItsTransform) {
  SvgDocument document = read(R"~(<defs><rect id="unit" width="1" height="1"/></defs>
      <use href="#unit" x="5" y="7"/>
      <use xmlns:xlink="http://www.w3.org/1999/xlink" xlink:href="#unit" x="5" transform="scale(2)"/>)~");
  ASSERT_EQ(document.shapes.size(), 2u);
  EXPECT_EQ(document.shapes[0].subpaths[0].points[0].x, 5.0);
  EXPECT_EQ(document.shapes[0].subpaths[0].points[0].y, 7.0);
  expectSamePoints(document.shapes[1].subpaths[0].points, {{10, 0}, {12, 0}, {12, 2}, {10, 2}});
  EXPECT_EQ(warningsContaining(document, "use"), 0);
}

// A group is copied whole; the copy inherits paint from the use, not from the original's
// place, and what the original sets itself wins.
TEST(SvgReaderUse, CopiesGroupsInheritingFromTheUse) {
  SvgDocument document = read(R"~(<g id="pair" fill="#00f"><rect width="1" height="1"/>
      <rect x="2" width="1" height="1" fill="#0f0"/></g>
      <g fill="#f00"><use href="#pair" y="10"/></g>
      <defs><g id="loose"><rect width="1" height="1"/></g></defs><use href="#loose" fill="#f00"/>)~");
  ASSERT_EQ(document.shapes.size(), 5u);
  EXPECT_EQ(document.shapes[2].fill->b, 255);  // the group's own fill travels with it
  EXPECT_EQ(document.shapes[3].fill->g, 255);
  EXPECT_EQ(document.shapes[2].subpaths[0].points[0].y, 10.0);
  EXPECT_EQ(document.shapes[4].fill->r, 255);  // nothing set: the use's fill
}

// A use inside what another use copies is expanded too; a symbol is copied like a group.
TEST(SvgReaderUse, NestedUsesAndSymbols) {
  SvgDocument document = read(R"~(<defs><symbol id="dot"><circle r="1"/></symbol>
      <g id="row"><use href="#dot" x="0"/><use href="#dot" x="10"/></g></defs>
      <use href="#row" y="5"/><use href="#row" y="15"/>)~");
  ASSERT_EQ(document.shapes.size(), 4u);
  EXPECT_NEAR(bounds(document.shapes[3]).min.x, 9.0, 1e-3);  // the circle, flattened
  EXPECT_NEAR(bounds(document.shapes[3]).min.y, 14.0, 1e-3);
}

// Missing and cyclic references are warnings, never a crash or a hang; an exponential chain
// of uses stops at the copy budget.
TEST(SvgReaderUse, MissingAndRecursiveReferencesWarn) {
  SvgDocument missing = read(R"~(<rect width="1" height="1"/><use href="#nowhere"/><use href="other.svg#x"/><use/>)~");
  EXPECT_EQ(missing.shapes.size(), 1u);
  EXPECT_EQ(warningsContaining(missing, "#nowhere: no element has that id"), 1);
  EXPECT_EQ(warningsContaining(missing, "another file"), 1);
  EXPECT_EQ(warningsContaining(missing, "without href"), 1);

  SvgDocument self = read(R"~(<g id="a"><rect width="1" height="1"/><use href="#a" x="2"/></g>)~");
  EXPECT_EQ(self.shapes.size(), 1u);
  EXPECT_EQ(warningsContaining(self, "a cycle"), 1);

  SvgDocument mutual = read(R"~(<g id="a"><rect width="1" height="1"/><use href="#b"/></g>
      <g id="b"><rect width="1" height="1"/><use href="#a"/></g>)~");
  EXPECT_GE(warningsContaining(mutual, "a cycle"), 1);
  EXPECT_LT(mutual.shapes.size(), 10u);

  std::string laughs = R"~(<defs><rect id="l0" width="1" height="1"/>)~";
  for (int level = 1; level <= 8; ++level) {
    laughs += "<g id=\"l" + std::to_string(level) + "\">";
    for (int i = 0; i < 10; ++i) laughs += "<use href=\"#l" + std::to_string(level - 1) + "\"/>";
    laughs += "</g>";
  }
  laughs += R"~(</defs><use href="#l8"/>)~";
  SvgDocument bomb = read(laughs);
  EXPECT_GE(warningsContaining(bomb, "elements; skipped"), 1);
  EXPECT_LT(bomb.shapes.size(), 200000u);
}



// ---- strokes: caps, joins, miter limit ----------------------------------------------------

// Area of everything the only shape paints (fill and stroke).
double paintedArea(const std::string& body) {
  SvgDocument document = read(body);
  EXPECT_EQ(document.shapes.size(), 1u) << body;
  if (document.shapes.empty()) return 0.0;
  return area(paintedRegion(document.shapes.front()));
}

// A horizontal stroke 80 long and 10 wide: caps add nothing (butt, SVG's default), a half
// disc at each end (round) or 5 at each end (square).
TEST(SvgReaderStroke, LineCapsShapeTheEnds) {
  const std::string line = R"~(<path d="M10 50 H90" fill="none" stroke="#000" stroke-width="10")~";
  EXPECT_NEAR(paintedArea(line + "/>"), 800.0, 0.5);
  EXPECT_NEAR(paintedArea(line + R"~( stroke-linecap="butt"/>)~"), 800.0, 0.5);
  EXPECT_NEAR(paintedArea(line + R"~( stroke-linecap="round"/>)~"), 800.0 + kPi * 25, 2.0);  // arcs are polygons
  EXPECT_NEAR(paintedArea(line + R"~( style="stroke-linecap:square"/>)~"), 900.0, 0.5);
}

// A right-angled corner, two 40-long legs 10 wide with butt ends (775 without any join): the
// miter fills the 5×5 outer corner, round a quarter disc, bevel less than either.
TEST(SvgReaderStroke, LineJoinsShapeTheCorners) {
  const std::string corner = R"~(<path d="M10 10 H50 V50" fill="none" stroke="#000" stroke-width="10")~";
  EXPECT_NEAR(paintedArea(corner + "/>"), 800.0, 0.5);  // miter: SVG's default
  EXPECT_NEAR(paintedArea(corner + R"~( stroke-linejoin="round"/>)~"), 775.0 + kPi * 25 / 4, 1.0);
  const double bevel = paintedArea(corner + R"~( stroke-linejoin="bevel"/>)~");
  EXPECT_GT(bevel, 775.0 + 12.5 - 0.5);  // at least the bevel's triangle
  EXPECT_LT(bevel, 800.0 - 1.0);         // and less than the miter
}

// Inherited from a group's style, like the other presentation properties.
TEST(SvgReaderStroke, CapsAndJoinsAreInherited) {
  SvgDocument document = read(R"~(<g style="stroke-linecap:round;stroke-linejoin:bevel" stroke-miterlimit="7">
      <path d="M10 10 H50" stroke="#000"/></g>)~");
  ASSERT_EQ(document.shapes.size(), 1u);
  EXPECT_EQ(document.shapes[0].lineCap, StrokeCap::Round);
  EXPECT_EQ(document.shapes[0].lineJoin, StrokeJoin::Bevel);
  EXPECT_DOUBLE_EQ(document.shapes[0].miterLimit, 7.0);
}

// A sharp turn (miter length 2.24 × the width): mitered under the default limit 4, cut
// under a limit of 2.
TEST(SvgReaderStroke, MiterLimitCutsSharpCorners) {
  const std::string spike = R"~(<path d="M10 10 L90 50 L10 90" fill="none" stroke="#000" stroke-width="10")~";
  const double mitered = paintedArea(spike + "/>");
  const double cut = paintedArea(spike + R"~( stroke-miterlimit="2"/>)~");
  EXPECT_GT(mitered - cut, 5.0);
}

// Dashes are read, scaled like the stroke width by the transform, and inherited; an odd list
// repeats to an even one (SVG); `none` and a list of zeros are solid; the outline stays solid.
TEST(SvgReaderStroke, DashesAreReadScaledAndInherited) {
  SvgDocument document = read(R"~(<g stroke-dasharray="4 2" style="stroke-dashoffset:1">
      <path id="a" d="M10 10 H50" stroke="#000"/>
      <path id="b" d="M10 20 H50" stroke="#000" transform="scale(2)"/>
      <path id="c" d="M10 30 H50" stroke="#000" stroke-dasharray="3, 1, 2"/>
      <path id="d" d="M10 40 H50" stroke="#000" style="stroke-dasharray:none"/>
      <path id="e" d="M10 50 H50" stroke="#000" stroke-dasharray="0 0"/></g>)~");
  ASSERT_EQ(document.shapes.size(), 5u);
  EXPECT_EQ(document.shapes[0].dashArray, (std::vector<double>{4, 2}));
  EXPECT_DOUBLE_EQ(document.shapes[0].dashOffset, 1.0);
  EXPECT_EQ(document.shapes[1].dashArray, (std::vector<double>{8, 4}));
  EXPECT_DOUBLE_EQ(document.shapes[1].dashOffset, 2.0);
  EXPECT_DOUBLE_EQ(document.shapes[1].strokeWidth, 2.0);
  EXPECT_EQ(document.shapes[2].dashArray, (std::vector<double>{3, 1, 2, 3, 1, 2}));
  EXPECT_TRUE(document.shapes[3].dashArray.empty());
  EXPECT_TRUE(document.shapes[4].dashArray.empty());
  EXPECT_TRUE(document.warnings.empty()) << document.warnings.front().message;
  // The outline of a dashed stroke is the solid stroke's.
  const std::string line = R"~(<path d="M10 50 H90" fill="none" stroke="#000" stroke-width="10")~";
  EXPECT_NEAR(paintedArea(line + R"~( stroke-dasharray="5 15"/>)~"), 800.0, 0.5);
}

// A negative or unreadable length is an error SVG ignores the property for: the inherited
// dashes stay, with a warning.
TEST(SvgReaderStroke, BadDashesAreIgnoredWithAWarning) {
  SvgDocument document = read(R"~(<g stroke-dasharray="4 2">
      <path d="M10 10 H50" stroke="#000" stroke-dasharray="4 -2"/>
      <path d="M10 20 H50" stroke="#000" stroke-dasharray="4 banana"/></g>)~");
  ASSERT_EQ(document.shapes.size(), 2u);
  EXPECT_EQ(document.shapes[0].dashArray, (std::vector<double>{4, 2}));
  EXPECT_EQ(document.shapes[1].dashArray, (std::vector<double>{4, 2}));
  ASSERT_EQ(document.warnings.size(), 2u);
  EXPECT_NE(document.warnings[0].message.find("stroke-dasharray"), std::string::npos);
  EXPECT_NE(document.warnings[1].message.find("stroke-dasharray"), std::string::npos);
}

// A zero-length subpath (outline icons draw dots as `M4 20h0`): a disc with round caps, a
// square with square caps, nothing with butt caps.
TEST(SvgReaderStroke, ZeroLengthSubpathsWithRoundOrSquareCapsAreDots) {
  const std::string dot = R"~(<path d="M4 20h0" fill="none" stroke="#000" stroke-width="2")~";
  EXPECT_NEAR(paintedArea(dot + R"~( stroke-linecap="round"/>)~"), kPi, 0.06);  // a polygon in the disc
  EXPECT_NEAR(paintedArea(dot + R"~( stroke-linecap="square"/>)~"), 4.0, 1e-6);
  EXPECT_TRUE(read(dot + "/>").shapes.empty());  // butt: nothing to draw
  // A dot beside a line in one path keeps both.
  SvgDocument both = read(R"~(<path d="M10 10 H30 M50 50 h0" fill="none" stroke="#000" stroke-linecap="round"/>)~");
  ASSERT_EQ(both.shapes.size(), 1u);
  EXPECT_EQ(both.shapes[0].subpaths.size(), 2u);
}

// A transform that scales x and y apart widens a stroke more in one direction, as browsers
// draw it (flag-icons stretch their stripes and saltires): the stroke becomes a filled shape
// of its colour, after the shape's own fill. A 10-wide line under scale(1 2) is 20 wide.
TEST(SvgReaderStroke, StretchedStrokesAreAsWideAsTheTransformMakesThem) {
  EXPECT_NEAR(paintedArea(R"~(<path d="M0 20 H100" fill="none" stroke="#000" stroke-width="10" )~"
                          R"~(transform="scale(1 2)"/>)~"),
              2000.0, 1e-6);
  SvgDocument square = read(R"~(<rect id="box" width="10" height="10" fill="#f00" stroke="#00f" stroke-width="2" )~"
                            R"~(transform="matrix(-2 0 0 1 30 0)"/>)~");
  ASSERT_EQ(square.shapes.size(), 2u);
  EXPECT_EQ(square.shapes[0].id, "box");
  EXPECT_EQ(*square.shapes[0].fill, (Color{255, 0, 0, 1.0}));
  EXPECT_FALSE(square.shapes[0].stroke.has_value());
  EXPECT_EQ(square.shapes[1].id, "box-stroke");
  EXPECT_EQ(*square.shapes[1].fill, (Color{0, 0, 255, 1.0}));
  // The band between 24 × 12 and 16 × 8 (miter corners), mirrored without harm.
  EXPECT_NEAR(area(filledRegion(square.shapes[1])), 24.0 * 12.0 - 16.0 * 8.0, 1e-6);
  // Lines drawn as a stroke leave no empty fill behind (it would be "a path that paints no area").
  SvgDocument lines = read(R"~(<path d="M0 10 H100 M0 30 H100" stroke="#f00" stroke-width="5" transform="scale(1 2)"/>)~");
  ASSERT_EQ(lines.shapes.size(), 1u);
  EXPECT_EQ(*lines.shapes[0].fill, (Color{255, 0, 0, 1.0}));
  // A uniform scale keeps the stroke a stroke.
  EXPECT_TRUE(read(R"~(<path d="M0 0 H10" stroke="#000" transform="rotate(30) scale(2)"/>)~").shapes[0].stroke);
}

// Effects Pak does not draw each give a warning naming the property, on shapes and on
// groups, from attributes and from style; none (or normal) is no effect; hidden or defined
// things do not warn.
TEST(SvgReaderVisibility, UndrawnEffectsGiveNamedWarnings) {
  SvgDocument document = read(R"~(<defs><rect id="inDefs" width="1" height="1" filter="url(#f)"/></defs>
      <rect id="masked" width="10" height="10" mask="url(#m)"/>
      <g id="blurred" style="filter: url(#f)"><rect width="1" height="1"/></g>
      <path id="arrow" d="M0 0 H10" stroke="#000" marker-start="url(#a)" marker-mid="url(#a)" style="marker-end:url(#a)"/>
      <rect id="blended" width="1" height="1" style="mix-blend-mode:multiply"/>
      <rect id="plain" width="1" height="1" mask="none" style="mix-blend-mode:normal"/>
      <rect id="hidden" width="1" height="1" mask="url(#m)" display="none"/>)~");
  std::vector<std::string> named;
  for (const Warning& warning : document.warnings) named.push_back(warning.where + " | " + warning.message);
  auto has = [&](const std::string& where, const std::string& property) {
    return std::count_if(named.begin(), named.end(), [&](const std::string& line) {
      return line.find(where) != std::string::npos && line.find("| " + property + "=") != std::string::npos;
    });
  };
  EXPECT_EQ(has("id=\"masked\"", "mask"), 1);
  EXPECT_EQ(has("id=\"blurred\"", "filter"), 1);
  EXPECT_EQ(has("id=\"arrow\"", "marker-start"), 1);
  EXPECT_EQ(has("id=\"arrow\"", "marker-mid"), 1);
  EXPECT_EQ(has("id=\"arrow\"", "marker-end"), 1);
  EXPECT_EQ(has("id=\"blended\"", "mix-blend-mode"), 1);
  EXPECT_EQ(has("plain", ""), 0);
  EXPECT_EQ(has("hidden", ""), 0);
  EXPECT_EQ(has("inDefs", ""), 0);
  EXPECT_EQ(named.size(), 6u) << ::testing::PrintToString(named);
}

// ---- clip-path -----------------------------------------------------------------------------

// A 100×100 square clipped by a 50×50 one keeps only the overlap.
TEST(SvgReaderClip, ClipPathKeepsTheIntersection) {
  EXPECT_NEAR(fillArea(R"~(<clipPath id="c"><rect x="25" y="25" width="50" height="50"/></clipPath>
      <rect width="100" height="100" clip-path="url(#c)"/>)~"), 2500.0, 1e-6);
}

// On a group, in the group's user space (its transform included), for every shape inside;
// the clip path's own transform and its shapes' clip-rule apply; style="clip-path:…" works.
TEST(SvgReaderClip, GroupsTransformsAndClipRule) {
  SvgDocument document = read(R"~(<defs><clipPath id="half" transform="translate(10 0)">
        <rect width="10" height="20"/></clipPath>
      <clipPath id="ring"><path clip-rule="evenodd" d="M0 0 H20 V20 H0 Z M5 5 H15 V15 H5 Z"/></clipPath></defs>
      <g transform="scale(2)" style="clip-path:url(#half)"><rect width="20" height="20"/><rect y="30" width="20" height="20"/></g>
      <rect width="20" height="20" clip-path="url('#ring')"/>)~");
  ASSERT_EQ(document.shapes.size(), 2u);  // the second square lies outside the clip
  EXPECT_NEAR(area(filledRegion(document.shapes[0])), 4 * 200.0, 1e-6);
  EXPECT_NEAR(bounds(document.shapes[0]).min.x, 20.0, 1e-9);
  EXPECT_NEAR(area(filledRegion(document.shapes[1])), 400.0 - 100.0, 1e-6);
}

// A clipped stroke is cut too: it becomes a filled shape of the stroke's colour.
TEST(SvgReaderClip, StrokesAreClipped) {
  SvgDocument document = read(R"~(<clipPath id="left"><rect x="-10" y="-10" width="60" height="120"/></clipPath>
      <path id="bar" d="M10 50 H90" stroke="#f00" stroke-width="10" fill="#00f" clip-path="url(#left)"/>)~");
  ASSERT_EQ(document.shapes.size(), 1u);  // the fill of a line has no area
  EXPECT_FALSE(document.shapes[0].stroke);
  EXPECT_EQ(document.shapes[0].fill->r, 255);
  EXPECT_NEAR(area(filledRegion(document.shapes[0])), 40 * 10.0, 1e-6);
}

// What cannot be applied is a warning and the shape is drawn unclipped.
TEST(SvgReaderClip, MissingOrBoundingBoxClipsWarn) {
  SvgDocument document = read(R"~(<clipPath id="box" clipPathUnits="objectBoundingBox"><rect width="0.5" height="0.5"/></clipPath>
      <rect width="10" height="10" clip-path="url(#nowhere)"/><rect width="10" height="10" clip-path="url(#box)"/>)~");
  ASSERT_EQ(document.shapes.size(), 2u);
  EXPECT_NEAR(area(filledRegion(document.shapes[0])), 100.0, 1e-9);
  EXPECT_NEAR(area(filledRegion(document.shapes[1])), 100.0, 1e-9);
  EXPECT_EQ(warningsContaining(document, "no <clipPath> has that id"), 1);
  EXPECT_EQ(warningsContaining(document, "objectBoundingBox"), 1);
}

TEST(SvgReaderFillRule, EvenOddMakesHolesNonZeroDoesNot) {
  const std::string squares = "M0 0 H10 V10 H0 Z M3 3 H7 V7 H3 Z";  // same winding
  SvgDocument nonzero = read(R"~(<path fill-rule="nonzero" d=")~" + squares + R"~("/>)~");
  SvgDocument evenodd = read(R"~(<path style="fill-rule:evenodd" d=")~" + squares + R"~("/>)~");
  EXPECT_EQ(nonzero.shapes[0].fillRule, FillRule::NonZero);
  EXPECT_EQ(evenodd.shapes[0].fillRule, FillRule::EvenOdd);
  Region full = filledRegion(nonzero.shapes[0]);
  Region holed = filledRegion(evenodd.shapes[0]);
  EXPECT_NEAR(area(full), 100.0, 1e-9);
  EXPECT_NEAR(area(holed), 84.0, 1e-9);
  ASSERT_EQ(holed.size(), 1u);
  EXPECT_EQ(holed[0].holes.size(), 1u);
  // Opposite winding makes a hole under nonzero too.
  SvgDocument reversed = read(R"~(<path d="M0 0 H10 V10 H0 Z M3 3 V7 H7 V3 Z"/>)~");
  EXPECT_NEAR(area(filledRegion(reversed.shapes[0])), 84.0, 1e-9);
}

TEST(SvgReaderLayers, ByIdAndInkscapeLabelCaseInsensitive) {
  SvgDocument document = read(R"~(
      <g id="Container"><rect id="c" width="1" height="1"/></g>
      <g id="layer2" inkscape:label="FIXED"><g id="sub"><rect id="f" width="1" height="1"/></g></g>
      <g id="Artwork"><g id="guides"><path id="g" d="M0 0 L1 1" stroke="black"/></g>
        <rect id="art" width="1" height="1"/></g>
      <rect id="loose" width="1" height="1"/>)~");
  ASSERT_EQ(document.shapes.size(), 5u);
  EXPECT_EQ(document.shapes[0].layer, "container");
  EXPECT_EQ(document.shapes[0].topGroup, 0);
  EXPECT_EQ(document.shapes[1].layer, "fixed");
  EXPECT_EQ(document.shapes[1].topGroup, 1);
  EXPECT_EQ(document.shapes[2].layer, "guides");  // nearest known name wins
  EXPECT_EQ(document.shapes[2].topGroup, 2);
  EXPECT_EQ(document.shapes[3].layer, "artwork");  // else the outermost named group
  EXPECT_EQ(document.shapes[4].layer, "");
  EXPECT_EQ(document.shapes[4].topGroup, -1);
  EXPECT_EQ(document.layers, (std::vector<std::string>{"container", "fixed", "artwork", "guides"}));
}

TEST(SvgReaderLayers, IllustratorSuffixesAreDropped) {
  SvgDocument document = read(R"~(<g id="Container_1_"><rect width="1" height="1"/></g>
      <g id="Leaf_2_"><rect width="1" height="1"/></g>)~");
  ASSERT_EQ(document.shapes.size(), 2u);
  EXPECT_EQ(document.shapes[0].layer, "container");
  EXPECT_EQ(document.shapes[1].layer, "leaf_2_");  // only Pak's own layer names are tidied
}

TEST(SvgReaderNamespaces, FilesWithoutXmlnsOrWithIllustratorEntitiesStillRead) {
  SvgDocument bare = readSvgString(R"~(<svg viewBox="0 0 10 10"><rect width="2" height="3"/></svg>)~", "bare.svg");
  ASSERT_EQ(bare.shapes.size(), 1u);
  SvgDocument illustrator = readSvgString(R"~(<?xml version="1.0"?>
      <!DOCTYPE svg PUBLIC "-//W3C//DTD SVG 1.1//EN" "http://www.w3.org/Graphics/SVG/1.1/DTD/svg11.dtd" [
        <!ENTITY ns_svg "http://www.w3.org/2000/svg">]>
      <svg xmlns="&ns_svg;" viewBox="0 0 10 10"><g id="Layer_1"><rect width="2" height="3"/></g></svg>)~",
                                          "illustrator.svg");
  ASSERT_EQ(illustrator.shapes.size(), 1u);
  EXPECT_EQ(illustrator.shapes[0].layer, "layer_1");
}

TEST(SvgReaderNamespaces, EditorMetadataIsIgnored) {
  SvgDocument document = readSvgString(R"~(<svg xmlns="http://www.w3.org/2000/svg"
      xmlns:sodipodi="http://sodipodi.sourceforge.net/DTD/sodipodi-0.dtd" viewBox="0 0 10 10" data-name="x">
      <sodipodi:namedview pagecolor="#fff"/><metadata><foo/></metadata><title>t</title>
      <rect width="2" height="3" sodipodi:type="rect" style="-inkscape-font-specification:x;fill:red"/></svg>)~",
                                       "inkscape.svg");
  ASSERT_EQ(document.shapes.size(), 1u);
  EXPECT_EQ(*document.shapes[0].fill, (Color{255, 0, 0, 1.0}));
}

// ---- errors ------------------------------------------------------------------------------

TEST(SvgReaderErrors, MissingFile) {
  try {
    readSvgFile("/no/such/folder/missing.svg");
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("/no/such/folder/missing.svg"), std::string::npos);
    EXPECT_NE(std::string(error.what()).find("cannot open"), std::string::npos);
  }
}

TEST(SvgReaderErrors, NotXml) {
  const std::string message = errorOf("<svg><g></svg>", "broken.svg");
  EXPECT_NE(message.find("broken.svg"), std::string::npos) << message;
  EXPECT_NE(message.find("not a valid XML"), std::string::npos) << message;
  EXPECT_NE(message.find("line 1"), std::string::npos) << message;
  EXPECT_NE(errorOf("just some text", "text.svg").find("not a valid XML"), std::string::npos);
  EXPECT_NE(errorOf("", "empty.svg").find("empty.svg"), std::string::npos);
}

TEST(SvgReaderErrors, XmlThatIsNotSvg) {
  const std::string message = errorOf("<html><body/></html>", "page.svg");
  EXPECT_NE(message.find("page.svg"), std::string::npos) << message;
  EXPECT_NE(message.find("not an SVG document"), std::string::npos) << message;
  EXPECT_NE(message.find("<html>"), std::string::npos) << message;
}

TEST(SvgReaderErrors, NanCoordinateNamesTheElement) {
  const std::string message = errorOf(svg(R"~(<path id="broken" d="M0 0 L NaN 5 Z"/>)~"), "nan.svg");
  EXPECT_NE(message.find("nan.svg"), std::string::npos) << message;
  EXPECT_NE(message.find("broken"), std::string::npos) << message;
  EXPECT_NE(message.find("non-finite"), std::string::npos) << message;
  EXPECT_NE(errorOf(svg(R"~(<rect id="r" width="inf" height="1"/>)~")).find("non-finite"), std::string::npos);
}

TEST(SvgReaderErrors, AbsurdCoordinateNamesTheElement) {
  const std::string message = errorOf(svg(R"~(<path id="far" d="M0 0 L 1e12 5 L0 5 Z"/>)~"), "far.svg");
  EXPECT_NE(message.find("far.svg"), std::string::npos) << message;
  EXPECT_NE(message.find("<path id=\"far\">"), std::string::npos) << message;
  EXPECT_NE(message.find("absurd"), std::string::npos) << message;
  // Also when the transform makes it absurd, or a tag without id.
  const std::string scaled = errorOf(svg(R"~(<g transform="scale(1e8)"><rect width="100" height="1"/></g>)~"));
  EXPECT_NE(scaled.find("<rect>"), std::string::npos) << scaled;
  EXPECT_NE(scaled.find("absurd"), std::string::npos) << scaled;
}

TEST(SvgReaderErrors, ErrorsAndShapesNameTheirLine) {
  const std::string text = "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 10 10\">\n"
                           "  <rect id=\"fine\" width=\"1\" height=\"1\"/>\n"
                           "  <path id=\"far\"\n        d=\"M0 0 L 1e12 5 L0 5 Z\"/>\n</svg>\n";
  const std::string message = errorOf(text, "lines.svg");
  EXPECT_NE(message.find("lines.svg:3: <path id=\"far\">: absurd coordinate"), std::string::npos) << message;
  const std::string garbage = errorOf("<svg xmlns=\"http://www.w3.org/2000/svg\">\n\n<path id=\"p\" d=\"M0 0 L 5 x Z\"/></svg>");
  EXPECT_NE(garbage.find("bad.svg:3: <path id=\"p\">: attribute d="), std::string::npos) << garbage;
  SvgDocument document = readSvgString(text.substr(0, text.find("  <path")) + "</svg>", "fine.svg");
  ASSERT_EQ(document.shapes.size(), 1u);
  EXPECT_EQ(document.shapes[0].line, 2);
}

TEST(SvgReaderErrors, GarbagePathData) {
  const std::string message = errorOf(svg(R"~(<path id="p" d="M0 0 L 5 x Z"/>)~"), "garbage.svg");
  EXPECT_NE(message.find("garbage.svg"), std::string::npos) << message;
  EXPECT_NE(message.find("<path id=\"p\">"), std::string::npos) << message;
  EXPECT_NE(message.find("cannot be parsed"), std::string::npos) << message;
}

TEST(SvgReaderErrors, UnparsableStyleIsAWarningNotAnError) {
  SvgDocument document = read(R"~(<rect width="1" height="1" fill="context-fill" opacity="lots"/>)~");
  EXPECT_EQ(document.shapes.size(), 1u);
  EXPECT_GE(document.warnings.size(), 1u);
}

}  // namespace
}  // namespace pak
