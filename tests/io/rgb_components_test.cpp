#include "io/rgb_components.hpp"

#include <gtest/gtest.h>

namespace pak {
namespace {

TEST(RgbComponents, DecimalNumbersRoundAndClampOnly) {
  EXPECT_EQ(roundedRgbComponents("rgb(12.5, 100.2, 200)"), "rgb(13,100, 200)");
  EXPECT_EQ(roundedRgbComponents("fill:rgb(1.5,2,3);stroke:#fff"), "fill:rgb(2,2,3);stroke:#fff");
  EXPECT_EQ(roundedRgbComponents("RGB(300.7, -2.2, 1e1)"), "RGB(255,0,10)");
  EXPECT_EQ(roundedRgbComponents("url(#g) rgb(0.4,0,0)"), "url(#g) rgb(0,0,0)");  // a paint's fallback
  // Nothing to round: integers, percentages, words, an unclosed function, a longer name.
  for (const char* same : {"rgb(10,20,30)", "rgb(10%, 50.5%, 100%)", "rgb(a.5,2,3)", "rgb(1.5,2", "xrgb(1.5,2,3)", "#0a0b0c"})
    EXPECT_EQ(roundedRgbComponents(same), std::nullopt) << same;
}

}  // namespace
}  // namespace pak
