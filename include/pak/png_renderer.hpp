#pragma once
// Renders a Drawing to PNG with cairo (anti-aliased).
#include <optional>
#include <string>

#include "pak/art.hpp"
#include "pak/drawing.hpp"

namespace pak {

struct PngOptions {
  int width = 1000;                          // pixels; height follows the aspect ratio
  std::optional<Color> background = Color{255, 255, 255, 1.0};  // nullopt: transparent
};

// Atomic write (temporary file + rename). Throws InputError if it cannot be written.
void writePngFile(const Drawing& drawing, const std::string& path, const PngOptions& = {});

}  // namespace pak
