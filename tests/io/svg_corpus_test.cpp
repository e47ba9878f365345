// tests/svg: small drawings of our own made the way real icon sets make theirs (tabler,
// OpenMoji, flag-icons; see docs/icon-sets.md). Each is read as an element library and must
// give its known answer: how many elements, the area they paint, what their art holds, and
// no warning. (clipped-square.svg and unsupported-effects.svg are checked by inspect_test.)
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "pak/io/scene_loader.hpp"

namespace pak {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::vector<LoadedElement> readCorpus(const std::string& name) {
  return loadElements({std::string(PAK_SOURCE_DIR) + "/tests/svg/" + name});
}

std::string warningsOf(const LoadedElement& element) {
  std::string text;
  for (const Warning& warning : element.warnings) text += warning.where + ": " + warning.message + "\n";
  return text;
}

std::size_t shapesPainted(const LoadedElement& element, const Color& color) {
  return static_cast<std::size_t>(std::count_if(element.shapes.begin(), element.shapes.end(), [&](const SvgShape& s) {
    return (s.fill && *s.fill == color) || (s.stroke && *s.stroke == color);
  }));
}

// Tabler-like: paint on the root, an invisible frame, strokes, a zero-length round-capped dot.
TEST(SvgCorpus, OutlineIcon) {
  const std::vector<LoadedElement> elements = readCorpus("outline-icon.svg");
  ASSERT_EQ(elements.size(), 1u);
  const LoadedElement& icon = elements[0];
  EXPECT_TRUE(icon.warnings.empty()) << warningsOf(icon);
  EXPECT_EQ(icon.shapes.size(), 3u);  // the frame is no shape
  // The square's band (18² − 14² less four round corners), the bar with its round caps, the dot.
  const double band = 18.0 * 18.0 - 14.0 * 14.0 - 4.0 * (1.0 - kPi / 4.0);
  EXPECT_NEAR(area(icon.element.outline), band + (16.0 + kPi) + kPi, 0.5);
  EXPECT_EQ(icon.element.outline.size(), 3u);  // band, bar, dot: the dot is not lost
}

// OpenMoji-like: a `color` layer under a `line` layer is one element holding both.
TEST(SvgCorpus, LayeredEmojiIsOneElement) {
  const std::vector<LoadedElement> elements = readCorpus("layered-emoji.svg");
  ASSERT_EQ(elements.size(), 1u);
  const LoadedElement& face = elements[0];
  EXPECT_EQ(face.element.name, "layered-emoji");
  EXPECT_TRUE(face.warnings.empty()) << warningsOf(face);
  ASSERT_EQ(face.shapes.size(), 5u);
  EXPECT_EQ(face.shapes[0].layer, "color");
  EXPECT_EQ(face.shapes[1].layer, "line");
  EXPECT_EQ(shapesPainted(face, Color{0xfc, 0xea, 0x2b, 1.0}), 1u);
  EXPECT_EQ(shapesPainted(face, Color{0, 0, 0, 1.0}), 4u);
  EXPECT_NEAR(area(face.element.outline), kPi * 25.0 * 25.0, 3.0);
}

// flag-icons-like: a clip group cuts a wider drawing square, stars are <use> copies (one beyond
// the clip is dropped), and a band copied by a <use> at the root stays in the same element.
TEST(SvgCorpus, FlagWithUseStarsInAClipGroup) {
  const std::vector<LoadedElement> elements = readCorpus("flag-stars.svg");
  ASSERT_EQ(elements.size(), 1u);
  const LoadedElement& flag = elements[0];
  EXPECT_TRUE(flag.warnings.empty()) << warningsOf(flag);
  EXPECT_EQ(flag.shapes.size(), 5u);
  EXPECT_EQ(shapesPainted(flag, Color{255, 255, 255, 1.0}), 3u);
  EXPECT_EQ(shapesPainted(flag, Color{0xd0, 0x3a, 0x2f, 1.0}), 1u);
  EXPECT_NEAR(area(flag.element.outline), 3600.0, 1e-6);
}

// use-clones.svg copies stripes with <use> at the root: each copy is a top-level group, and
// all of them, laid over the field, are one drawing (they were five elements).
TEST(SvgCorpus, RootLevelUsesAreOneElement) {
  const std::vector<LoadedElement> elements = readCorpus("use-clones.svg");
  ASSERT_EQ(elements.size(), 1u);
  EXPECT_NEAR(area(elements[0].element.outline), 120.0 * 60.0, 1e-6);
}

}  // namespace
}  // namespace pak
