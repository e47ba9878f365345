// The legacy RepulsionPak `.path` format on small hand-written files.
#include "pak/io/path_reader.hpp"

#include <gtest/gtest.h>

#include <string>

#include "pak/error.hpp"

namespace pak {
namespace {

std::string errorOf(const std::string& text, const std::string& name = "bad.path") {
  try {
    readPathString(text, name);
  } catch (const InputError& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(PathReader, PathsColoursAndTypes) {
  const std::string text =
      "1\n"
      "foreground_color_rgb 0 -1,-1,-1 0,0,0 -1,-1,-1\n"
      "background_color_rgb 0 255,255,255 -1,-1,-1 240,100,101\n"
      "0 1 0 0 0 10 0 10 10 0 10\n"
      "0 1 7 2 2 4 2 4 4\n"
      "0 1 2 5 5 6 5 6 6 5 5\n"
      "0 0 6 1 1 9 9\n"
      "0 0 3 1 9 9 1\n";
  SvgDocument document = readPathString(text, "scene.path");
  ASSERT_EQ(document.shapes.size(), 5u);
  const SvgShape& boundary = document.shapes[0];
  EXPECT_EQ(boundary.line, 4);  // each shape knows its line, for messages
  EXPECT_EQ(document.shapes[1].line, 5);
  EXPECT_EQ(boundary.tag, "path-file");
  EXPECT_EQ(boundary.layer, "");
  EXPECT_EQ(*boundary.fill, (Color{255, 255, 255, 1.0}));
  EXPECT_FALSE(boundary.stroke);
  EXPECT_TRUE(boundary.subpaths[0].closed);
  EXPECT_NEAR(area(filledRegion(boundary)), 100.0, 1e-9);

  const SvgShape& hole = document.shapes[1];
  EXPECT_EQ(hole.layer, "holes");
  EXPECT_FALSE(hole.fill);
  EXPECT_EQ(*hole.stroke, (Color{0, 0, 0, 1.0}));

  const SvgShape& focal = document.shapes[2];
  EXPECT_EQ(focal.layer, "fixed");
  EXPECT_EQ(*focal.fill, (Color{240, 100, 101, 1.0}));
  EXPECT_EQ(focal.subpaths[0].points.size(), 3u);  // repeated first point dropped

  EXPECT_EQ(document.shapes[3].layer, "spines");
  EXPECT_FALSE(document.shapes[3].subpaths[0].closed);
  EXPECT_EQ(document.shapes[4].layer, "guides");
  EXPECT_EQ(document.layers, (std::vector<std::string>{"holes", "fixed", "spines", "guides"}));
  // Everything lies on the original 500 × 500 artboard.
  EXPECT_DOUBLE_EQ(document.viewBox.width(), 500.0);
}

TEST(PathReader, OpenOutlineIsClosedLikeTheOriginalDid) {
  // The snake: isClosed = 0 and its first point repeated at the end.
  SvgDocument document = readPathString("1\n0 0 0 0 0 10 0 10 10 0 10 0 0\n", "snake.path");
  ASSERT_EQ(document.shapes.size(), 1u);
  const Subpath& subpath = document.shapes[0].subpaths[0];
  EXPECT_TRUE(subpath.closed);
  EXPECT_EQ(subpath.points.size(), 4u);
  EXPECT_NEAR(area(filledRegion(document.shapes[0])), 100.0, 1e-9);
}

TEST(PathReader, NoColourLinesMeansFilledBlack) {
  SvgDocument document = readPathString("1\n0 1 0 0 0 10 0 10 10\n", "plain.path");
  ASSERT_EQ(document.shapes.size(), 1u);
  EXPECT_EQ(*document.shapes[0].fill, (Color{0, 0, 0, 1.0}));
  EXPECT_FALSE(document.shapes[0].stroke);
}

TEST(PathReader, ToleratesExtraSpacesBlankLinesAndCrLf) {
  SvgDocument document = readPathString("1\r\n\r\n0  1 0 0 0   10 0 10 10 \r\n", "spaces.path");
  ASSERT_EQ(document.shapes.size(), 1u);
  EXPECT_EQ(document.shapes[0].subpaths[0].points.size(), 3u);
}

TEST(PathReader, ViewBoxFollowsCoordinatesOffTheArtboard) {
  SvgDocument document = readPathString("1\n0 1 0 -100 0 900 0 900 50\n", "big.path");
  EXPECT_DOUBLE_EQ(document.viewBox.min.x, -100.0);
  EXPECT_DOUBLE_EQ(document.viewBox.width(), 1000.0);
}

TEST(PathReaderErrors, GarbageNamesTheLine) {
  const std::string message = errorOf("1\n0 1 0 0 0 10 0\n0 1 0 0 0 abc 0 10 10\n", "animal.path");
  EXPECT_NE(message.find("animal.path:3: expected a number, got \"abc\""), std::string::npos) << message;
}

TEST(PathReaderErrors, EachMalformedLine) {
  EXPECT_NE(errorOf("").find("empty file"), std::string::npos);
  EXPECT_NE(errorOf("one\n").find("bad.path:1:"), std::string::npos);
  EXPECT_NE(errorOf("1\n0 1\n").find("bad.path:2:"), std::string::npos);
  EXPECT_NE(errorOf("1\n3 1 0 0 0 1 0 1 1\n").find("region 3 out of range"), std::string::npos);
  EXPECT_NE(errorOf("1\n0 5 0 0 0 1 0 1 1\n").find("isClosed must be 0 or 1"), std::string::npos);
  EXPECT_NE(errorOf("1\n0 1 0 0 0 1 0 1\n").find("odd number of coordinates"), std::string::npos);
  EXPECT_NE(errorOf("1\n0 1 0 0 0 1 0 nan 1\n").find("not a finite number"), std::string::npos);
  EXPECT_NE(errorOf("1\n0 1 0 0 0 1 0 1e12 1\n").find("absurd"), std::string::npos);
  EXPECT_NE(errorOf("1\nbackground_color_rgb 0 1,2\n0 1 0 0 0 1 0 1 1\n").find("bad.path:2: expected a colour"),
            std::string::npos);
  EXPECT_NE(errorOf("1\nbackground_color_rgb 0 1,2,300\n").find("out of 0..255"), std::string::npos);
  EXPECT_NE(errorOf("1\n").find("no paths"), std::string::npos);
}

TEST(PathReaderErrors, MissingFile) {
  try {
    readPathFile("/no/such/file.path");
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("/no/such/file.path: cannot open"), std::string::npos);
  }
}

TEST(PathReader, UnknownPathTypeIsSkippedWithAWarning) {
  SvgDocument document = readPathString("1\n0 1 0 0 0 10 0 10 10\n0 1 5 0 0 1 0 1 1\n", "types.path");
  EXPECT_EQ(document.shapes.size(), 1u);
  ASSERT_EQ(document.warnings.size(), 1u);
  EXPECT_NE(document.warnings[0].where.find("types.path:3"), std::string::npos);
}

}  // namespace
}  // namespace pak
