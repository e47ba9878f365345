// `pak animate`: AnimationPak from the command line.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "command.hpp"
#include "option_table.hpp"
#include "pak/animation/animation.hpp"
#include "pak/error.hpp"
#include "pak/geom/verify.hpp"
#include "pak/io/animation_checkpoint.hpp"
#include "pak/io/animation_output.hpp"
#include "pak/io/animation_script_reader.hpp"
#include "pak/io/atomic_file.hpp"
#include "pak/io/packing_drawing.hpp"
#include "pak/io/png_renderer.hpp"
#include "pak/io/scene_loader.hpp"
#include "pak/io/text_file.hpp"

namespace pak::cli {
namespace {

const NumberOption<AnimationOptions> kNumberOptions[] = {
    {"element-area", &AnimationOptions::elementArea, "an element's nominal skin area as a fraction of the container (0: 1 / element count)"},
    {"gap", &AnimationOptions::gap, "d_gap as a fraction of the nominal element size (thesis 0.08)"},
    {"mesh-spacing", &AnimationOptions::meshSpacing, "slice mesh spacing, canonical units (0: nominal element size / 4)"},
    {"initial-scale", &AnimationOptions::initialScale, "elements start shrunk to this fraction of their size (thesis 0.05–0.1)"},
    {"torsion", &AnimationOptions::torsionStrength, "k_tor for elements with a preferred orientation"},
    {"stall-growth", &AnimationOptions::stallGrowth, "stop when the slices' mean growth rose less than this over --stall-window iterations"},
    {"closeness", &AnimationOptions::closeness, "stop when every slice is this close to a neighbour or the wall (canonical units; thesis 0.006 of the container)"},
};
const IntegerOption<AnimationOptions> kIntegerOptions[] = {
    {"stall-window", &AnimationOptions::stallWindow, "iterations over which --stall-growth is measured"},
    {"slices", &AnimationOptions::slices, "n_s, slices along t (0: the animation file's, default 100)"},
    {"max-iterations", &AnimationOptions::maxIterations, "stop after this many simulation steps"},
    {"threads", &AnimationOptions::threads, "worker threads (0: all cores); the result does not depend on it"},
};
const OptionTable<AnimationOptions> kOptions{kNumberOptions, kIntegerOptions};

const NumberOption<SpacetimeParameters> kForceOptions[] = {
    {"repulsion", &SpacetimeParameters::repulsionStrength, "k_rpl, repulsion between elements"},
    {"overlap", &SpacetimeParameters::overlapStrength, "k_ovr, pushes a vertex out of another element"},
    {"boundary", &SpacetimeParameters::boundaryStrength, "k_bdr, pulls vertices back into the container"},
    {"edge", &SpacetimeParameters::edgeStrength, "edge and shear springs (shape keeping)"},
    {"negative-space", &SpacetimeParameters::negativeSpaceStrength, "negative-space springs (concavities)"},
    {"time-springs", &SpacetimeParameters::timeStrength, "time springs between consecutive slices: higher is smoother, lower packs tighter (thesis Fig. 5.21)"},
    {"target", &SpacetimeParameters::targetStrength, "pull of a guided element toward its targets"},
    {"temporal", &SpacetimeParameters::temporalStrength, "k_tmp of eq. 5.2, keeps slices at their time"},
    {"time-step", &SpacetimeParameters::timeStep, "Δt_sim"},
    {"velocity-cap", &SpacetimeParameters::velocityCap, "largest vertex speed (canonical units per unit time)"},
    {"damping", &SpacetimeParameters::damping, "fraction of velocity lost per step"},
    {"growth-rate", &SpacetimeParameters::growthRate, "a free slice grows by this × Δt per step"},
    {"max-growth", &SpacetimeParameters::maxGrowth, "growth cap (1: the nominal size)"},
    {"growth-spread", &SpacetimeParameters::growthSpread, "a slice grows only while within this of its neighbouring slices' growth, so sizes do not pulse (0: independent slices, as in the thesis)"},
    {"cell-size", &SpacetimeParameters::cellSize, "collision grid cell and exact repulsion reach (canonical units; thesis 0.04 of the container)"},
    {"time-length", &SpacetimeParameters::timeLength, "length of the t axis in canonical units (x and y span 1000)"},
};
const OptionTable<SpacetimeParameters> kForceTable{kForceOptions, {}};

struct AnimateArguments {
  std::string container, animation, output, config, report, checkpoint, resume, video, png;
  int frames = 0, width = 480, every = 100, sheetFrames = 5, svgKeyframes = 60;
  bool quiet = false, pngFrames = false, svgFrames = false, noGif = false;
  std::uint64_t seed = 1;
  AnimationOptions options;
  CLI::App* command = nullptr;
};

// What a checkpoint belongs to: the input files and every option that shapes the run.
std::uint64_t runFingerprint(const AnimateArguments& args, const Library& library) {
  nlohmann::json parameters;
  kOptions.report(parameters, args.options);
  kForceTable.report(parameters, args.options.simulation);
  parameters.erase("threads");
  parameters.erase("max-iterations");
  parameters["seed"] = args.seed;
  std::uint64_t h = fingerprintBytes(parameters.dump());
  h = fingerprintBytes(readTextFile(args.container), h);
  h = fingerprintBytes(readTextFile(args.animation), h);
  for (const ElementArt& e : library) h = fingerprintBytes(readTextFile(e.source), h);
  return h;
}

int runAnimate(AnimateArguments& args) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  if (!args.config.empty())
    applyConfigFile(args.config, *args.command, kOptions, args.options, [&] {
      std::vector<ConfigKey> keys = tableKeys(kForceTable, args.options.simulation);
      keys.push_back(seedKey("seed", args.seed));
      return keys;
    }());
  args.options.seed = args.seed;
  if (args.every < 1) throw InputError("", "--every must be at least 1");
  if (args.width < 16 || args.width > 8000) throw InputError("", "--width must be between 16 and 8000 pixels");
  if (args.sheetFrames < 1 || args.sheetFrames > 100) throw InputError("", "--sheet-frames must be between 1 and 100");
  if (args.svgKeyframes < 2 || args.svgKeyframes > 10000) throw InputError("", "--svg-keyframes must be between 2 and 10000");
  if (args.frames < 0 || args.frames > 10000) throw InputError("", "--frames must be between 1 and 10000");

  const AnimationScript script = readAnimationScript(args.animation);
  const LoadedScene input = loadScene(args.container, SceneOptions{});
  const Scene& scene = input.scene;
  Library library;
  for (const AnimatedElementSpec& spec : script.elements) {
    Library one = loadLibrary({spec.svg});
    if (one.empty()) throw InputError(spec.svg, "holds no element");
    library.push_back(std::move(one.front()));
  }
  if (!args.quiet)
    for (const Warning& w : input.warnings) std::fprintf(stderr, "pak: warning: %s: %s\n", w.where.c_str(), w.message.c_str());

  const std::uint64_t fingerprint = runFingerprint(args, library);
  AnimationState resumed;
  if (!args.resume.empty()) resumed = readAnimationCheckpoint(args.resume, fingerprint);

  std::error_code ec;
  std::filesystem::create_directories(args.output, ec);
  if (ec) throw InputError(args.output, "cannot create the output folder: " + ec.message());
  const std::filesystem::path out(args.output);

  AnimationCallbacks callbacks;
  if (!args.quiet)
    callbacks.onProgress = [&](const AnimationProgress& p) {
      const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
      std::fprintf(stderr,
                   "pak animate: iteration %5d  fill %.3f  growing %d/%d slices  overlapping %d  widest gap %.1f  %.1f s\n",
                   p.iteration, p.fill, p.growingSlices, p.slices, p.overlappingSlices,
                   std::isfinite(p.largestSliceGap) ? p.largestSliceGap : -1.0, elapsed);
      std::fflush(stderr);
    };
  if (!args.checkpoint.empty()) {
    callbacks.checkpointEvery = args.every;
    callbacks.onCheckpoint = [&](const AnimationState& state) { writeAnimationCheckpoint(state, fingerprint, args.checkpoint); };
  }

  const AnimatedPacking animation =
      packAnimation(scene, library, script, args.options, callbacks, args.resume.empty() ? nullptr : &resumed);
  const auto simulated = Clock::now();

  // Frames at evenly spaced t (5.6); a loop's last frame would repeat the first.
  const int frameCount = args.frames > 0 ? args.frames : script.frames;
  auto frameTime = [&](int i, int count) {
    return script.loop ? static_cast<double>(i) / count : (count > 1 ? static_cast<double>(i) / (count - 1) : 0.0);
  };
  auto drawingAt = [&](double t) { return packingDrawing(input.layout, animationFrame(animation, t)); };
  AnimationOutputOptions output;
  output.duration = script.duration;
  output.loop = script.loop;
  output.width = args.width;

  // Each frame's packing once: it is drawn, and checked below.
  std::vector<Packing> packings;
  std::vector<Drawing> frames;
  packings.reserve(frameCount);
  frames.reserve(frameCount);
  for (int i = 0; i < frameCount; ++i) {
    packings.push_back(animationFrame(animation, frameTime(i, frameCount)));
    frames.push_back(packingDrawing(input.layout, packings.back()));
  }
  if (!args.noGif) writeGif(frames, (out / "animation.gif").string(), output);
  if (args.pngFrames) writePngFrames(frames, (out / "frames").string(), output);
  if (args.svgFrames) writeSvgFrames(frames, (out / "svg-frames").string(), output);
  if (!args.video.empty()) writeVideo(frames, args.video, output);
  if (!args.png.empty()) {
    PngOptions png;
    png.width = args.width;
    writePngFile(frames.front(), args.png, png);
  }
  {
    const int keys = std::min(args.svgKeyframes, frameCount);
    std::vector<Drawing> keyframes;
    for (int i = 0; i < keys; ++i) keyframes.push_back(drawingAt(frameTime(i, keys)));
    writeAnimatedSvg(keyframes, (out / "animation.svg").string(), output);
  }
  {
    std::vector<Drawing> sheet;
    std::vector<std::string> captions;
    for (int i = 0; i < args.sheetFrames; ++i) {
      const double t = frameTime(i, args.sheetFrames);
      sheet.push_back(drawingAt(t));
      char caption[32];
      std::snprintf(caption, sizeof caption, "t = %.3g", t);
      captions.push_back(caption);
    }
    writeContactSheet(sheet, captions, (out / "contact-sheet.png").string(), std::min(args.sheetFrames, 5), output);
  }
  const auto rendered = Clock::now();

  // Overlaps between rendered frames (thesis 5.6 warns of brief ones between slices):
  // measured on every rendered frame, reported, never hidden.
  const double containerArea = area(animation.container);
  PackingCheckOptions checkOptions;
  checkOptions.areaTolerance = 1e-6 * containerArea;
  int framesWithOverlap = 0, framesOutside = 0, worstPairs = 0;
  double worstOverlapArea = 0.0, meanFill = 0.0;
  for (const Packing& frame : packings) {
    const std::vector<Region> outlines = artOutlines(frame);
    for (const Region& r : outlines) meanFill += area(r) / containerArea / frameCount;
    const PackingCheck check = verifyPacking(outlines, animation.container, checkOptions);
    framesWithOverlap += check.overlappingPairs > 0 ? 1 : 0;
    framesOutside += check.elementsOutside > 0 ? 1 : 0;
    worstPairs = std::max(worstPairs, check.overlappingPairs);
    worstOverlapArea = std::max(worstOverlapArea, check.overlapArea / containerArea);
  }
  const double wall = std::chrono::duration<double>(Clock::now() - start).count();
  const double simSeconds = std::chrono::duration<double>(simulated - start).count();
  const double renderSeconds = std::chrono::duration<double>(rendered - simulated).count();

  if (!args.quiet)
    std::fprintf(stderr,
                 "pak animate: %zu elements, %zu vertices, %zu springs, %d slices, %d iterations (%s), art fill %.3f "
                 "(mean over frames), %d/%d frames with overlaps, %d with an element outside; simulation %.1f s, "
                 "rendering %.1f s; wrote %s\n",
                 animation.elements.size(), animation.vertices, animation.springs, animation.slices, animation.iterations,
                 toString(animation.stopReason), meanFill, framesWithOverlap, frameCount, framesOutside, simSeconds,
                 renderSeconds, args.output.c_str());

  if (!args.report.empty()) {
    nlohmann::json parameters;
    kOptions.report(parameters, args.options);
    kForceTable.report(parameters, args.options.simulation);
    parameters["seed"] = args.seed;
    parameters["frames"] = frameCount;
    nlohmann::json report;
    report["parameters"] = parameters;
    report["units"] = "distances in canonical units: the container's bounding square is 1000 wide; t spans time-length";
    report["container"] = args.container;
    report["animation"] = args.animation;
    report["elements"] = animation.elements.size();
    report["vertices"] = animation.vertices;
    report["springs"] = animation.springs;
    report["envelope-triangles"] = animation.envelopeTriangles;
    report["slices"] = animation.slices;
    report["iterations"] = animation.iterations;
    report["stop-reason"] = toString(animation.stopReason);
    report["threads-used"] = animation.threads;
    report["skin-fill-mean-over-slices"] = animation.fill;
    report["art-fill-mean-over-frames"] = meanFill;
    report["overlapping-slices-at-end"] = animation.overlappingSlices;
    report["frames-with-overlaps"] = framesWithOverlap;
    report["frames-with-element-outside"] = framesOutside;
    report["most-overlapping-pairs-in-a-frame"] = worstPairs;
    report["largest-overlap-area-fraction"] = worstOverlapArea;
    report["seconds"] = {{"setup", animation.setupSeconds},
                         {"simulation", animation.seconds - animation.setupSeconds},
                         {"rendering", renderSeconds},
                         {"wall", wall}};
    report["seconds-per-iteration"] =
        animation.iterations > 0 ? (animation.seconds - animation.setupSeconds) / animation.iterations : 0.0;
    writeFileAtomically(args.report, report.dump(2) + "\n");
  }
  return 0;
}

const CommandRegistrar registrar{{"animate", [](CLI::App& app) {
  auto args = std::make_shared<AnimateArguments>();
  CLI::App* cmd = app.add_subcommand(
      "animate",
      "Pack animated elements into a container (AnimationPak, thesis ch. 5) and render the animation.\n"
      "Each element is a spacetime tube of mesh slices; the tubes repel, deform and grow in (x, y, t)\n"
      "until the container is full at every moment. Writes OUT/animation.gif, OUT/animation.svg (plays\n"
      "in a browser) and OUT/contact-sheet.png, and optionally PNG/SVG frames and a video.\n"
      "Example: pak animate --container examples/animate/stars/disc.svg \\\n"
      "           --animation examples/animate/stars/stars.json -o out/stars");
  args->command = cmd;
  cmd->add_option("--container,-c", args->container, "container SVG (a `container` layer or one closed shape; holes allowed)")->required();
  cmd->add_option("--animation,-a", args->animation, "animation file (JSON): elements, counts, tracks, handles, targets, loops; see docs/animation-format.md")->required();
  cmd->add_option("-o,--output", args->output, "output folder")->required();
  cmd->add_option("--frames", args->frames, "frames to render (0: the animation file's, default 500)")->capture_default_str();
  cmd->add_option("--seed", args->seed, "random seed; the same seed gives the same animation")->capture_default_str();
  kOptions.addTo(*cmd, args->options);
  kForceTable.addTo(*cmd, args->options.simulation);
  cmd->add_option("--width", args->width, "width in pixels of the GIF, PNG frames, video and contact-sheet cells")->capture_default_str();
  cmd->add_flag("--png-frames", args->pngFrames, "also write OUT/frames/frame-NNNN.png");
  cmd->add_flag("--svg-frames", args->svgFrames, "also write OUT/svg-frames/frame-NNNN.svg");
  cmd->add_flag("--no-gif", args->noGif, "skip the GIF");
  cmd->add_option("--png", args->png, "also write the first frame (t = 0) as a PNG preview to this file");
  cmd->add_option("--video", args->video, "also write a video, FILE.mp4 or FILE.webm (needs the ffmpeg program)");
  cmd->add_option("--sheet-frames", args->sheetFrames, "frames on the contact sheet, evenly spaced in t")->capture_default_str();
  cmd->add_option("--svg-keyframes", args->svgKeyframes, "frames stored in the animated SVG (the browser interpolates between them)")->capture_default_str();
  cmd->add_option("--checkpoint", args->checkpoint, "save the simulation state to this file every --every iterations (atomically)");
  cmd->add_option("--every", args->every, "with --checkpoint: iterations between saves")->capture_default_str();
  cmd->add_option("--resume", args->resume, "continue from a checkpoint made with the same inputs and options (bit-identical result)");
  cmd->add_option("--config", args->config, "JSON file of option names to values (command-line flags win)");
  cmd->add_option("--report", args->report, "write a JSON report: parameters, sizes, iterations, times, fill, overlaps per frame");
  cmd->add_flag("--quiet,-q", args->quiet, "no progress output");
  return [args] { return runAnimate(*args); };
}}};

}  // namespace
}  // namespace pak::cli
