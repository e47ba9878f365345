#include "length_units.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <utility>

#include "pak/sim/canonical_units.hpp"

namespace pak::cli {

namespace {

// CSS pixels per unit: 96 per inch, as SVG and every editor count them.
constexpr std::array<std::pair<const char*, double>, 5> kPxPer{{
    {"mm", 96.0 / 25.4}, {"cm", 96.0 / 2.54}, {"in", 96.0}, {"pt", 96.0 / 72.0}, {"px", 1.0}}};

}  // namespace

const char* const kLengthHelp =
    "LENGTH: a bare number is in canonical units (the frame's longer side is 1000); with a unit it is measured on the "
    "document as an editor shows it: mm, cm, in, pt, px (96 to the inch), or % of the frame's longer side. The "
    "report's parameters give it in canonical units and lengths-given as written.";

std::optional<ParsedLength> parseLength(const std::string& text, std::string& problem) {
  ParsedLength length;
  const char* begin = text.data();
  const char* end = begin + text.size();
  const auto [stop, error] = std::from_chars(begin, end, length.number);
  if (error != std::errc() || !std::isfinite(length.number)) {
    problem = "'" + text + "' is not a length (a number, or a number with mm, cm, in, pt, px or %)";
    return std::nullopt;
  }
  length.unit.assign(stop, end);
  std::transform(length.unit.begin(), length.unit.end(), length.unit.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  const bool known = length.unit.empty() || length.unit == "%" ||
                     std::any_of(kPxPer.begin(), kPxPer.end(), [&](const auto& u) { return length.unit == u.first; });
  if (!known) {
    problem = "'" + text + "': unknown unit '" + length.unit + "' (mm, cm, in, pt, px or %; none: canonical units)";
    return std::nullopt;
  }
  return length;
}

LengthScale lengthScale(const SceneLayout& layout, const Box& frame) {
  const Box& viewBox = layout.viewBox;
  const double widthPx = layout.width;
  LengthScale scale;
  const double side = std::max(frame.width(), frame.height());
  if (!frame.empty() && side > 0.0) scale.canonicalPerUserUnit = kCanonicalSide / side;
  // Without a physical width (or a viewBox) a user unit is a pixel, as in a browser.
  if (!viewBox.empty() && viewBox.width() > 0.0 && widthPx > 0.0 && std::isfinite(widthPx))
    scale.userUnitsPerPx = viewBox.width() / widthPx;
  return scale;
}

double toCanonical(const ParsedLength& length, const LengthScale& scale) {
  if (length.unit.empty()) return length.number;
  if (length.unit == "%") return length.number * kCanonicalSide / 100.0;
  for (const auto& [unit, pxPer] : kPxPer)
    if (length.unit == unit) return length.number * pxPer * scale.userUnitsPerPx * scale.canonicalPerUserUnit;
  return length.number;  // parseLength lets no other unit through
}

}  // namespace pak::cli
