#pragma once
// Colours as Inkscape and CSS Color 4 write them: rgb() with decimal components
// ("rgb(12.5, 100.2, 200)"). SVG++'s colour grammar takes integers (or percentages) only, so
// the reader rounds such components before it parses.
#include <optional>
#include <string>
#include <string_view>

namespace pak {

// `value` with every plain-number component of an rgb(…) rounded to the nearest integer and
// clamped to 0–255; percentages and anything that is not a number stay as written (the parser
// then reports them). Nullopt when nothing changes.
std::optional<std::string> roundedRgbComponents(std::string_view value);

}  // namespace pak
