#pragma once
// One palette of at most 256 colours for many images (a GIF's global colour table): median
// cut over a 5-bit-per-channel histogram of all their pixels, then nearest-colour mapping.
#include <cstdint>
#include <optional>
#include <vector>

#include "pak/io/png_renderer.hpp"

namespace pak::color_palette {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  friend bool operator==(const Rgb&, const Rgb&) = default;
};

// Pixel counts per 32 x 32 x 32 colour cell, with the sums of the exact colours in each so a
// cell's colour is the mean of its pixels (flat fills keep their exact colour).
class ColorHistogram {
 public:
  ColorHistogram();
  // Counts the pixels at least half opaque, except those exactly `skip` (a colour the palette
  // holds anyway, like the background, which would otherwise crowd the others out).
  void add(const RgbaImage& image, std::optional<Rgb> skip = std::nullopt);

  struct Cell {
    std::uint64_t count = 0, r = 0, g = 0, b = 0;
  };
  const std::vector<Cell>& cells() const { return cells_; }

 private:
  std::vector<Cell> cells_;
};

// `fixed` colours first, exactly, then up to maxColors - fixed.size() from median cut.
std::vector<Rgb> medianCut(const ColorHistogram& histogram, int maxColors, const std::vector<Rgb>& fixed = {});

// The nearest palette entry (squared RGB distance) among entries [first, size), cached per colour.
class NearestColor {
 public:
  NearestColor(std::vector<Rgb> palette, int first = 0);
  std::uint8_t operator()(Rgb colour);

 private:
  std::vector<Rgb> palette_;
  int first_;
  std::vector<std::uint16_t> cache_;  // by 24-bit colour; 0xffff: not computed yet
};

}  // namespace pak::color_palette
