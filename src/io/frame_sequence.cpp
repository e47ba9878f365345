// An animation as numbered files, one per frame (frame-0000.png …), for video editors, ffmpeg
// command lines and flip-book inspection.
#include <filesystem>
#include <string>

#include "io/animation_frames.hpp"
#include "pak/io/animation_output.hpp"
#include "pak/io/atomic_file.hpp"
#include "pak/io/svg_writer.hpp"

namespace pak {
namespace {

std::string framePath(const std::string& folder, std::size_t index, std::size_t count, const std::string& extension) {
  return (std::filesystem::path(folder) / animation_frames::frameFileName(index, count, extension)).string();
}

}  // namespace

void writePngFrames(const std::vector<Drawing>& frames, const std::string& folder, const AnimationOutputOptions& options) {
  animation_frames::checkFrames(frames, options, folder);
  animation_frames::makeFolder(folder);
  // One pixel size for all, taken from the first frame: a video made from them needs it.
  PngOptions png = animation_frames::rasterOptions(frames, options, folder);
  for (std::size_t i = 0; i < frames.size(); ++i)
    writePngFile(frames[i], framePath(folder, i, frames.size(), ".png"), png);
}

void writeSvgFrames(const std::vector<Drawing>& frames, const std::string& folder, const AnimationOutputOptions& options) {
  animation_frames::checkFrames(frames, options, folder);
  animation_frames::makeFolder(folder);
  SvgWriteOptions svg;
  if (options.svgPrecision >= 0) svg.precision = options.svgPrecision;
  svg.curveTolerance = options.svgCurveTolerance;
  for (std::size_t i = 0; i < frames.size(); ++i)
    writeSvgFile(frames[i], framePath(folder, i, frames.size(), ".svg"), svg);
}

}  // namespace pak
