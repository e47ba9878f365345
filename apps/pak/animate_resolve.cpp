#include "animate_resolve.hpp"

#include <algorithm>
#include <string>

#include "mirror_option.hpp"
#include "pak/error.hpp"
#include "pak/limits.hpp"

namespace pak::cli {
namespace {

void checkOutputOptions(const AnimateArguments& args) {
  if (args.common.every < 1) throw InputError("--every", "must be at least 1");
  if (args.width < 16 || args.width > 8000) throw InputError("--width", "must be between 16 and 8000 pixels");
  if (args.sheetFrames < 1 || args.sheetFrames > 100) throw InputError("--sheet-frames", "must be between 1 and 100");
  using limits::kMaxFrames;
  const std::string upTo = " and " + std::to_string(kMaxFrames);
  if (args.svgKeyframes < 2 || args.svgKeyframes > kMaxFrames) throw InputError("--svg-keyframes", "must be between 2" + upTo);
  if (args.frames < 0 || args.frames > kMaxFrames) throw InputError("--frames", "must be between 1" + upTo);
  if (args.evennessFrames < 0 || args.evennessFrames > kMaxFrames) throw InputError("--evenness-frames", "must be between 0" + upTo);
  if (!(args.pngAt >= 0.0 && args.pngAt <= 1.0)) throw InputError("--png-at", "must be a time t between 0 and 1");
}

}  // namespace

void resolveAnimateOptions(AnimateArguments& args, const CLI::App& command, const nlohmann::json* config,
                           const std::string& configName) {
  if (config) animateOptions().applyConfigObject(*config, configName, command, args, &args.common.lengths);
  if (!args.mirror.empty()) {
    const MirrorLine line = parseMirror(args.mirror);
    if (!line.isVertical()) throw InputError("--mirror", "pak animate mirrors across a vertical line only: x=VALUE");
    args.options.mirrorX = line.from.x;
  }
  checkOutputOptions(args);
}

int renderedFrameCount(const AnimateArguments& args, const AnimationScript& script) {
  return args.frames > 0 ? args.frames : script.frames;
}

AnimationOptions animationRunOptions(const AnimateArguments& args, const AnimationScript& script) {
  AnimationOptions options = args.options;
  if (options.frameSeparation.samples == 0)
    options.frameSeparation.samples =
        std::max(renderedFrameCount(args, script), 2 * (options.slices > 0 ? options.slices : script.slices));
  return options;
}

}  // namespace pak::cli
