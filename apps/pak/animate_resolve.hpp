#pragma once
// `pak animate`'s options as the run uses them, shared by the command line and pak.animate
// (whose keyword arguments are a --config object).
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "animate_arguments.hpp"
#include "pak/animation/animation_script.hpp"

namespace pak::cli {

// `command` holds animateOptions() (what it gave wins over `config`); `config`, when not
// null, is a --config object, its errors naming `configName`. Then checks the output options
// (--frames, --width, --svg-keyframes …).
void resolveAnimateOptions(AnimateArguments& args, const CLI::App& command, const nlohmann::json* config,
                           const std::string& configName);

// The frames rendered: --frames, else the animation file's.
int renderedFrameCount(const AnimateArguments& args, const AnimationScript& script);
// The options the simulation runs with: the frame separation checks at least every frame
// rendered (FrameSeparationOptions::samples).
AnimationOptions animationRunOptions(const AnimateArguments& args, const AnimationScript& script);

}  // namespace pak::cli
