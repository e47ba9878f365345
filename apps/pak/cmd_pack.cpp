// `pak pack`: RepulsionPak from the command line.
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>

#include "command.hpp"
#include "input_warnings.hpp"
#include "interrupt.hpp"
#include "outline_output.hpp"
#include "output_files.hpp"
#include "pack_arguments.hpp"
#include "pack_report.hpp"
#include "pack_resolve.hpp"
#include "pak/error.hpp"
#include "pak/io/atomic_file.hpp"
#include "pak/io/output_batch.hpp"
#include "pak/io/packing_drawing.hpp"
#include "pak/io/png_renderer.hpp"
#include "pak/io/scene_loader.hpp"
#include "pak/io/svg_writer.hpp"
#include "pak/io/tile_drawing.hpp"
#include "pak/repulsion/repulsion_presets.hpp"
#include "pak/repulsion/tiling.hpp"
#include "pak/sim/canonical_units.hpp"

namespace pak::cli {
namespace {

std::string formatSeconds(double s) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1f s", s);
  return buffer;
}

int runPack(PackArguments& args, const CLI::App& command) {
  using Clock = std::chrono::steady_clock;
  auto start = Clock::now();
  nlohmann::json config;
  if (!args.common.config.empty()) config = readConfigObject(args.common.config);
  resolvePackOptions(args, command, args.common.config.empty() ? nullptr : &config, args.common.config);
  const CommonArguments& common = args.common;
  const bool tiled = isTiled(args.options.tiling.size);
  if (tiled && !args.container.empty()) throw InputError("--tile", "packs its own rectangle; give no --container");
  if (!tiled && args.container.empty()) throw InputError("--container", "is required (or --tile W,H)");
  if (!args.tilePreview.empty() && !tiled) throw InputError("--tile-preview", "needs --tile W,H");
  if (args.tilePreviewRepeat < 1 || args.tilePreviewRepeat > 16) throw InputError("--tile-preview-repeat", "must be 1 to 16");
  SceneOptions sceneOptions;
  sceneOptions.containerLayer = args.containerLayer;
  const Vec2 tile = args.options.tiling.size;
  const LoadedScene input = tiled ? LoadedScene{tileScene(tile), tileLayout(tile), {}} : loadScene(args.container, sceneOptions);
  const Scene& scene = input.scene;
  packOptions().resolveLengths(args, common.lengths,
                               lengthScale(input.layout, canonicalFrameBox(scene, false)));
  const std::vector<LoadedElement> elements = loadElements(args.elements);
  const std::vector<LoadedElement> secondaryElements = args.secondary.empty() ? std::vector<LoadedElement>{} : loadElements(args.secondary);
  Library library = libraryOf(elements);
  Library secondaryLibrary = libraryOf(secondaryElements);
  checkPngWidth(common.pngWidth);
  checkOutputsBeforeTheRun({{"-o", common.output}, {"--png", common.png}, {"--report", common.report}, {"--tile-preview", args.tilePreview}},
                           inputFiles({args.container, common.config}, {&library, &secondaryLibrary}));
  if (!common.quiet) printInputWarnings(input.warnings, {&elements, &secondaryElements});

  const bool tty = isatty(STDERR_FILENO);
  RepulsionCallbacks callbacks;
  if (!common.quiet) {
    callbacks.progressEvery = args.progressEvery > 0 ? args.progressEvery : (tty ? 50 : 1000);
    callbacks.onProgress = [&](const RepulsionProgress& p) {
      double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
      std::fprintf(stderr, "%spak pack: iteration %6d  fill %.3f  growing %3d/%d (blocked: %d by neighbours, %d by the wall)  %s%s",
                   tty ? "\r" : "", p.iteration, p.fill, p.growing, p.elements, p.touchingNeighbours, p.againstWall,
                   formatSeconds(elapsed).c_str(), tty ? "   " : "\n");
      std::fflush(stderr);
    };
  }
  if (!common.snapshots.empty()) {
    createFolder(common.snapshots);
    callbacks.snapshotEvery = std::max(1, common.every);
    callbacks.onSnapshot = [&](const Packing& p) {
      char name[64];
      std::snprintf(name, sizeof name, "snapshot-%06d.svg", p.iterations);
      writeSvgFile(packingDrawing(input.layout, p), (std::filesystem::path(common.snapshots) / name).string());
    };
  }

  auto simulationStart = Clock::now();
  args.options.run.stopRequest = &interruptRequest();
  Packing packing = packRepulsion(scene, library, secondaryLibrary, args.options, callbacks);
  PackTimes times;
  times.simulation = std::chrono::duration<double>(Clock::now() - simulationStart).count();
  if (!common.quiet && tty) std::fprintf(stderr, "\n");

  OutputBatch outputs;  // every output, or none: a failed PNG leaves no SVG behind
  PackingDrawingOptions drawingOptions;
  drawingOptions.debugLayers = common.debugLayers;
  Drawing drawing = packingDrawing(input.layout, packing, drawingOptions);
  SvgPathStats paths;
  writeSvgFile(drawing, common.output, outlineWriteOptions(args.polyline, kMeshCurveTolerance, packing.canonicalScale),
               common.report.empty() ? nullptr : &paths);  // measuring the fit is for the report
  writePngPreview(drawing, common.png, common.pngWidth);
  if (!args.tilePreview.empty()) {
    const int n = args.tilePreviewRepeat;
    writePngPreview(tileRepetition(drawing, args.options.tiling.size, n, n), args.tilePreview, common.pngWidth);
  }

  const PackAudit audit = auditPacking(packing, library, secondaryLibrary);
  times.wall = std::chrono::duration<double>(Clock::now() - start).count();
  if (!common.quiet)
    std::fprintf(stderr,
                 "pak pack: %zu elements, %d vertices, %d iterations (%s), art fill %.3f, skin fill %.3f, "
                 "%d overlapping pairs, %d outside, %d self-crossing outlines, pocket share P2 %.3f, %s\n",
                 packing.elements.size(), packing.vertexCount, packing.iterations, toString(packing.stopReason),
                 audit.artArea / audit.containerArea, packing.skinFill, audit.check.overlappingPairs,
                 audit.check.elementsOutside, audit.check.selfIntersecting, audit.evenness.pocketShare[1],
                 formatSeconds(times.wall).c_str());
  if (!common.report.empty())
    writeFileAtomically(common.report, packReport(args, scene, packing, audit, times, paths).dump(2) + "\n");
  outputs.commit();
  return 0;
}

void declarePackOptions(CLI::App& command, PackArguments& args) {
  command.add_option("--container,-c", args.container, "scene or container file (.svg or .path); required unless --tile");
  command.add_option("--elements,-e", args.elements, "element files and/or folders of .svg/.path files")->required();
  command.add_option("--secondary", args.secondary,
                     "secondary element files and/or folders: small elements packed into the pockets the primaries "
                     "leave, in a second pass with the primaries frozen (thesis 4.6)");
  command.add_option("--tile-preview", args.tilePreview,
                     "with --tile: also render an N x N repetition of the tile to this PNG");
  command.add_option("--tile-preview-repeat", args.tilePreviewRepeat, "N for --tile-preview")->capture_default_str();
  addCommonOptions(command, args.common,
                   {{CommonOption::Output, "output SVG"}, {CommonOption::Png}, {CommonOption::PngWidth},
                    {CommonOption::Config},
                    {CommonOption::Report, "write a JSON report: parameters, iterations, times, fill ratios, overlaps"},
                    {CommonOption::Snapshots}, {CommonOption::Every},
                    {CommonOption::DebugLayers, "add the skins and meshes as extra layers"}, {CommonOption::Quiet}});
  packOptions().addTo(command, args, &args.common.lengths);
  command.footer(kLengthHelp);
  command.add_option("--progress-every", args.progressEvery,
                     "progress line interval in iterations (0: 50 on a terminal, 1000 otherwise)");
}

const CommandRegistrar registrar{subcommand<PackArguments>(
    "pack",
    "Fill a container with deformable elements (RepulsionPak, thesis ch. 4).\n"
    "Elements are meshed, seeded small, then repel, grow and deform until the container is full.\n"
    "Example: pak pack --container heart.svg --elements animals/ -o out.svg --png out.png",
    declarePackOptions, runPack)};

}  // namespace
}  // namespace pak::cli
