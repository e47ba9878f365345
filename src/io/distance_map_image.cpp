// Thesis Fig. 6.3b: the discrete distance transform of the negative space as shades.
#include "pak/io/distance_map_image.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>

#include "io/cairo_output.hpp"
#include "pak/error.hpp"
#include "pak/io/atomic_file.hpp"

namespace pak {
namespace {

using namespace cairo_output;

// Dark blue (touching) through teal to pale yellow (the largest empty disc's centre): light
// means far, as in the thesis, and stays distinct from the grey elements.
std::array<double, 3> shade(double t) {
  constexpr std::array<std::array<double, 3>, 3> stops{{{0.05, 0.07, 0.30}, {0.10, 0.55, 0.55}, {1.00, 0.97, 0.70}}};
  t = std::clamp(t, 0.0, 1.0) * 2.0;
  const int k = std::min(1, static_cast<int>(t));
  const double f = t - k;
  return {stops[k][0] + f * (stops[k + 1][0] - stops[k][0]), stops[k][1] + f * (stops[k + 1][1] - stops[k][1]),
          stops[k][2] + f * (stops[k + 1][2] - stops[k][2])};
}

std::uint32_t pixel(double r, double g, double b) {
  auto byte = [](double v) { return static_cast<std::uint32_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); };
  return 0xff000000u | (byte(r) << 16) | (byte(g) << 8) | byte(b);
}

}  // namespace

void writeDistanceMapImage(const PackingGeometry& packing, const std::string& path, int width) {
  checkOutputPath(path);  // a missing folder fails before the transform is computed
  if (width < 16 || width > 8192) throw InputError(path, "distance map width must be 16 to 8192 pixels");
  const DistanceMap map = distanceMap(packing, width);

  SurfacePtr surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, map.columns, map.rows));
  cairo_surface_flush(surface.get());
  unsigned char* data = cairo_image_surface_get_data(surface.get());
  const int stride = cairo_image_surface_get_stride(surface.get());
  const Box box = bounds(packing.container);
  for (int j = 0; j < map.rows; ++j) {
    auto* row = reinterpret_cast<std::uint32_t*>(data + static_cast<std::size_t>(j) * stride);
    for (int i = 0; i < map.columns; ++i) {
      const double d = map.distance[static_cast<std::size_t>(j) * map.columns + i];
      const Vec2 centre = map.origin + Vec2{(i + 0.5) * map.cell, (j + 0.5) * map.cell};
      if (d >= 0.0) {
        const auto [r, g, b] = shade(map.largest > 0.0 ? d / map.largest : 0.0);
        row[i] = pixel(r, g, b);
      } else {
        row[i] = box.contains(centre) && pointInRegion(centre, packing.container) ? pixel(0.72, 0.72, 0.72)
                                                                                  : pixel(1.0, 1.0, 1.0);
      }
    }
  }
  cairo_surface_mark_dirty(surface.get());

  std::string bytes;
  if (cairo_surface_write_to_png_stream(surface.get(), appendToString, &bytes) != CAIRO_STATUS_SUCCESS)
    throw InputError(path, "cannot encode the distance map as PNG");
  writeFileAtomically(path, bytes);
}

}  // namespace pak
