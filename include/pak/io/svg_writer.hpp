#pragma once
// Writes a Drawing as SVG that opens in Inkscape and browsers.
#include <cstddef>
#include <string>

#include "pak/io/drawing.hpp"

namespace pak {

struct SvgWriteOptions {
  int precision = 3;  // decimals for coordinates
  // > 0: every subpath of 3 or more points is written as cubic Béziers fitted within this
  // distance (input units; Schneider's method, sharp corners kept) instead of line segments:
  // smooth outlines that are easy to edit.
  double curveTolerance = 0.0;
};

// What the written paths hold, for a report.
struct SvgPathStats {
  std::size_t points = 0;         // coordinate pairs in the paths' `d` (control points included)
  double largestDeviation = 0.0;  // of a fitted curve from the points it fits (input units; 0: none fitted)
  // Of the shapes drawn from an input shape (Shape::drawnPoints > 0): the points they were
  // drawn with, and the points written for them.
  std::size_t drawnPoints = 0, pointsOfDrawnShapes = 0;
};

// `stats`, when given, receives what the paths hold (measuring the deviation costs a little).
std::string toSvgString(const Drawing& drawing, const SvgWriteOptions& = {}, SvgPathStats* stats = nullptr);
// Atomic: writes a temporary file beside `path`, then renames it. Throws InputError if
// the folder cannot be written.
void writeSvgFile(const Drawing& drawing, const std::string& path, const SvgWriteOptions& = {},
                  SvgPathStats* stats = nullptr);

}  // namespace pak
