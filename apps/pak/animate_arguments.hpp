#pragma once
// What `pak animate` reads from its command line and --config file.
#include <string>

#include "common_options.hpp"
#include "option_table.hpp"
#include "pak/animation/animation.hpp"

namespace pak::cli {

struct AnimateArguments {
  CommonArguments common{.every = 100};  // -o is the output folder; --every paces --checkpoint
  std::string container, animation, checkpoint, resume, video;
  std::string mirror;  // x=VALUE, parsed into options.mirrorX
  int frames = 0, width = 480, sheetFrames = 5, svgKeyframes = 60, evennessFrames = 10;
  double pngAt = 0.0;  // t of the --png preview
  bool pngFrames = false, svgFrames = false, noGif = false;
  bool polyline = false;  // SVG frames' outlines as polygons, not fitted Béziers
  AnimationOptions options;  // also --config keys and report parameters (animateOptions)
};

const OptionTable<AnimateArguments>& animateOptions();

}  // namespace pak::cli
