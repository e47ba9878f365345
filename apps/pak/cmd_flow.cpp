// `pak flow`: FLOWPAK from the command line.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "command.hpp"
#include "flow_arguments.hpp"
#include "flow_report.hpp"
#include "flow_resolve.hpp"
#include "input_warnings.hpp"
#include "interrupt.hpp"
#include "outline_output.hpp"
#include "output_files.hpp"
#include "pak/error.hpp"
#include "pak/io/output_batch.hpp"
#include "pak/io/atomic_file.hpp"
#include "pak/io/flow_drawing.hpp"
#include "pak/io/scene_loader.hpp"
#include "pak/io/svg_writer.hpp"
#include "pak/sim/canonical_units.hpp"

namespace pak::cli {
namespace {


int runFlow(FlowArguments& args, const CLI::App& command) {
  using Clock = std::chrono::steady_clock;
  auto start = Clock::now();
  const CommonArguments& common = args.common;
  nlohmann::json config;
  if (!common.config.empty()) config = readConfigObject(common.config);
  resolveFlowOptions(args, command, common.config.empty() ? nullptr : &config, common.config);

  const LoadedScene input = loadScene(args.scene, SceneOptions{});
  const Scene& scene = input.scene;
  flowOptions().resolveLengths(args, common.lengths,
                               lengthScale(input.layout, canonicalFrameBox(scene, true)));
  const std::vector<LoadedElement> elements = loadElements(args.elements);
  const Library library = libraryOf(elements);
  checkPngWidth(common.pngWidth);
  checkOutputsBeforeTheRun({{"-o", common.output}, {"--png", common.png}, {"--report", common.report}},
                           inputFiles({args.scene, common.config}, {&library}));
  if (!common.quiet) printInputWarnings(input.warnings, {&elements});

  FlowCallbacks callbacks;
  if (!common.quiet)
    callbacks.onProgress = [&](const FlowProgress& p) {
      double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
      if (p.phase == "refinement")
        std::fprintf(stderr, "pak flow: refinement %d/%d  %d elements  element area %.3f of the free space  %.1f s\n",
                     p.iteration, p.iterations, p.elements, p.elementArea, elapsed);
      else
        std::fprintf(stderr, "pak flow: %s  %.1f s\n", p.phase.c_str(), elapsed);
      std::fflush(stderr);
    };
  if (!common.snapshots.empty()) {
    createFolder(common.snapshots);
    if (common.every < 1) throw InputError("--every", "must be at least 1");
    callbacks.onIteration = [&](const FlowPacking& p, int iteration) {
      if (iteration % common.every != 0 && iteration != args.options.iterations) return;
      char name[64];
      std::snprintf(name, sizeof name, "iteration-%03d.svg", iteration);
      writeSvgFile(flowDrawing(input.layout, p, elements), (std::filesystem::path(common.snapshots) / name).string());
    };
  }

  args.options.run.stopRequest = &interruptRequest();
  FlowPacking packing = packFlow(scene, library, args.options, callbacks);
  OutputBatch outputs;  // every output, or none
  FlowDrawingOptions drawingOptions;
  drawingOptions.debugLayers = common.debugLayers;
  Drawing drawing = flowDrawing(input.layout, packing, elements, drawingOptions);
  const SvgWriteOptions svgOptions = outlineWriteOptions(args.polyline, kFlowCurveTolerance, packing.canonicalScale);
  SvgPathStats paths;
  writeSvgFile(drawing, common.output, svgOptions, common.report.empty() ? nullptr : &paths);  // measuring the fit is for the report
  writePngPreview(drawing, common.png, common.pngWidth);

  const PackingCheck check = auditFlowPacking(packing, library);
  const double wall = std::chrono::duration<double>(Clock::now() - start).count();
  if (!common.quiet)
    std::fprintf(stderr,
                 "pak flow: %zu elements (%zu gap shapes), %zu streamlines, %d refinement iterations, element area "
                 "%.3f of the free space, %d overlapping pairs, %d outside, %d folded, %.1f s%s\n",
                 packing.elements.size(), packing.gapElements.size(), packing.streamlines.size(), packing.iterations,
                 flowFill(packing), check.overlappingPairs, check.elementsOutside, check.selfIntersecting, wall,
                 packing.stopReason == StopReason::IterationCap ? "" : packing.stopReason == StopReason::TimeLimit
                                                                         ? " (stopped by --time-limit)"
                                                                         : " (stopped by Ctrl-C)");
  if (!common.report.empty()) writeFileAtomically(common.report, flowReport(args, packing, check, paths, wall).dump(2) + "\n");
  outputs.commit();
  return 0;
}

void declareFlowOptions(CLI::App& command, FlowArguments& args) {
  command.add_option("scene,--container,-c", args.scene,
                     "scene SVG, as -c/--container or the first argument: layers `container` (closed regions), "
                     "`guides` (direction strokes; every container needs one), optional `fixed` (copied, avoided) "
                     "and `spines` (fixed spines)")
      ->required();
  command.add_option("--elements,-e", args.elements,
                     "element files and/or folders; an element may mark its spine with <path id=\"spine\"> (default: "
                     "its principal axis)")
      ->required();
  addCommonOptions(
      command, args.common,
      {{CommonOption::Output, "output SVG"}, {CommonOption::Png}, {CommonOption::PngWidth}, {CommonOption::Config},
       {CommonOption::Report, "write a JSON report: parameters, counts, times per phase, fill ratio, overlaps"},
       {CommonOption::Snapshots,
        "write the packing after placement (iteration-000.svg) and after refinement iterations into this folder"},
       {CommonOption::Every, "with --snapshots: every N-th refinement iteration (and the last)"},
       {CommonOption::DebugLayers, "add layers showing the vector field, streamlines, element spines and blobs"},
       {CommonOption::Quiet}});
  flowOptions().addTo(command, args, &args.common.lengths);
  command.footer(kLengthHelp);
}

const CommandRegistrar registrar{subcommand<FlowArguments>(
    "flow",
    "Fill containers with elements bent along a flow (FLOWPAK, thesis ch. 3).\n"
    "The scene's `guides` strokes set a vector field; evenly spaced streamlines each receive the\n"
    "element whose shape best fits the space around them, bent along the streamline; then\n"
    "streamlines shift and blobs grow for --iterations rounds to even out the negative space.\n"
    "Example: pak flow examples/flow/koi.svg --elements examples/flow/elements -o out.svg --png out.png",
    declareFlowOptions, runFlow)};

}  // namespace
}  // namespace pak::cli
