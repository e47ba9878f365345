#pragma once
// What every animation writer checks and computes the same way: that there are frames, the
// one pixel size all raster frames share, frame file names and timing.
#include <string>
#include <vector>

#include "pak/io/animation_output.hpp"
#include "pak/io/png_renderer.hpp"

namespace pak::animation_frames {

// Throws InputError (naming `where`) when there are no frames or the duration is not positive.
void checkFrames(const std::vector<Drawing>& frames, const AnimationOutputOptions& options, const std::string& where);

// Raster options that give every frame the first frame's pixel size (`evenSize`: rounded up to
// even numbers, as H.264's 4:2:0 chroma needs), so frames whose view boxes differ still match.
PngOptions rasterOptions(const std::vector<Drawing>& frames, const AnimationOutputOptions& options,
                         const std::string& where, bool evenSize = false);

// "frame-0000.png": four digits, more when there are 10000 frames or more, so names sort.
std::string frameFileName(std::size_t index, std::size_t count, const std::string& extension);

// Creates `folder` (and its parents) when missing; throws InputError when it cannot.
void makeFolder(const std::string& folder);

// When frame `index` of `count` starts, in hundredths of a second, rounded so the frames
// add up to the whole duration exactly.
long long frameStartCentiseconds(std::size_t index, std::size_t count, double duration);

}  // namespace pak::animation_frames
