#pragma once
// Lengths with units on the command line and in --config files: `--gap 2mm`, `0.1in`, `3px`,
// `1%`. A bare number keeps its meaning, canonical units (the frame's longer side is 1000);
// a length with a unit becomes canonical units once the command has read its scene.
#include <map>
#include <optional>
#include <string>

#include "pak/geom/box.hpp"
#include "pak/io/scene_layout.hpp"

namespace pak::cli {

struct ParsedLength {
  double number = 0.0;
  std::string unit;  // "" (canonical units), "mm", "cm", "in", "pt", "px" or "%"
};

// The length `text` gives, or nullopt with `problem` saying what is wrong.
std::optional<ParsedLength> parseLength(const std::string& text, std::string& problem);

// How a scene's units map to canonical ones.
struct LengthScale {
  double canonicalPerUserUnit = 1.0;  // kCanonicalSide / the frame's longer side
  double userUnitsPerPx = 1.0;        // the document's user units per CSS pixel (96 per inch)
};

// `layout` describes the document (its user-unit viewBox and its width in CSS pixels);
// `frame` is what the command maps to canonical units.
LengthScale lengthScale(const SceneLayout& layout, const Box& frame);

double toCanonical(const ParsedLength& length, const LengthScale& scale);

// The length options given with a unit, by option name, as written ("2mm").
using GivenLengths = std::map<std::string, std::string>;

// The help's last words on LENGTH values.
extern const char* const kLengthHelp;

}  // namespace pak::cli
