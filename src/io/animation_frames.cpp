// Checks and sizes shared by the animation writers.
#include "io/animation_frames.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <system_error>

#include "io/drawing_raster.hpp"
#include "pak/error.hpp"
#include "pak/io/atomic_file.hpp"

namespace pak::animation_frames {

void checkFrames(const std::vector<Drawing>& frames, const AnimationOutputOptions& options, const std::string& where) {
  if (frames.empty()) throw InputError(where, "no frames to write");
  if (!(options.duration > 0.0) || !std::isfinite(options.duration))
    throw InputError(where, "animation duration must be a positive number of seconds, not " +
                                std::to_string(options.duration));
}

PngOptions rasterOptions(const std::vector<Drawing>& frames, const AnimationOutputOptions& options,
                         const std::string& where, bool evenSize) {
  PngOptions png;
  png.width = options.width;
  png.background = options.background;
  raster::PixelSize size = raster::pixelSize(frames.front(), png, where);
  if (evenSize) {
    size.width += size.width % 2;
    size.height += size.height % 2;
  }
  png.width = size.width;
  png.height = size.height;
  return png;
}

std::string frameFileName(std::size_t index, std::size_t count, const std::string& extension) {
  std::size_t digits = std::to_string(count > 0 ? count - 1 : 0).size();
  std::string number = std::to_string(index);
  if (number.size() < std::max<std::size_t>(4, digits))
    number.insert(0, std::max<std::size_t>(4, digits) - number.size(), '0');
  return "frame-" + number + extension;
}

void makeFolder(const std::string& folder) {
  if (folder.empty()) throw InputError("", "output folder name is empty");
  namespace fs = std::filesystem;
  std::error_code error;
  if (fs::is_directory(folder, error)) return;
  if (fs::exists(folder, error)) throw InputError(folder, "cannot write frames: it is a file, not a folder");
  const bool created = fs::create_directories(folder, error);
  if (error) throw InputError(folder, "cannot create the folder: " + error.message());
  if (created) listCreatedFolder(folder);  // removed again if the run fails before filling it
}

long long frameStartCentiseconds(std::size_t index, std::size_t count, double duration) {
  return std::llround(100.0 * duration * static_cast<double>(index) / static_cast<double>(count));
}

}  // namespace pak::animation_frames
