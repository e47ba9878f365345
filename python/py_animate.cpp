#include "py_animate.hpp"

#include <algorithm>
#include <chrono>

#include <CLI/CLI.hpp>

#include "animate_report.hpp"
#include "animate_resolve.hpp"
#include "pak/error.hpp"
#include "pak/io/animation_output.hpp"
#include "pak/io/animation_script_reader.hpp"
#include "pak/sim/canonical_units.hpp"
#include "py_inputs.hpp"
#include "py_options.hpp"
#include "py_progress.hpp"

namespace pak::python {

using namespace pybind11::literals;

namespace {

// A path, or the file's JSON as a dict (json.dumps'd and read by the same reader).
AnimationScript scriptArgument(const py::object& animation, std::string& file) {
  const py::module_ os = py::module_::import("os");
  if (py::isinstance<py::str>(animation) || py::hasattr(animation, "__fspath__")) {
    file = py::cast<std::string>(os.attr("fspath")(animation));
    return readAnimationScript(file);
  }
  if (!py::isinstance<py::dict>(animation))
    throw InputError("animation", "expects the path of an animation file or its JSON as a dict");
  const std::string text = py::cast<std::string>(py::module_::import("json").attr("dumps")(animation));
  return parseAnimationScript(text, "animation", py::cast<std::string>(os.attr("getcwd")()));
}

}  // namespace

AnimationResult animate(const py::object& container, const py::object& animation, const py::object& progress,
                        int progressEvery, const AnimateOutputs& outputs, const py::kwargs& options) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  // The keyword arguments are a --config object, read by `pak animate`'s own table and rules.
  AnimationResult result;
  cli::AnimateArguments& args = result.args;
  args.frames = outputs.frames;
  args.svgKeyframes = outputs.svgKeyframes;
  args.evennessFrames = outputs.evennessFrames;
  CLI::App command;
  cli::animateOptions().addTo(command, args, &args.common.lengths);
  const nlohmann::json config = optionsObject(options, "pak.animate");
  cli::resolveAnimateOptions(args, command, &config, "pak.animate");

  if (container.is_none()) throw InputError("container", "is required");
  if (animation.is_none()) throw InputError("animation", "is required");
  result.script = scriptArgument(animation, args.animation);
  const SceneInput input = sceneArgument(container, "container");
  args.container = input.file;
  result.layout = input.loaded.layout;
  const Scene& scene = input.loaded.scene;
  cli::animateOptions().resolveLengths(
      args, args.common.lengths,
      cli::lengthScale(input.loaded.layout, canonicalFrameBox(simulatedPart(scene, args.options), false)));
  std::vector<LoadedElement> elements;
  for (const AnimatedElementSpec& spec : result.script.elements) {
    std::vector<LoadedElement> one = loadElements({spec.svg});
    if (one.empty()) throw InputError(spec.svg, "holds no element");
    elements.push_back(std::move(one.front()));
  }
  const Library library = libraryOf(elements);

  ProgressHook hook(progress);
  AnimationCallbacks callbacks;
  callbacks.progressEvery = std::max(1, progressEvery);
  callbacks.onProgress = [&](const AnimationProgress& p) {
    hook([&] {
      return py::dict("iteration"_a = p.iteration, "fill"_a = p.fill, "growing_slices"_a = p.growingSlices,
                      "overlapping_slices"_a = p.overlappingSlices, "slices"_a = p.slices,
                      "largest_slice_gap"_a = p.largestSliceGap, "settle_left"_a = p.settleLeft);
    });
  };
  const int frameCount = cli::renderedFrameCount(args, result.script);
  AnimationOptions runOptions = cli::animationRunOptions(args, result.script);
  runOptions.run.stopRequest = hook.stopRequest();
  result.separation = runOptions.frameSeparation;

  {
    py::gil_scoped_release release;
    result.animation = packAnimation(scene, library, result.script, runOptions, callbacks);
    const auto simulated = Clock::now();
    // The frames, the animated SVG and the report as `pak animate` makes them.
    const cli::AnimationFrames render = result.render();
    result.frames = cli::renderFrames(render, frameCount);
    result.svg = animatedSvgText(render.drawings(std::min(args.svgKeyframes, frameCount)), "animation.svg",
                                 cli::animationOutputOptions(args, result.script, result.animation));
    const auto rendered = Clock::now();
    const cli::FrameAudit audit =
        cli::auditRenderedFrames(result.frames, result.animation, result.separation, args.evennessFrames);
    cli::AnimateTimes seconds;
    seconds.wall = std::chrono::duration<double>(Clock::now() - start).count();
    seconds.simulation = std::chrono::duration<double>(simulated - start).count();
    seconds.rendering = std::chrono::duration<double>(rendered - simulated).count();
    result.report = cli::animateReport(args, result.animation, frameCount, audit, seconds);
  }
  hook.rethrow();
  return result;
}

}  // namespace pak::python
