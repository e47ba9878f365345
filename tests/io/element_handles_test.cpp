// AnimationPak handles in element files: `handle-NAME` shapes mark points and are not art.
#include <gtest/gtest.h>

#include <string>

#include "pak/error.hpp"
#include "pak/io/scene_loader.hpp"

namespace pak {
namespace {

SvgDocument elementSvg(const std::string& body, const std::string& name = "fish.svg") {
  return readSvgString(R"~(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">)~" + body + "</svg>", name);
}

TEST(ElementHandles, HandleShapesBecomePointsNotArt) {
  const LoadedElement loaded = elementFromDocument(elementSvg(R"~(
      <rect x="0" y="0" width="40" height="20" fill="orange"/>
      <circle id="handle-tail" cx="35" cy="10" r="2" fill="red"/>
      <rect id="Handle-Head" x="2" y="4" width="4" height="6" fill="blue"/>)~"));
  const ElementArt& element = loaded.element;
  ASSERT_EQ(element.shapes.size(), 1u);  // only the body is art
  ASSERT_EQ(loaded.shapes.size(), 1u);
  EXPECT_EQ(loaded.shapes.front().tag, "rect");
  // The outline is the body alone: the handles stick out of nothing, and add no area.
  EXPECT_NEAR(area(element.outline), 800.0, 1e-6);
  ASSERT_EQ(element.handles.size(), 2u);
  EXPECT_EQ(element.handles[0].name, "tail");
  EXPECT_NEAR(element.handles[0].position.x, 35.0, 1e-6);
  EXPECT_NEAR(element.handles[0].position.y, 10.0, 1e-6);
  EXPECT_EQ(element.handles[1].name, "Head");  // prefix matched in any case, name kept as written
  EXPECT_EQ(element.handles[1].position, (Vec2{4, 7}));
}

TEST(ElementHandles, NoHandles) {
  const ElementArt element = elementFromDocument(elementSvg(R"~(<rect id="handle" width="4" height="4"/>)~")).element;
  EXPECT_TRUE(element.handles.empty());  // "handle" alone is an ordinary id
  EXPECT_EQ(element.shapes.size(), 1u);
}

TEST(ElementHandles, PerGroupInAMultiElementFile) {
  const Library library = libraryOf(elementsFromDocument(elementSvg(R"~(
      <g id="a"><rect width="10" height="10"/><circle id="handle-tip" cx="10" cy="5" r="1"/></g>
      <g id="b"><rect x="20" width="10" height="10"/><circle id="handle-tip" cx="30" cy="5" r="1"/></g>)~")));
  ASSERT_EQ(library.size(), 2u);
  ASSERT_EQ(library[0].handles.size(), 1u);
  ASSERT_EQ(library[1].handles.size(), 1u);
  EXPECT_NEAR(library[0].handles[0].position.x, 10.0, 1e-6);
  EXPECT_NEAR(library[1].handles[0].position.x, 30.0, 1e-6);
}

std::string errorOf(const std::string& body) {
  try {
    elementFromDocument(elementSvg(body));
  } catch (const InputError& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(ElementHandles, Errors) {
  const std::string twice = errorOf(R"~(<rect width="10" height="10"/>
      <circle id="handle-tail" cx="1" cy="1" r="1"/><circle id="handle-tail" cx="5" cy="5" r="1"/>)~");
  EXPECT_NE(twice.find("fish.svg:2: handle \"tail\" is given twice"), std::string::npos) << twice;
  const std::string unnamed = errorOf(R"~(<rect width="10" height="10"/><circle id="handle-" cx="1" cy="1" r="1"/>)~");
  EXPECT_NE(unnamed.find("needs a name"), std::string::npos) << unnamed;
}

}  // namespace
}  // namespace pak
