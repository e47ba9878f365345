// `pak animate`: AnimationPak from the command line.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>

#include "animate_arguments.hpp"
#include "animate_report.hpp"
#include "animate_resolve.hpp"
#include "animate_frames.hpp"
#include "art_check.hpp"
#include "command.hpp"
#include "input_warnings.hpp"
#include "interrupt.hpp"
#include "mirror_option.hpp"
#include "outline_output.hpp"
#include "output_files.hpp"
#include "run_eta.hpp"
#include "pak/error.hpp"
#include "pak/io/output_batch.hpp"
#include "pak/io/animation_checkpoint.hpp"
#include "pak/io/animation_output.hpp"
#include "pak/io/animation_script_reader.hpp"
#include "pak/io/atomic_file.hpp"
#include "pak/io/packing_drawing.hpp"
#include "pak/io/scene_loader.hpp"
#include "pak/io/text_file.hpp"
#include "pak/sim/canonical_units.hpp"

namespace pak::cli {
namespace {

// What a checkpoint belongs to: the input files and every option that shapes the run.
std::uint64_t runFingerprint(const AnimateArguments& args, const Library& library) {
  nlohmann::json parameters;
  animateOptions().report(parameters, args);
  parameters.erase("threads");
  parameters.erase("max-iterations");
  parameters.erase("time-limit");
  // The frame separation runs after the simulation: a resumed run may separate differently.
  for (const char* key :
       {"frame-separation", "frame-separation-samples", "frame-separation-ramp", "frame-separation-shrink-only",
        "frame-separation-shrink-pairs"})
    parameters.erase(key);
  std::uint64_t h = fingerprintBytes(parameters.dump());
  h = fingerprintBytes(readTextFile(args.container), h);
  h = fingerprintBytes(readTextFile(args.animation), h);
  for (const ElementArt& e : library) h = fingerprintBytes(readTextFile(e.source), h);
  return h;
}

int runAnimate(AnimateArguments& args, const CLI::App& command) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const CommonArguments& common = args.common;
  nlohmann::json config;
  if (!common.config.empty()) config = readConfigObject(common.config);
  resolveAnimateOptions(args, command, common.config.empty() ? nullptr : &config, common.config);
  if (!args.video.empty()) checkVideoTarget(args.video);  // before the simulation, not after it
  if (command.count("--png-at") > 0 && common.png.empty()) throw InputError("--png-at", "needs --png FILE, the preview it times");

  const AnimationScript script = readAnimationScript(args.animation);
  const LoadedScene input = loadScene(args.container, SceneOptions{});
  const Scene& scene = input.scene;
  animateOptions().resolveLengths(
      args, common.lengths,
      lengthScale(input.layout, canonicalFrameBox(simulatedPart(scene, args.options), false)));
  std::vector<LoadedElement> elements;
  for (const AnimatedElementSpec& spec : script.elements) {
    std::vector<LoadedElement> one = loadElements({spec.svg});
    if (one.empty()) throw InputError(spec.svg, "holds no element");
    elements.push_back(std::move(one.front()));
  }
  const Library library = libraryOf(elements);
  // Saving the checkpoint onto the one resumed from is how a long run goes on: not an overwrite.
  const std::string resumedFrom = args.resume == args.checkpoint ? std::string() : args.resume;
  checkOutputsBeforeTheRun({{"--png", common.png}, {"--report", common.report}, {"--video", args.video},
                            {"--checkpoint", args.checkpoint}},
                           inputFiles({args.container, args.animation, common.config, resumedFrom}, {&library}));
  checkOutputFolder(common.output);
  if (!common.quiet) printInputWarnings(input.warnings, {&elements});

  const std::uint64_t fingerprint = runFingerprint(args, library);
  AnimationState resumed;
  if (!args.resume.empty()) resumed = readAnimationCheckpoint(args.resume, fingerprint);

  const std::filesystem::path out(common.output);

  AnimationCallbacks callbacks;
  RunEta eta(args.options.stop.maxIterations + std::max(0, args.options.stop.settleIterations));
  if (!common.quiet)
    callbacks.onProgress = [&](const AnimationProgress& p) {
      const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
      char gap[40] = "";
      if (std::isfinite(p.largestSliceGap)) std::snprintf(gap, sizeof gap, "  widest gap %.1f", p.largestSliceGap);
      // The stall rule's measure falls about exponentially: its logarithm, linearly. In the
      // settle, the steps left.
      constexpr double kUnknown = std::numeric_limits<double>::infinity();
      const RunEta::Measures left =
          p.settleLeft >= 0 ? RunEta::Measures{static_cast<double>(p.settleLeft), kUnknown, kUnknown}
                            : RunEta::Measures{static_cast<double>(p.growingSlices),
                                               args.options.stop.closeness > 0.0
                                                   ? p.largestSliceGap - args.options.stop.closeness
                                                   : kUnknown,
                                               std::log(p.growthRise / args.options.stop.stallGrowth)};
      char phase[64];
      if (p.settleLeft >= 0) std::snprintf(phase, sizeof phase, "settling, %d steps to go", p.settleLeft);
      else std::snprintf(phase, sizeof phase, "growing %d/%d slices", p.growingSlices, p.slices);
      std::fprintf(stderr, "pak animate: iteration %5d  fill %.3f  %s  overlapping %d%s  %.1f s  %s\n", p.iteration,
                   p.fill, phase, p.overlappingSlices, gap, elapsed, eta.record(p.iteration, elapsed, left).c_str());
      std::fflush(stderr);
    };
  if (!args.checkpoint.empty()) {
    callbacks.checkpointEvery = common.every;
    callbacks.onCheckpoint = [&](const AnimationState& state) { writeAnimationCheckpoint(state, fingerprint, args.checkpoint); };
  }

  const int frameCount = renderedFrameCount(args, script);
  AnimationOptions options = animationRunOptions(args, script);
  options.run.stopRequest = &interruptRequest();
  const AnimatedPacking animation =
      packAnimation(scene, library, script, options, callbacks, args.resume.empty() ? nullptr : &resumed);
  const auto simulated = Clock::now();
  OutputBatch outputs;  // every output, or none (and the output folder only if it was filled)
  createFolder(common.output);

  const AnimationFrames render(animation, input.layout, script, options.frameSeparation);
  const AnimationOutputOptions output = animationOutputOptions(args, script, animation);
  const RenderedFrames rendered = renderFrames(render, frameCount);
  const std::vector<Drawing>& frames = rendered.drawings;
  if (!args.noGif) writeGif(frames, (out / "animation.gif").string(), output);
  if (args.pngFrames) writePngFrames(frames, (out / "frames").string(), output);
  if (args.svgFrames) writeSvgFrames(frames, (out / "svg-frames").string(), output);
  if (!args.video.empty()) writeVideo(frames, args.video, output);
  if (!common.png.empty()) writePngPreview(render.drawingAt(args.pngAt), common.png, args.width);
  writeAnimatedSvg(render.drawings(std::min(args.svgKeyframes, frameCount)), (out / "animation.svg").string(), output);
  {
    std::vector<Drawing> sheet;
    std::vector<std::string> captions;
    for (int i = 0; i < args.sheetFrames; ++i) {
      const double t = render.time(i, args.sheetFrames);
      sheet.push_back(render.drawingAt(t));
      char caption[32];
      std::snprintf(caption, sizeof caption, "t = %.3g", t);
      captions.push_back(caption);
    }
    writeContactSheet(sheet, captions, (out / "contact-sheet.png").string(), std::min(args.sheetFrames, 5), output);
  }
  const auto renderedAt = Clock::now();

  const FrameAudit audit =
      auditRenderedFrames(rendered, animation, options.frameSeparation, common.report.empty() ? 0 : args.evennessFrames);
  AnimateTimes seconds;
  seconds.wall = std::chrono::duration<double>(Clock::now() - start).count();
  seconds.simulation = std::chrono::duration<double>(simulated - start).count();
  seconds.rendering = std::chrono::duration<double>(renderedAt - simulated).count();

  std::string stopText = toString(animation.stopReason);
  if (animation.settleIterations > 0) stopText += ", then " + std::to_string(animation.settleIterations) + " settling";
  if (!common.quiet)
    std::fprintf(stderr,
                 "pak animate: %zu elements, %zu vertices, %zu springs, %d slices, %d iterations (%s), art fill %.3f "
                 "(mean over frames), %d/%d frames with overlaps, %d with an element outside, %d with a self-crossing "
                 "outline; simulation %.1f s, "
                 "rendering %.1f s; wrote %s\n",
                 animation.elements.size(), animation.vertices, animation.springs, animation.slices, animation.iterations,
                 stopText.c_str(), audit.meanFill, audit.framesWithOverlap, frameCount, audit.framesOutside,
                 audit.framesSelfIntersecting,
                 seconds.simulation, seconds.rendering, common.output.c_str());
  if (!common.report.empty())
    writeFileAtomically(common.report, animateReport(args, animation, frameCount, audit, seconds).dump(2) + "\n");
  outputs.commit();
  return 0;
}

void declareAnimateOptions(CLI::App& command, AnimateArguments& args) {
  command.add_option("--container,-c", args.container, "container SVG (a `container` layer or one closed shape; holes allowed)")->required();
  command.add_option("--animation,-a", args.animation, "animation file (JSON): elements, counts, tracks, handles, targets, loops; see docs/animation-format.md")->required();
  addCommonOptions(command, args.common,
                   {{CommonOption::Output, "output folder"},
                    {CommonOption::Png, "also write the frame at --png-at (t = 0 by default) as a PNG preview to this file"},
                    {CommonOption::Config},
                    {CommonOption::Report, "write a JSON report: parameters, sizes, iterations, times, fill, overlaps per frame"},
                    {CommonOption::Every, "with --checkpoint: iterations between saves"}, {CommonOption::Quiet}});
  command.add_option("--frames", args.frames, "frames to render (0: the animation file's, default 500)")->capture_default_str();
  animateOptions().addTo(command, args, &args.common.lengths);
  command.footer(kLengthHelp);
  command.add_option("--width", args.width, "width in pixels of the GIF, PNG frames, video and contact-sheet cells")->capture_default_str();
  command.add_option("--png-at", args.pngAt, "with --png: the time t ∈ [0, 1] of the preview (any t, not only a frame's)")->capture_default_str();
  command.add_flag("--png-frames", args.pngFrames, "also write OUT/frames/frame-NNNN.png");
  command.add_flag("--svg-frames", args.svgFrames, "also write OUT/svg-frames/frame-NNNN.svg, outlines as cubic Béziers (the animated SVG keeps polygons, which it interpolates)");
  command.add_flag("--polyline", args.polyline, polylineHelp(kMeshCurveTolerance) + " (in the SVG frames)");
  command.add_flag("--no-gif", args.noGif, "skip the GIF");
  command.add_option("--video", args.video, "also write a video, FILE.mp4 or FILE.webm (needs the ffmpeg program)");
  command.add_option("--evenness-frames", args.evennessFrames, "with --report: frames, spread over the animation, whose evenness (negative space, pocket share P2) is measured (0: none)")->capture_default_str();
  command.add_option("--sheet-frames", args.sheetFrames, "frames on the contact sheet, evenly spaced in t")->capture_default_str();
  command.add_option("--svg-keyframes", args.svgKeyframes, "frames stored in the animated SVG (the browser interpolates between them)")->capture_default_str();
  command.add_option("--checkpoint", args.checkpoint, "save the simulation state to this file every --every iterations (atomically)");
  command.add_option("--resume", args.resume, "continue from a checkpoint made with the same inputs and options (bit-identical result)");
}

const CommandRegistrar registrar{subcommand<AnimateArguments>(
    "animate",
    "Pack animated elements into a container (AnimationPak, thesis ch. 5) and render the animation.\n"
    "Each element is a spacetime tube of mesh slices; the tubes repel, deform and grow in (x, y, t)\n"
    "until the container is full at every moment. Writes OUT/animation.gif, OUT/animation.svg (plays\n"
    "in a browser) and OUT/contact-sheet.png, and optionally PNG/SVG frames and a video.\n"
    "Example: pak animate --container examples/animate/stars/disc.svg \\\n"
    "           --animation examples/animate/stars/stars.json -o out/stars",
    declareAnimateOptions, runAnimate)};

}  // namespace
}  // namespace pak::cli
