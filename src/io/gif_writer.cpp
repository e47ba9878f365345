// Animated GIF through libcgif. GIF holds at most 256 colours a frame; one global palette,
// built from the frames themselves, keeps the colours of every element steady from frame to
// frame (per-frame palettes make flat fills flicker). Opaque frames let cgif encode only what
// changed since the previous frame; a transparent background takes palette index 0 instead.
#include <cgif.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "io/animation_frames.hpp"
#include "io/color_palette.hpp"
#include "io/drawing_raster.hpp"
#include "pak/error.hpp"
#include "pak/io/animation_output.hpp"
#include "pak/io/atomic_file.hpp"

namespace pak {
namespace {

using color_palette::Rgb;

// Building the palette from every frame of a long animation costs a second render of each;
// this many evenly spaced frames see every colour Pak's animations have (elements keep their
// paint), and the nearest-colour mapping covers the rest.
constexpr std::size_t kPaletteFrames = 64;

struct GifDeleter {
  void operator()(CGIF* gif) const { cgif_close(gif); }
};

int appendBytes(void* context, const std::uint8_t* data, const std::size_t size) {
  static_cast<std::string*>(context)->append(reinterpret_cast<const char*>(data), size);
  return 0;
}

RgbaImage renderFrame(const Drawing& frame, const PngOptions& png, const std::string& path) {
  return raster::toRgba(raster::renderSurface(frame, png, path).get());
}

}  // namespace

void writeGif(const std::vector<Drawing>& frames, const std::string& path, const AnimationOutputOptions& options) {
  animation_frames::checkFrames(frames, options, path);
  checkOutputPath(path);  // a missing folder fails before the rendering
  const PngOptions png = animation_frames::rasterOptions(frames, options, path);
  const bool transparent = !options.background.has_value();

  // Index 0 is transparent when the background is; otherwise the background colour itself, so
  // the largest area is exact. 255 colours at most leave cgif a free index for its "same as
  // the previous frame" optimisation.
  std::vector<Rgb> fixed;
  std::optional<Rgb> backgroundColour;
  if (transparent) {
    fixed.push_back({0, 0, 0});
  } else {
    backgroundColour = Rgb{options.background->r, options.background->g, options.background->b};
    fixed.push_back(*backgroundColour);
  }
  color_palette::ColorHistogram histogram;
  const std::size_t samples = std::min(frames.size(), kPaletteFrames);
  for (std::size_t s = 0; s < samples; ++s)
    histogram.add(renderFrame(frames[s * frames.size() / samples], png, path), backgroundColour);
  std::vector<Rgb> palette = color_palette::medianCut(histogram, transparent ? 256 : 255, fixed);
  while (palette.size() < 2) palette.push_back({0, 0, 0});  // GIF's smallest table
  color_palette::NearestColor nearest(palette, transparent ? 1 : 0);

  std::vector<std::uint8_t> table;
  for (const Rgb& c : palette) table.insert(table.end(), {c.r, c.g, c.b});
  CGIF_Config config{};
  config.pGlobalPalette = table.data();
  config.numGlobalPaletteEntries = static_cast<std::uint16_t>(palette.size());
  config.width = static_cast<std::uint16_t>(png.width);
  config.height = static_cast<std::uint16_t>(png.height);
  config.attrFlags = CGIF_ATTR_IS_ANIMATED;
  if (transparent) config.attrFlags |= CGIF_ATTR_HAS_TRANSPARENCY;
  if (!options.loop) config.attrFlags |= CGIF_ATTR_NO_LOOP;
  config.numLoops = CGIF_INFINITE_LOOP;
  std::string bytes;
  config.pWriteFn = appendBytes;
  config.pContext = &bytes;
  std::unique_ptr<CGIF, GifDeleter> gif(cgif_newgif(&config));
  if (!gif) throw InputError(path, "cannot start the GIF encoder (out of memory?)");

  std::vector<std::uint8_t> indices(static_cast<std::size_t>(png.width) * png.height);
  for (std::size_t i = 0; i < frames.size(); ++i) {
    RgbaImage image = renderFrame(frames[i], png, path);
    const std::uint8_t* p = image.rgba.data();
    for (std::uint8_t& index : indices) {
      index = transparent && p[3] < 128 ? 0 : nearest({p[0], p[1], p[2]});
      p += 4;
    }
    CGIF_FrameConfig frame{};
    frame.pImageData = indices.data();
    if (!transparent) frame.genFlags = CGIF_FRAME_GEN_USE_DIFF_WINDOW | CGIF_FRAME_GEN_USE_TRANSPARENCY;
    // GIF delays are in hundredths of a second; browsers slow anything under 2 down to 10.
    long long delay = animation_frames::frameStartCentiseconds(i + 1, frames.size(), options.duration) -
                      animation_frames::frameStartCentiseconds(i, frames.size(), options.duration);
    frame.delay = static_cast<std::uint16_t>(std::clamp<long long>(delay, 2, 65535));
    if (cgif_addframe(gif.get(), &frame) != CGIF_OK)
      throw InputError(path, "cannot encode GIF frame " + std::to_string(i));
  }
  int result = cgif_close(gif.release());
  if (result != CGIF_OK) throw InputError(path, "cannot encode the GIF (cgif error " + std::to_string(result) + ")");
  writeFileAtomically(path, bytes);
}

}  // namespace pak
