// The evenness measure's grid as colours, so a user sees where the pockets and channels are.
#include "pak/io/evenness_map_image.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "io/cairo_output.hpp"
#include "pak/error.hpp"
#include "pak/io/atomic_file.hpp"

namespace pak {
namespace {

using namespace cairo_output;
using Rgb = std::array<double, 3>;

std::uint32_t pixel(const Rgb& c) {
  auto byte = [](double v) { return static_cast<std::uint32_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); };
  return 0xff000000u | (byte(c[0]) << 16) | (byte(c[1]) << 8) | byte(c[2]);
}

// Channels from dark blue at the wall to teal at 2h, the distance map's first half; pockets
// in warm colours that stand out against them.
Rgb negativeColour(double d, double h) {
  constexpr Rgb wall{0.05, 0.07, 0.30}, wide{0.10, 0.55, 0.55};
  constexpr Rgb pocket{0.98, 0.62, 0.15}, deepPocket{0.84, 0.13, 0.10};
  if (!(h > 0.0)) return wall;
  if (d > 3.0 * h) return deepPocket;
  if (d > 2.0 * h) return pocket;
  const double t = std::clamp(d / (2.0 * h), 0.0, 1.0);
  return {wall[0] + t * (wide[0] - wall[0]), wall[1] + t * (wide[1] - wall[1]), wall[2] + t * (wide[2] - wall[2])};
}

// The axis one cell wider on each side (within the negative space), so it stays visible when
// the image is shown smaller than one pixel per cell.
std::vector<std::uint8_t> widenedAxis(const EvennessMap& map) {
  std::vector<std::uint8_t> wide(map.axis.size(), 0);
  for (int j = 0; j < map.rows; ++j)
    for (int i = 0; i < map.columns; ++i) {
      if (!map.axis[static_cast<std::size_t>(j) * map.columns + i]) continue;
      for (const auto& [di, dj] : {std::pair{0, 0}, {1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
        const int a = i + di, b = j + dj;
        if (a < 0 || b < 0 || a >= map.columns || b >= map.rows) continue;
        const std::size_t k = static_cast<std::size_t>(b) * map.columns + a;
        if (map.kind[k] == EvennessCell::Negative) wide[k] = 1;
      }
    }
  return wide;
}

Rgb cellColour(const EvennessMap& map, const std::vector<std::uint8_t>& axis, std::size_t k) {
  switch (map.kind[k]) {
    case EvennessCell::Outside: return {1.0, 1.0, 1.0};
    case EvennessCell::Positive: return {0.72, 0.72, 0.72};
    case EvennessCell::FilledHole: return {0.50, 0.50, 0.50};
    case EvennessCell::Negative: break;
  }
  if (axis[k]) return {1.0, 1.0, 1.0};
  return negativeColour(map.distance[k], map.evenness.halfWidth);
}

}  // namespace

Evenness writeEvennessMapImage(const PackingGeometry& packing, const std::string& path,
                               const EvennessOptions& options) {
  checkOutputPath(path);  // a missing folder fails before the measurement
  if (options.resolution < 16 || options.resolution > 8192)
    throw InputError(path, "evenness map width must be 16 to 8192 pixels");
  const EvennessMap map = evennessMap(packing, options);
  const std::vector<std::uint8_t> axis = widenedAxis(map);

  SurfacePtr surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, map.columns, map.rows));
  cairo_surface_flush(surface.get());
  unsigned char* data = cairo_image_surface_get_data(surface.get());
  const int stride = cairo_image_surface_get_stride(surface.get());
  for (int j = 0; j < map.rows; ++j) {
    auto* row = reinterpret_cast<std::uint32_t*>(data + static_cast<std::size_t>(j) * stride);
    for (int i = 0; i < map.columns; ++i) row[i] = pixel(cellColour(map, axis, static_cast<std::size_t>(j) * map.columns + i));
  }
  cairo_surface_mark_dirty(surface.get());

  std::string bytes;
  if (cairo_surface_write_to_png_stream(surface.get(), appendToString, &bytes) != CAIRO_STATUS_SUCCESS)
    throw InputError(path, "cannot encode the evenness map as PNG");
  writeFileAtomically(path, bytes);
  return map.evenness;
}

}  // namespace pak
