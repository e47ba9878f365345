#pragma once
// Writes a Drawing as SVG that opens in Inkscape and browsers.
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

std::string toSvgString(const Drawing& drawing, const SvgWriteOptions& = {});
// Atomic: writes a temporary file beside `path`, then renames it. Throws InputError if
// the folder cannot be written.
void writeSvgFile(const Drawing& drawing, const std::string& path, const SvgWriteOptions& = {});

}  // namespace pak
