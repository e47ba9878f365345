// `pak flow`: FLOWPAK from the command line.
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "command.hpp"
#include "option_table.hpp"
#include "pak/error.hpp"
#include "pak/flow/flow.hpp"
#include "pak/geom/verify.hpp"
#include "pak/io/atomic_file.hpp"
#include "pak/io/flow_drawing.hpp"
#include "pak/io/png_renderer.hpp"
#include "pak/io/scene_loader.hpp"
#include "pak/io/svg_writer.hpp"

namespace pak::cli {
namespace {

const NumberOption<FlowOptions> kNumberOptions[] = {
    {"gap", &FlowOptions::gap, "s_gap, the distance between neighbouring streamlines, about an element's width (canonical units: l_canvas, the larger side of the containers' bounds, is 1000)"},
    {"min-length", &FlowOptions::minLength, "s_min: shorter streamlines get no element (canonical units)"},
    {"max-length", &FlowOptions::maxLength, "s_max: streamlines stop before this length (canonical units)"},
    {"stop-ratio", &FlowOptions::stopRatio, "s_stop = ratio × s_gap: a streamline stops this close to another"},
    {"sample-spacing", &FlowOptions::sampleSpacing, "sampling of guides, boundaries and streamlines (canonical units; thesis 0.005 l_canvas)"},
    {"spacing", &FlowOptions::spacing, "space kept between elements, and between elements and walls (canonical units)"},
    {"growth-tolerance", &FlowOptions::growthTolerance, "α: a refined placement is kept when its area is at least α × the old one"},
    {"growth-limit", &FlowOptions::growthLimit, "g_limit: how far a streamline end or a blob moves per iteration (canonical units)"},
    {"shift-distance-weight", &FlowOptions::shiftDistanceWeight, "w_d of eq. 3.2: keeps a shifted streamline near the old one"},
    {"shift-field-weight", &FlowOptions::shiftFieldWeight, "w_f of eq. 3.2: keeps a shifted streamline along the field"},
    {"shift-field-power", &FlowOptions::shiftFieldPower, "p of eq. 3.2"},
    {"fill-gaps-inset", &FlowOptions::fillGapsInset, "with --fill-gaps: the gap shapes' inset from the elements (canonical units; 0: spacing / 2)"},
};
const IntegerOption<FlowOptions> kIntegerOptions[] = {
    {"iterations", &FlowOptions::iterations, "refinement iterations (Algorithm 2)"},
    {"max-rotation", &FlowOptions::maxRotationDegrees, "refinement tries rotations of ±1…N degrees"},
    {"lr-samples", &FlowOptions::lrSamples, "n_f, samples of the LR functions"},
    {"field-resolution", &FlowOptions::fieldResolution, "vector field grid cells along the longer side"},
    {"blob-resolution", &FlowOptions::blobResolution, "blob (Voronoi) grid cells along the longer side"},
    {"shift-neighbours", &FlowOptions::shiftNeighbours, "nearest nodes examined from each node when shifting a streamline"},
};
const OptionTable<FlowOptions> kOptions{kNumberOptions, kIntegerOptions};

// --smooth: how far the written Bézier outlines may stray from the bent polygons (canonical units).
constexpr double kSmoothTolerance = 0.4;

struct FlowArguments {
  std::string scene;
  std::vector<std::string> elements;
  std::string output, png, config, report, snapshots, mirror;
  int pngWidth = 1200;
  int every = 1;
  bool quiet = false, debugLayers = false, fillGaps = false, smooth = false;
  std::uint64_t seed = 1;
  FlowOptions options;
  CLI::App* command = nullptr;
};

void applyConfig(FlowArguments& args) {
  applyConfigFile(args.config, *args.command, kOptions, args.options,
                  {seedKey("seed", args.seed), booleanKey("fill-gaps", args.fillGaps), booleanKey("smooth", args.smooth),
                   stringKey("mirror", args.mirror)});
}

// "x=VALUE" (input units) for --mirror.
double parseMirror(const std::string& text) {
  double x = 0.0;
  char extra = 0;
  if (std::sscanf(text.c_str(), " x = %lf %c", &x, &extra) != 1 || !std::isfinite(x))
    throw InputError("", "--mirror expects x=VALUE (the vertical mirror line, input units), got \"" + text + "\"");
  return x;
}

int runFlow(FlowArguments& args) {
  using Clock = std::chrono::steady_clock;
  auto start = Clock::now();
  if (!args.config.empty()) applyConfig(args);
  args.options.seed = args.seed;
  args.options.fillGaps = args.fillGaps;
  if (!args.mirror.empty()) args.options.mirrorX = parseMirror(args.mirror);

  const LoadedScene input = loadScene(args.scene, SceneOptions{});
  const Scene& scene = input.scene;
  const std::vector<LoadedElement> elements = loadElements(args.elements);
  const Library library = libraryOf(elements);
  if (!args.quiet)
    for (const Warning& w : input.warnings) std::fprintf(stderr, "pak: warning: %s: %s\n", w.where.c_str(), w.message.c_str());

  FlowCallbacks callbacks;
  if (!args.quiet)
    callbacks.onProgress = [&](const FlowProgress& p) {
      double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
      if (p.phase == "refinement")
        std::fprintf(stderr, "pak flow: refinement %d/%d  %d elements  element area %.3f of the free space  %.1f s\n",
                     p.iteration, p.iterations, p.elements, p.elementArea, elapsed);
      else
        std::fprintf(stderr, "pak flow: %s  %.1f s\n", p.phase.c_str(), elapsed);
      std::fflush(stderr);
    };
  if (!args.snapshots.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(args.snapshots, ec);
    if (ec) throw InputError(args.snapshots, "cannot create snapshot folder: " + ec.message());
    if (args.every < 1) throw InputError("", "--every must be at least 1");
    callbacks.onIteration = [&](const FlowPacking& p, int iteration) {
      if (iteration % args.every != 0 && iteration != args.options.iterations) return;
      char name[64];
      std::snprintf(name, sizeof name, "iteration-%03d.svg", iteration);
      writeSvgFile(flowDrawing(input.layout, p, elements), (std::filesystem::path(args.snapshots) / name).string());
    };
  }

  FlowPacking packing = packFlow(scene, library, args.options, callbacks);
  FlowDrawingOptions drawingOptions;
  drawingOptions.debugLayers = args.debugLayers;
  Drawing drawing = flowDrawing(input.layout, packing, elements, drawingOptions);
  SvgWriteOptions svgOptions;
  if (args.smooth) svgOptions.curveTolerance = kSmoothTolerance / packing.canonicalScale;
  writeSvgFile(drawing, args.output, svgOptions);
  if (!args.png.empty()) {
    PngOptions png;
    png.width = args.pngWidth;
    writePngFile(drawing, args.png, png);
  }

  // Invariants of the result, on the art as drawn; fixed elements count as one more element.
  std::vector<Region> outlines;
  for (const auto* list : {&packing.elements, &packing.gapElements})
    for (const FlowElement& e : *list) outlines.push_back(e.outline);
  if (!packing.fixedArt.empty()) outlines.push_back(packing.fixedArt);
  const double containerArea = area(packing.container);
  PackingCheckOptions checkOptions;
  checkOptions.areaTolerance = 1e-6 * containerArea;
  PackingCheck check = verifyPacking(outlines, packing.container, checkOptions);
  const double fill = flowFill(packing);
  const double wall = std::chrono::duration<double>(Clock::now() - start).count();
  if (!args.quiet)
    std::fprintf(stderr,
                 "pak flow: %zu elements (%zu gap shapes), %zu streamlines, %d refinement iterations, element area "
                 "%.3f of the free space, %d overlapping pairs, %d outside, %.1f s\n",
                 packing.elements.size(), packing.gapElements.size(), packing.streamlines.size(), packing.iterations,
                 fill, check.overlappingPairs, check.elementsOutside, wall);

  if (!args.report.empty()) {
    nlohmann::json parameters;
    kOptions.report(parameters, args.options);
    parameters["seed"] = args.seed;
    parameters["fill-gaps"] = args.fillGaps;
    parameters["mirror"] = args.mirror;
    parameters["smooth"] = args.smooth;
    nlohmann::json report;
    report["parameters"] = parameters;
    report["units"] = "distances in canonical units: l_canvas (the larger side of the containers' and fixed elements' bounds) is 1000";
    report["scene"] = args.scene;
    report["elements-library"] = args.elements;
    report["element-count"] = packing.elements.size();
    report["gap-element-count"] = packing.gapElements.size();
    report["streamline-count"] = packing.streamlines.size();
    report["iterations"] = packing.iterations;
    report["placements-tried"] = packing.placementsTried;
    report["placements-accepted"] = packing.placementsAccepted;
    report["fill-ratio-art"] = fill;
    report["fill-ratio-includes"] = "placed elements (and gap shapes) over the free space (containers minus fixed elements)";
    report["element-area-per-iteration"] = packing.areaPerIteration;
    report["seconds"] = {{"field", packing.seconds.field},           {"streamlines", packing.seconds.streamlines},
                         {"blobs", packing.seconds.blobs},           {"placement", packing.seconds.placement},
                         {"refinement", packing.seconds.refinement}, {"extras", packing.seconds.extras},
                         {"wall", wall}};
    report["overlap-count"] = check.overlappingPairs;
    report["overlap-area"] = check.overlapArea;
    report["elements-outside"] = check.elementsOutside;
    report["outside-area"] = check.outsideArea;
    report["problems"] = check.problems;
    report["canonical-scale"] = packing.canonicalScale;
    std::vector<int> perContainer(packing.containers.size(), 0);
    for (const FlowElement& e : packing.elements)
      if (e.container >= 0 && e.container < static_cast<int>(perContainer.size())) ++perContainer[e.container];
    report["elements-per-container"] = perContainer;
    writeFileAtomically(args.report, report.dump(2) + "\n");
  }
  return 0;
}

const CommandRegistrar registrar{{"flow", [](CLI::App& app) {
  auto args = std::make_shared<FlowArguments>();
  CLI::App* cmd = app.add_subcommand(
      "flow",
      "Fill containers with elements bent along a flow (FLOWPAK, thesis ch. 3).\n"
      "The scene's `guides` strokes set a vector field; evenly spaced streamlines each receive the\n"
      "element whose shape best fits the space around them, bent along the streamline; then\n"
      "streamlines shift and blobs grow for --iterations rounds to even out the negative space.\n"
      "Example: pak flow examples/flow/koi.svg --elements examples/flow/elements -o out.svg --png out.png");
  args->command = cmd;
  cmd->add_option("scene", args->scene,
                  "scene SVG: layers `container` (closed regions), `guides` (direction strokes; every container needs "
                  "one), optional `fixed` (copied, avoided) and `spines` (fixed spines)")
      ->required();
  cmd->add_option("--elements,-e", args->elements,
                  "element files and/or folders; an element may mark its spine with <path id=\"spine\"> (default: its "
                  "principal axis)")
      ->required();
  cmd->add_option("-o,--output", args->output, "output SVG")->required();
  cmd->add_option("--png", args->png, "also render a PNG preview to this file");
  cmd->add_option("--png-width", args->pngWidth, "PNG width in pixels")->capture_default_str();
  cmd->add_option("--seed", args->seed, "random seed; the same seed gives the same packing")->capture_default_str();
  kOptions.addTo(*cmd, args->options);
  cmd->add_flag("--fill-gaps", args->fillGaps, "add shapes made from the negative space between the elements (thesis Fig. 3.15)");
  cmd->add_flag("--smooth", args->smooth,
                "write outlines as cubic Béziers fitted within 0.4 canonical units instead of polygons (thesis 3.4's "
                "post-process): smaller files, easier to edit");
  cmd->add_option("--mirror", args->mirror,
                  "x=VALUE: pack the part of the scene left of the vertical line x = VALUE (input units) and reflect it "
                  "(thesis Fig. 3.13)");
  cmd->add_option("--config", args->config, "JSON file of option names to values (command-line flags win)");
  cmd->add_option("--report", args->report, "write a JSON report: parameters, counts, times per phase, fill ratio, overlaps");
  cmd->add_option("--snapshots", args->snapshots,
                  "write the packing after placement (iteration-000.svg) and after refinement iterations into this folder");
  cmd->add_option("--every", args->every, "with --snapshots: every N-th refinement iteration (and the last)")->capture_default_str();
  cmd->add_flag("--debug-layers", args->debugLayers, "add layers showing the vector field, streamlines, element spines and blobs");
  cmd->add_flag("--quiet,-q", args->quiet, "no progress output");
  return [args] { return runFlow(*args); };
}}};

}  // namespace
}  // namespace pak::cli
