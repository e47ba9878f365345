#pragma once
// Renders a Drawing with cairo (anti-aliased): to a PNG file, or to RGBA pixels in memory for
// the animation writers (GIF, video), which all share the same drawing code.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "pak/geom/art.hpp"
#include "pak/io/drawing.hpp"

namespace pak {

// The widest and tallest raster: big enough for print previews, small enough that a typo in a
// width cannot eat the memory (16384² × 4 bytes = 1 GiB), and inside cairo's 32767-pixel limit.
inline constexpr int kMaxPngPixels = 16384;

struct PngOptions {
  int width = 1000;                          // pixels; height follows the aspect ratio
  std::optional<Color> background = Color{255, 255, 255, 1.0};  // nullopt: transparent
  // > 0: the image is exactly width x height and the drawing is fitted and centred in it (like
  // SVG's xMidYMid meet), so every frame of an animation gets the same size.
  int height = 0;
};

// Straight (not premultiplied) 8-bit RGBA, row after row, 4 bytes a pixel.
struct RgbaImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;
};

// Atomic write (temporary file + rename). Throws InputError if it cannot be written.
void writePngFile(const Drawing& drawing, const std::string& path, const PngOptions& = {});
// The PNG file's bytes, in memory (the Python module's to_png); errors name `where`.
std::string renderPng(const Drawing& drawing, const PngOptions& = {}, const std::string& where = "");
// The same picture writePngFile draws, as pixels. Throws InputError on an impossible size.
RgbaImage renderToImage(const Drawing& drawing, const PngOptions& = {});

}  // namespace pak
