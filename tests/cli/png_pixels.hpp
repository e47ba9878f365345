#pragma once
// Reads a PNG back with cairo so CLI tests can check the colour of chosen pixels.
#include <cairo/cairo.h>

#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

namespace pak::testing {

struct Rgba {
  int r = 0, g = 0, b = 0, a = 0;
};

struct PngPixels {
  int width = 0, height = 0;  // 0 x 0 when the file is not a readable PNG
  std::vector<Rgba> pixels;
  Rgba at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
};

inline PngPixels readPngPixels(const std::string& path) {
  PngPixels image;
  cairo_surface_t* surface = cairo_image_surface_create_from_png(path.c_str());
  if (cairo_surface_status(surface) == CAIRO_STATUS_SUCCESS) {
    image.width = cairo_image_surface_get_width(surface);
    image.height = cairo_image_surface_get_height(surface);
    int stride = cairo_image_surface_get_stride(surface);
    const unsigned char* data = cairo_image_surface_get_data(surface);
    bool opaque = cairo_image_surface_get_format(surface) == CAIRO_FORMAT_RGB24;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        std::uint32_t word = *reinterpret_cast<const std::uint32_t*>(data + y * stride + x * 4);
        int a = opaque ? 255 : static_cast<int>(word >> 24);
        // Cairo stores premultiplied alpha; undo it.
        auto channel = [&](int shift) {
          int value = static_cast<int>((word >> shift) & 0xff);
          return a == 0 ? 0 : (value * 255 + a / 2) / a;
        };
        image.pixels.push_back({channel(16), channel(8), channel(0), a});
      }
  }
  cairo_surface_destroy(surface);
  return image;
}

inline bool near(const Rgba& p, int r, int g, int b, int tolerance = 3) {
  return std::abs(p.r - r) <= tolerance && std::abs(p.g - g) <= tolerance && std::abs(p.b - b) <= tolerance;
}

}  // namespace pak::testing
