// SVG writer: well-formed XML (parsed back with rapidxml_ns), the attributes artists' tools
// need, escaping, atomic files, and a round trip through Pak's own SVG reader.
#include "pak/io/svg_writer.hpp"

#include <gtest/gtest.h>
#include <rapidxml_ns/rapidxml_ns.hpp>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "pak/error.hpp"
#include "io/svg_builder.hpp"
#include "pak/io/svg_reader.hpp"

namespace fs = std::filesystem;

namespace {

pak::Subpath rectangle(double x0, double y0, double x1, double y1) {
  return {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, true};
}

// A container with a hole, and one element group holding two coloured shapes.
pak::Drawing sampleDrawing() {
  pak::Drawing drawing;
  drawing.viewBox = {{0, 0}, {200, 100}};

  pak::DrawingGroup container;
  container.id = "container";
  pak::DrawnShape outline;
  outline.subpaths = {rectangle(10, 10, 190, 90), rectangle(80, 40, 120, 60)};
  outline.fill = pak::Color{220, 235, 245, 1.0};
  outline.stroke = pak::Color{43, 95, 128, 1.0};
  outline.strokeWidth = 2.5;
  outline.fillRule = pak::FillRule::EvenOdd;
  container.shapes.push_back(outline);

  pak::DrawingGroup elements;
  elements.id = "elements";
  pak::DrawingGroup element;
  element.cssClass = "element";
  element.attributes = {{"data-source", "examples/elements/leaf.svg"}};
  pak::DrawnShape body;
  body.id = "body";
  body.subpaths = {{{{20, 20}, {40, 20}, {30, 35}}, true}};
  body.fill = pak::Color{90, 168, 71, 0.5};
  body.opacity = 0.75;
  pak::DrawnShape vein;
  vein.subpaths = {{{{22, 22}, {30, 30}, {38, 22}}, false}};
  vein.stroke = pak::Color{47, 107, 42, 1.0};
  vein.strokeWidth = 1.5;
  element.shapes = {body, vein};
  elements.children.push_back(element);

  drawing.groups = {container, elements};
  return drawing;
}

// Parses with rapidxml_ns, so a malformed document fails the test with the parser's reason.
class ParsedSvg {
 public:
  explicit ParsedSvg(const std::string& text) : buffer_(text.begin(), text.end()) {
    buffer_.push_back('\0');
    document_.parse<rapidxml_ns::parse_default>(buffer_.data());
  }
  rapidxml_ns::xml_node<>* root() { return document_.first_node("svg"); }

 private:
  std::vector<char> buffer_;
  rapidxml_ns::xml_document<> document_;
};

std::string attribute(rapidxml_ns::xml_node<>* node, const char* name) {
  auto* found = node ? node->first_attribute(name) : nullptr;
  return found ? std::string(found->value(), found->value_size()) : std::string("<absent>");
}

TEST(SvgWriter, WritesWellFormedSvgWithTheDocumentAttributes) {
  std::string text = pak::toSvgString(sampleDrawing());
  ParsedSvg parsed(text);
  auto* svg = parsed.root();
  ASSERT_NE(svg, nullptr);
  EXPECT_EQ(attribute(svg, "xmlns"), "http://www.w3.org/2000/svg");
  EXPECT_EQ(attribute(svg, "version"), "1.1");
  EXPECT_EQ(attribute(svg, "viewBox"), "0 0 200 100");
  EXPECT_EQ(attribute(svg, "width"), "200");
  EXPECT_EQ(attribute(svg, "height"), "100");
}

TEST(SvgWriter, ExplicitSizeIsKept) {
  pak::Drawing drawing = sampleDrawing();
  drawing.width = 400;
  drawing.height = 200;
  ParsedSvg parsed(pak::toSvgString(drawing));
  EXPECT_EQ(attribute(parsed.root(), "width"), "400");
  EXPECT_EQ(attribute(parsed.root(), "viewBox"), "0 0 200 100");
}

// A scene's size as written (units and all) wins over the numbers; a side it left out stays out.
TEST(SvgWriter, SizeAsWrittenIsKept) {
  pak::Drawing drawing = sampleDrawing();
  drawing.width = 755.906;
  drawing.height = 377.953;
  drawing.widthText = "200mm";
  drawing.heightText = "100mm";
  ParsedSvg both(pak::toSvgString(drawing));
  EXPECT_EQ(attribute(both.root(), "width"), "200mm");
  EXPECT_EQ(attribute(both.root(), "height"), "100mm");
  EXPECT_EQ(attribute(both.root(), "viewBox"), "0 0 200 100");
  drawing.heightText.clear();
  ParsedSvg one(pak::toSvgString(drawing));
  EXPECT_EQ(attribute(one.root(), "width"), "200mm");
  EXPECT_EQ(attribute(one.root(), "height"), "<absent>");
}

TEST(SvgWriter, GroupsAndPathsKeepStructureAndPaint) {
  ParsedSvg parsed(pak::toSvgString(sampleDrawing()));
  auto* container = parsed.root()->first_node("g");
  ASSERT_NE(container, nullptr);
  EXPECT_EQ(attribute(container, "id"), "container");
  EXPECT_EQ(attribute(container, "inkscape:groupmode"), "layer");
  EXPECT_EQ(attribute(container, "inkscape:label"), "container");
  auto* outline = container->first_node("path");
  ASSERT_NE(outline, nullptr);
  EXPECT_EQ(attribute(outline, "d"), "M10,10 L190,10 190,90 10,90 Z M80,40 L120,40 120,60 80,60 Z");
  EXPECT_EQ(attribute(outline, "fill"), "#dcebf5");
  EXPECT_EQ(attribute(outline, "fill-rule"), "evenodd");
  EXPECT_EQ(attribute(outline, "stroke"), "#2b5f80");
  EXPECT_EQ(attribute(outline, "stroke-width"), "2.5");
  EXPECT_EQ(attribute(outline, "fill-opacity"), "<absent>");
  EXPECT_EQ(attribute(outline, "opacity"), "<absent>");

  auto* elements = container->next_sibling("g");
  ASSERT_NE(elements, nullptr);
  EXPECT_EQ(attribute(elements, "id"), "elements");
  auto* element = elements->first_node("g");
  ASSERT_NE(element, nullptr);
  EXPECT_EQ(attribute(element, "class"), "element");
  EXPECT_EQ(attribute(element, "data-source"), "examples/elements/leaf.svg");
  EXPECT_EQ(attribute(element, "inkscape:groupmode"), "<absent>");  // only top-level groups are layers
  auto* body = element->first_node("path");
  ASSERT_NE(body, nullptr);
  EXPECT_EQ(attribute(body, "id"), "body");
  EXPECT_EQ(attribute(body, "fill"), "#5aa847");
  EXPECT_EQ(attribute(body, "fill-opacity"), "0.5");
  EXPECT_EQ(attribute(body, "opacity"), "0.75");
  EXPECT_EQ(attribute(body, "stroke"), "<absent>");
  auto* vein = body->next_sibling("path");
  ASSERT_NE(vein, nullptr);
  EXPECT_EQ(attribute(vein, "fill"), "none");
  EXPECT_EQ(attribute(vein, "stroke"), "#2f6b2a");
  EXPECT_EQ(attribute(vein, "stroke-width"), "1.5");
  EXPECT_EQ(attribute(vein, "d"), "M22,22 L30,30 38,22");  // open: no Z
}

TEST(SvgWriter, NumbersUseTheRequestedPrecision) {
  pak::Drawing drawing;
  drawing.viewBox = {{0, 0}, {10, 10}};
  pak::DrawingGroup group;
  pak::DrawnShape shape;
  shape.fill = pak::Color{};
  shape.subpaths = {{{{1.23456, -0.0001}, {2.5, 3.0}, {-1.9999, 7.126}}, true}};
  group.shapes.push_back(shape);
  drawing.groups.push_back(group);
  ParsedSvg two(pak::toSvgString(drawing, {.precision = 2}));
  EXPECT_EQ(attribute(two.root()->first_node("g")->first_node("path"), "d"), "M1.23,0 L2.5,3 -2,7.13 Z");
  ParsedSvg four(pak::toSvgString(drawing, {.precision = 4}));
  EXPECT_EQ(attribute(four.root()->first_node("g")->first_node("path"), "d"), "M1.2346,-0.0001 L2.5,3 -1.9999,7.126 Z");
}

TEST(SvgWriter, EscapesIdsAndAttributeValues) {
  pak::Drawing drawing = sampleDrawing();
  drawing.groups[0].id = "a<b & \"c\" 'd'>";
  drawing.groups[1].children[0].attributes = {{"data-source", "dir/Tom & Jerry <1>.svg"}};
  drawing.groups[1].children[0].shapes[0].id = "x\"y\tz\x01";
  std::string text = pak::toSvgString(drawing);
  EXPECT_NE(text.find("id=\"a&lt;b &amp; &quot;c&quot; &apos;d&apos;&gt;\""), std::string::npos) << text;
  ParsedSvg parsed(text);
  auto* container = parsed.root()->first_node("g");
  // rapidxml expands the entities back, so the values arrive unchanged (minus the control character).
  EXPECT_EQ(attribute(container, "id"), "a<b & \"c\" 'd'>");
  auto* element = container->next_sibling("g")->first_node("g");
  EXPECT_EQ(attribute(element, "data-source"), "dir/Tom & Jerry <1>.svg");
  EXPECT_EQ(text.find('\x01'), std::string::npos);
}

TEST(SvgWriter, InvalidAttributeNamesAreDropped) {
  pak::Drawing drawing = sampleDrawing();
  drawing.groups[0].attributes = {{"data-ok", "1"}, {"bad name", "2"}, {"1bad", "3"}, {"", "4"}};
  std::string text = pak::toSvgString(drawing);
  ParsedSvg parsed(text);
  EXPECT_EQ(attribute(parsed.root()->first_node("g"), "data-ok"), "1");
  EXPECT_EQ(text.find("bad"), std::string::npos);
}

TEST(SvgWriter, EmptyViewBoxBecomesTheBoundsOfTheShapes) {
  pak::Drawing drawing = sampleDrawing();
  drawing.viewBox = pak::Box{};
  ParsedSvg parsed(pak::toSvgString(drawing));
  EXPECT_EQ(attribute(parsed.root(), "viewBox"), "10 10 180 80");
}

TEST(SvgWriter, EmptyDrawingIsStillValid) {
  ParsedSvg parsed(pak::toSvgString(pak::Drawing{}));
  ASSERT_NE(parsed.root(), nullptr);
  EXPECT_EQ(attribute(parsed.root(), "viewBox"), "0 0 1 1");
}

TEST(SvgWriter, EmptyShapesAndGroupsDoNotProduceEmptyPaths) {
  pak::Drawing drawing;
  drawing.viewBox = {{0, 0}, {1, 1}};
  pak::DrawingGroup group;
  group.id = "nothing";
  group.shapes.push_back(pak::DrawnShape{});
  drawing.groups.push_back(group);
  std::string text = pak::toSvgString(drawing);
  EXPECT_EQ(text.find("<path"), std::string::npos);
  ParsedSvg parsed(text);
  EXPECT_EQ(attribute(parsed.root()->first_node("g"), "id"), "nothing");
}

TEST(SvgWriter, NonFiniteCoordinateIsAnError) {
  pak::Drawing drawing = sampleDrawing();
  drawing.groups[0].shapes[0].subpaths[0].points[1].x = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(pak::toSvgString(drawing), pak::InputError);
}

class SvgFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    folder_ = fs::temp_directory_path() / ("pak-svgw-" + std::string(info->name()) + "-" + std::to_string(::getpid()));
    fs::remove_all(folder_);
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }
  fs::path folder_;
};

TEST_F(SvgFileTest, WritesTheSameTextAsToSvgStringAndNoTemporary) {
  std::string path = (folder_ / "out.svg").string();
  pak::writeSvgFile(sampleDrawing(), path);
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), pak::toSvgString(sampleDrawing()));
  EXPECT_EQ(std::distance(fs::directory_iterator(folder_), fs::directory_iterator()), 1);
}

TEST_F(SvgFileTest, MissingFolderFailsWithThePathAndWritesNothing) {
  std::string path = (folder_ / "missing" / "out.svg").string();
  try {
    pak::writeSvgFile(sampleDrawing(), path);
    FAIL() << "expected InputError";
  } catch (const pak::InputError& error) {
    EXPECT_EQ(std::string(error.what()).rfind(path, 0), 0u) << error.what();
  }
  EXPECT_TRUE(fs::is_empty(folder_));
}

TEST_F(SvgFileTest, BadDrawingLeavesTheOldFileAlone) {
  std::string path = (folder_ / "out.svg").string();
  pak::writeSvgFile(sampleDrawing(), path);
  auto before = fs::file_size(path);
  pak::Drawing broken = sampleDrawing();
  broken.groups[0].shapes[0].subpaths[0].points[0].y = std::numeric_limits<double>::infinity();
  try {
    pak::writeSvgFile(broken, path);
    FAIL() << "expected InputError";
  } catch (const pak::InputError& error) {
    EXPECT_EQ(std::string(error.what()).rfind(path + ": ", 0), 0u) << error.what();
  }
  EXPECT_EQ(fs::file_size(path), before);
  EXPECT_EQ(std::distance(fs::directory_iterator(folder_), fs::directory_iterator()), 1);
}

// --- Round trip through Pak's reader -------------------------------------------------------

// Shapes in document order, whatever the nesting.
const pak::SvgShape* findShape(const pak::SvgDocument& document, const std::string& id) {
  for (const auto& shape : document.shapes)
    if (shape.id == id) return &shape;
  return nullptr;
}

void expectSamePoints(const pak::Subpath& written, const pak::Subpath& read, double tolerance) {
  ASSERT_EQ(read.points.size(), written.points.size());
  EXPECT_EQ(read.closed, written.closed);
  for (std::size_t i = 0; i < written.points.size(); ++i) {
    EXPECT_NEAR(read.points[i].x, written.points[i].x, tolerance) << "point " << i;
    EXPECT_NEAR(read.points[i].y, written.points[i].y, tolerance) << "point " << i;
  }
}

TEST(SvgWriterRoundTrip, ReaderSeesTheSameShapesColoursAndLayers) {
  pak::Drawing drawing = sampleDrawing();
  // Coordinates that need rounding: the reader must agree within the written precision.
  drawing.groups[1].children[0].shapes[0].subpaths[0].points[2] = {30.12345, 35.98765};
  drawing.groups[0].shapes[0].id = "outline";
  drawing.groups[1].children[0].shapes[1].id = "vein";
  pak::SvgDocument document = pak::readSvgString(pak::toSvgString(drawing, {.precision = 3}), "roundtrip.svg");

  EXPECT_NEAR(document.viewBox.min.x, 0, 1e-9);
  EXPECT_NEAR(document.viewBox.max.x, 200, 1e-9);
  EXPECT_NEAR(document.viewBox.max.y, 100, 1e-9);
  ASSERT_EQ(document.shapes.size(), 3u);
  ASSERT_FALSE(document.layers.empty());
  EXPECT_EQ(document.layers[0], "container");

  const pak::SvgShape* outline = findShape(document, "outline");
  ASSERT_NE(outline, nullptr);
  const pak::Shape& writtenOutline = drawing.groups[0].shapes[0];
  ASSERT_EQ(outline->subpaths.size(), 2u);
  expectSamePoints(writtenOutline.subpaths[0], outline->subpaths[0], 1e-9);
  expectSamePoints(writtenOutline.subpaths[1], outline->subpaths[1], 1e-9);
  EXPECT_EQ(outline->fill, writtenOutline.fill);
  EXPECT_EQ(outline->stroke, writtenOutline.stroke);
  EXPECT_DOUBLE_EQ(outline->strokeWidth, 2.5);
  EXPECT_EQ(outline->fillRule, pak::FillRule::EvenOdd);
  EXPECT_EQ(outline->layer, "container");

  const pak::SvgShape* body = findShape(document, "body");
  ASSERT_NE(body, nullptr);
  const pak::Shape& writtenBody = drawing.groups[1].children[0].shapes[0];
  expectSamePoints(writtenBody.subpaths[0], body->subpaths[0], 0.0005 + 1e-9);
  ASSERT_TRUE(body->fill.has_value());
  EXPECT_EQ(body->fill->r, 90);
  EXPECT_EQ(body->fill->g, 168);
  EXPECT_EQ(body->fill->b, 71);
  // The reader may fold `opacity` into the colour's alpha or keep it apart; what is painted
  // (alpha × opacity) must match.
  EXPECT_NEAR(body->fill->alpha * body->opacity, 0.5 * 0.75, 1e-6);
  EXPECT_FALSE(body->stroke.has_value());
  EXPECT_EQ(body->fillRule, pak::FillRule::NonZero);
  EXPECT_EQ(body->layer, "elements");

  const pak::SvgShape* vein = findShape(document, "vein");
  ASSERT_NE(vein, nullptr);
  expectSamePoints(drawing.groups[1].children[0].shapes[1].subpaths[0], vein->subpaths[0], 1e-9);
  EXPECT_FALSE(vein->fill.has_value());
  ASSERT_TRUE(vein->stroke.has_value());
  EXPECT_EQ((pak::Color{vein->stroke->r, vein->stroke->g, vein->stroke->b, 1.0}), (pak::Color{47, 107, 42, 1.0}));
  EXPECT_DOUBLE_EQ(vein->strokeWidth, 1.5);
}

TEST(SvgWriterRoundTrip, EscapedIdsComeBackUnchanged) {
  pak::Drawing drawing = sampleDrawing();
  drawing.groups[0].shapes[0].id = "fish & chips <1>";
  pak::SvgDocument document = pak::readSvgString(pak::toSvgString(drawing), "escaped.svg");
  EXPECT_NE(findShape(document, "fish & chips <1>"), nullptr);
}

// A 100 × 100 drawing with one group of `shapes`.
pak::Drawing oneGroupDrawing(const std::string& id, std::vector<pak::DrawnShape> shapes) {
  pak::Drawing drawing;
  drawing.viewBox = {{0, 0}, {100, 100}};
  pak::DrawingGroup group;
  group.id = id;
  group.shapes = std::move(shapes);
  drawing.groups = {group};
  return drawing;
}

// Stroke caps, joins and the miter limit are written (when not SVG's defaults) and read back;
// a dot (a one-point subpath) is written as a zero-length segment so round caps draw it.
TEST(SvgWriterRoundTrip, StrokeCapsJoinsMiterLimitAndDotsComeBack) {
  pak::DrawnShape corner;
  corner.subpaths = {{{{10, 10}, {50, 10}, {50, 50}}, false}};
  corner.stroke = pak::Color{0, 0, 0, 1.0};
  corner.strokeWidth = 4;
  corner.lineCap = pak::StrokeCap::Square;
  corner.lineJoin = pak::StrokeJoin::Bevel;
  pak::DrawnShape spike = corner;
  spike.lineCap = pak::StrokeCap::Butt;
  spike.lineJoin = pak::StrokeJoin::Miter;
  spike.miterLimit = 9;
  pak::DrawnShape dot = corner;
  dot.subpaths = {{{{70, 70}}, false}};
  dot.lineCap = pak::StrokeCap::Round;
  const std::string svg = pak::toSvgString(oneGroupDrawing("art", {corner, spike, dot}));
  ParsedSvg parsed(svg);
  auto* first = parsed.root()->first_node("g")->first_node("path");
  ASSERT_NE(first, nullptr);
  EXPECT_EQ(attribute(first, "stroke-linecap"), "square");
  EXPECT_EQ(attribute(first, "stroke-linejoin"), "bevel");
  auto* second = first->next_sibling("path");
  EXPECT_EQ(attribute(second, "stroke-linecap"), "<absent>");  // butt: SVG's default
  EXPECT_EQ(attribute(second, "stroke-miterlimit"), "9");

  pak::SvgDocument back = pak::readSvgString(svg, "caps.svg");
  ASSERT_EQ(back.shapes.size(), 3u);
  EXPECT_EQ(back.shapes[0].lineCap, pak::StrokeCap::Square);
  EXPECT_EQ(back.shapes[0].lineJoin, pak::StrokeJoin::Bevel);
  EXPECT_EQ(back.shapes[1].lineCap, pak::StrokeCap::Butt);
  EXPECT_EQ(back.shapes[1].lineJoin, pak::StrokeJoin::Miter);
  EXPECT_DOUBLE_EQ(back.shapes[1].miterLimit, 9.0);
  EXPECT_EQ(back.shapes[2].lineCap, pak::StrokeCap::Round);
  ASSERT_EQ(back.shapes[2].subpaths.size(), 1u);
  EXPECT_EQ(back.shapes[2].subpaths[0].points.size(), 1u);
  EXPECT_NEAR(pak::area(pak::paintedRegion(back.shapes[2])), std::acos(-1.0) * 4, 0.25);  // a disc of radius 2 (as a polygon)
}

// Dashes are written on stroked shapes (the offset when not 0) and read back; a shape without
// a stroke writes none.
TEST(SvgWriterRoundTrip, StrokeDashesComeBack) {
  pak::DrawnShape dashed;
  dashed.subpaths = {{{{10, 10}, {50, 10}}, false}};
  dashed.stroke = pak::Color{0, 0, 0, 1.0};
  dashed.dashArray = {4, 2.5};
  dashed.dashOffset = 1.25;
  pak::DrawnShape filled = dashed;
  filled.stroke.reset();
  filled.fill = pak::Color{0, 0, 0, 1.0};
  filled.subpaths = {rectangle(60, 60, 70, 70)};
  const std::string svg = pak::toSvgString(oneGroupDrawing("art", {dashed, filled}));
  ParsedSvg parsed(svg);
  auto* first = parsed.root()->first_node("g")->first_node("path");
  ASSERT_NE(first, nullptr);
  EXPECT_EQ(attribute(first, "stroke-dasharray"), "4 2.5");
  EXPECT_EQ(attribute(first, "stroke-dashoffset"), "1.25");
  EXPECT_EQ(attribute(first->next_sibling("path"), "stroke-dasharray"), "<absent>");

  pak::SvgDocument back = pak::readSvgString(svg, "dashes.svg");
  ASSERT_EQ(back.shapes.size(), 2u);
  EXPECT_EQ(back.shapes[0].dashArray, (std::vector<double>{4, 2.5}));
  EXPECT_DOUBLE_EQ(back.shapes[0].dashOffset, 1.25);
}

TEST(SvgWriter, CurveToleranceWritesCubicBeziersThatReadBackAsTheSameShape) {
  pak::DrawnShape disc;
  pak::Subpath ring;
  ring.closed = true;
  for (int k = 0; k < 400; ++k)
    ring.points.push_back({50 + 40 * std::cos(2 * M_PI * k / 400), 50 + 40 * std::sin(2 * M_PI * k / 400)});
  disc.subpaths.push_back(ring);
  disc.fill = pak::Color{10, 20, 30, 1.0};
  const pak::Drawing drawing = oneGroupDrawing("elements", {disc});
  pak::SvgWriteOptions options;
  options.curveTolerance = 0.05;
  std::string svg = pak::toSvgString(drawing, options);
  EXPECT_NE(svg.find(" C"), std::string::npos);
  EXPECT_EQ(svg.find(" L"), std::string::npos);
  EXPECT_LT(svg.size(), pak::toSvgString(drawing).size() / 4);  // far fewer numbers than 400 vertices
  pak::SvgDocument back = pak::readSvgString(svg, "curves.svg");
  ASSERT_EQ(back.shapes.size(), 1u);
  // Every flattened point of the curves lies within the tolerance (plus flattening) of the circle.
  for (const pak::Subpath& sub : back.shapes[0].subpaths)
    for (pak::Vec2 p : sub.points) EXPECT_NEAR(pak::distance(p, {50, 50}), 40.0, 0.15);
}

// A ring fitted with curves when they hold fewer points than it, else written as it is: a
// 12-gon is no circle within 0.01 (its chords are 3.4 inside it), and a cubic per edge would
// triple its points.
TEST(SvgWriter, CurvesOnlyWhereTheyHoldFewerPointsThanThePolygon) {
  auto ring = [](int sides) {
    pak::Shape shape;
    pak::Subpath sub;
    for (int k = 0; k < sides; ++k) {
      const double a = 2 * std::acos(-1.0) * k / sides;
      sub.points.push_back({100 * std::cos(a), 100 * std::sin(a)});
    }
    sub.closed = true;
    shape.subpaths.push_back(sub);
    return shape;
  };
  pak::SvgPathStats coarse, fine;
  const std::string polygon = pak::svg_builder::pathData(ring(12), 3, 0.01, &coarse);
  EXPECT_EQ(polygon.find('C'), std::string::npos) << polygon;
  EXPECT_EQ(coarse.points, 12u);
  const std::string curves = pak::svg_builder::pathData(ring(400), 3, 0.05, &fine);
  EXPECT_NE(curves.find('C'), std::string::npos);
  EXPECT_LT(fine.points, 40u);
  EXPECT_LE(fine.largestDeviation, 0.05 * 1.13);
}

}  // namespace
