// Lengths with units (issue 17, item 5): parsing, and the conversion to canonical units
// through the document's size and the frame the command maps to 1000.
#include <gtest/gtest.h>

#include "length_units.hpp"

namespace pak::cli {
namespace {

LengthScale scaleOf(const Box& viewBox, double widthPx, const Box& frame) {
  SceneLayout layout;
  layout.viewBox = viewBox;
  layout.width = widthPx;
  return lengthScale(layout, frame);
}

double canonical(const std::string& text, const LengthScale& scale) {
  std::string problem;
  const std::optional<ParsedLength> length = parseLength(text, problem);
  EXPECT_TRUE(length) << problem;
  return length ? toCanonical(*length, scale) : 0.0;
}

TEST(LengthUnits, ABareNumberStaysInCanonicalUnits) {
  const LengthScale scale{2.5, 4.0};
  EXPECT_EQ(canonical("12.5", scale), 12.5);
  EXPECT_EQ(canonical("-1", scale), -1.0);  // negative: "automatic" where an option says so
  EXPECT_EQ(canonical("1e1", scale), 10.0);
}

// A document 100 mm wide with a 400-unit viewBox (4 user units per mm), whose frame's longer
// side is 400 user units (2.5 canonical units each).
TEST(LengthUnits, UnitsGoThroughTheDocumentSizeAndTheFrame) {
  const LengthScale scale = scaleOf(Box{{0, 0}, {400, 200}}, 100.0 * 96.0 / 25.4, Box{{0, 0}, {400, 150}});
  EXPECT_NEAR(scale.canonicalPerUserUnit, 2.5, 1e-12);
  EXPECT_NEAR(canonical("1mm", scale), 4.0 * 2.5, 1e-9);
  EXPECT_NEAR(canonical("1cm", scale), 40.0 * 2.5, 1e-9);
  EXPECT_NEAR(canonical("0.1in", scale), 2.54 * 4.0 * 2.5, 1e-9);
  EXPECT_NEAR(canonical("72pt", scale), 25.4 * 4.0 * 2.5, 1e-9);
  EXPECT_NEAR(canonical("96px", scale), 25.4 * 4.0 * 2.5, 1e-9);
  EXPECT_NEAR(canonical("1%", scale), 10.0, 1e-12);  // of the frame's longer side, whatever the document
  EXPECT_NEAR(canonical("2MM", scale), 20.0, 1e-9);
}

// Without a physical width a user unit is a CSS pixel, as browsers draw it.
TEST(LengthUnits, WithoutAWidthAUserUnitIsAPixel) {
  const LengthScale scale = scaleOf(Box{{0, 0}, {400, 200}}, 0.0, Box{{0, 0}, {1000, 10}});
  EXPECT_EQ(scale.userUnitsPerPx, 1.0);
  EXPECT_NEAR(canonical("3px", scale), 3.0, 1e-12);
  EXPECT_NEAR(canonical("1in", scale), 96.0, 1e-9);
}

TEST(LengthUnits, NonsenseIsRefusedWithTheReason) {
  for (const char* text : {"", "mm", "abc", "2 mm", "2furlong", "nan", "inf", "1e999", "--2"}) {
    std::string problem;
    EXPECT_FALSE(parseLength(text, problem)) << text;
    EXPECT_NE(problem.find(std::string("'") + text + "'"), std::string::npos) << problem;
  }
}

}  // namespace
}  // namespace pak::cli
