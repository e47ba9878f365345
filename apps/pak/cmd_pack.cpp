// `pak pack`: RepulsionPak from the command line.
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <set>
#include <nlohmann/json.hpp>
#include <thread>

#include "command.hpp"
#include "option_table.hpp"
#include "pak/error.hpp"
#include "pak/geom/closest_point.hpp"
#include "pak/geom/verify.hpp"
#include "pak/io/atomic_file.hpp"
#include "pak/io/packing_drawing.hpp"
#include "pak/io/png_renderer.hpp"
#include "pak/io/scene_loader.hpp"
#include "pak/io/svg_writer.hpp"
#include "pak/io/tile_drawing.hpp"
#include "pak/repulsion/repulsion.hpp"
#include "pak/repulsion/repulsion_presets.hpp"
#include "pak/repulsion/shape_matching.hpp"
#include "pak/repulsion/tiling.hpp"

namespace pak::cli {
namespace {

const NumberOption<RepulsionOptions> kNumberOptions[] = {
    {"gap", &RepulsionOptions::gap, "d_gap, the spacing between elements (canonical units: the container's bounding square is 1000 wide)"},
    {"mesh-spacing", &RepulsionOptions::meshSpacing, "distance between mesh samples, canonical units (0: max(gap, element size / 10))"},
    {"element-area", &RepulsionOptions::elementArea, "nominal area of one element as a fraction of the container; sets the count when --count is 0"},
    {"initial-coverage", &RepulsionOptions::initialCoverage, "fraction of the container the shrunken seeds cover at the start"},
    {"target-fill", &RepulsionOptions::targetFill, "stop when element skins cover this fraction of the container"},
    {"k-repulsion", &RepulsionOptions::repulsionStrength, "k_rpl, repulsion strength (eq. 4.2)"},
    {"k-overlap", &RepulsionOptions::overlapStrength, "k_ovr, overlap strength (eq. 4.4)"},
    {"k-boundary", &RepulsionOptions::boundaryStrength, "k_bdr, boundary strength (eq. 4.5)"},
    {"k-edge", &RepulsionOptions::edgeStrength, "k_edg for edge and shear springs (eq. 4.3): higher keeps shapes stiffer"},
    {"k-negative-space", &RepulsionOptions::negativeSpaceStrength, "k_edg for negative-space springs"},
    {"k-torsion", &RepulsionOptions::torsionStrength, "k_tor, pull toward the seeded orientation (eq. 4.6; 0: off)"},
    {"orientation-torsion", &RepulsionOptions::orientationTorsion, "k_tor used with --orientation upright/field when --k-torsion is 0"},
    {"soft", &RepulsionOptions::soft, "the soft parameter of eq. 4.2"},
    {"time-step", &RepulsionOptions::timeStep, "Δt of the explicit Euler step"},
    {"velocity-cap", &RepulsionOptions::velocityCap, "largest vertex speed (canonical units per unit time)"},
    {"damping", &RepulsionOptions::damping, "fraction of each vertex's velocity lost per step (0: none)"},
    {"growth-rate", &RepulsionOptions::growthRate, "k_g: growth factor increase per unit time while an element has room"},
    {"cell-size", &RepulsionOptions::cellSize, "neighbour grid cell and repulsion reach, canonical units (0: 2 × mesh spacing)"},
    {"outside-tolerance", &RepulsionOptions::outsideTolerance, "a mesh pushed further than this outside the container stops growing (canonical units; 1e9: never, as in the thesis)"},
    {"docking-strength", &RepulsionOptions::dockingStrength, "with --shape-matching: spring strength holding each matched element's tip on its corner"},
    {"stall-epsilon", &RepulsionOptions::stallEpsilon, "ε of eq. 4.7: stop when the RMS fill change per iteration falls below it"},
    {"secondary-scale", &RepulsionOptions::secondaryScale, "nominal size of a secondary element relative to a primary one (linear)"},
    {"secondary-min-distance", &RepulsionOptions::secondaryMinDistance, "d_min: secondaries go only where the negative space is at least this far from any element or wall (canonical units; 0: max(gap, L / 4), L the nominal secondary size)"},
    {"secondary-separation", &RepulsionOptions::secondarySeparation, "d_sep: secondary seeds keep at least this far apart (canonical units; 0: L, the nominal secondary size)"},
    {"secondary-target-fill", &RepulsionOptions::secondaryTargetFill, "the secondary pass stops when skins (and fixed elements) cover this fraction of the container"},
};
const IntegerOption<RepulsionOptions> kIntegerOptions[] = {
    {"count", &RepulsionOptions::count, "number of elements to seed (0: container area / element area)"},
    {"max-iterations", &RepulsionOptions::maxIterations, "hard cap on simulation iterations"},
    {"stall-window", &RepulsionOptions::stallWindow, "w of eq. 4.7, in iterations"},
    {"threads", &RepulsionOptions::threads, "worker threads (0: all cores); the result does not depend on it"},
    {"secondary-resolution", &RepulsionOptions::secondaryResolution, "distance transform cells across the container for seeding secondaries"},
};
const OptionTable<RepulsionOptions> kOptions{kNumberOptions, kIntegerOptions};

struct PackArguments {
  std::string container;
  std::vector<std::string> elements, secondary;
  std::string preset;
  bool rigid = false;
  std::string output, png, config, report, snapshots;
  std::string tile, tilePreview;  // --tile W,H; --tile-preview FILE.png
  int tilePreviewRepeat = 3;
  int pngWidth = 1200;
  int every = 500;
  int progressEvery = 0;
  bool quiet = false, debugLayers = false;
  std::uint64_t seed = 1;
  std::string orientation = "random", orientationField = "x:0:180", containerLayer = "container";
  RepulsionOptions options;
  std::set<std::string> configKeys;  // the options the --config file set
  CLI::App* command = nullptr;
};

void applyConfig(PackArguments& args) {
  args.configKeys = applyConfigFile(args.config, *args.command, kOptions, args.options,
                                    {seedKey("seed", args.seed),
                                     booleanKey("stall-on-measured-area", args.options.stallOnMeasuredArea),
                                     booleanKey("shape-matching", args.options.shapeMatching),
                                     booleanKey("rigid", args.rigid), stringKey("orientation", args.orientation),
                                     stringKey("orientation-field", args.orientationField),
                                     stringKey("container-layer", args.containerLayer), stringKey("tile", args.tile),
                                     stringKey("preset", args.preset)});
}

// "W,H" (input units) for --tile.
Vec2 parseTileSize(const std::string& text) {
  double w = 0.0, h = 0.0;
  char extra = 0;
  if (std::sscanf(text.c_str(), " %lf , %lf %c", &w, &h, &extra) != 2 || !(w > 0.0 && h > 0.0) || !std::isfinite(w) ||
      !std::isfinite(h))
    throw InputError("", "--tile expects W,H with two positive numbers, got \"" + text + "\"");
  return {w, h};
}

std::string formatSeconds(double s) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1f s", s);
  return buffer;
}

int runPack(PackArguments& args) {
  using Clock = std::chrono::steady_clock;
  auto start = Clock::now();
  // The config file may name the preset, so it is read first; the preset then sets the
  // strengths that neither the file nor a command-line flag gives.
  if (!args.config.empty()) applyConfig(args);
  if (args.rigid && !args.preset.empty() && args.preset != "rigid")
    throw InputError("", "--rigid conflicts with --preset " + args.preset);
  if (args.rigid) args.preset = "rigid";
  if (!args.preset.empty()) {
    RepulsionOptions preset = args.options;
    applyRepulsionPreset(args.preset, preset);
    kOptions.copyUnless(args.options, preset, [&](const char* name) {
      return args.command->count(std::string("--") + name) > 0 || args.configKeys.count(name) > 0;
    });
  }
  args.options.seed = args.seed;
  // A field given alone asks for the field.
  if (args.command->count("--orientation-field") > 0 && args.command->count("--orientation") == 0 &&
      args.orientation == "random")
    args.orientation = "field";
  args.options.orientation = parseOrientationMode(args.orientation);
  args.options.orientationField = parseOrientationField(args.orientationField);

  if (!args.tile.empty()) args.options.tile = parseTileSize(args.tile);
  const bool tiled = isTiled(args.options.tile);
  if (tiled && !args.container.empty()) throw InputError(args.container, "--tile packs its own rectangle; give no --container");
  if (!tiled && args.container.empty()) throw InputError("", "--container is required (or --tile W,H)");
  if (!args.tilePreview.empty() && !tiled) throw InputError(args.tilePreview, "--tile-preview needs --tile W,H");
  if (args.tilePreviewRepeat < 1 || args.tilePreviewRepeat > 16) throw InputError("", "--tile-preview-repeat must be 1 to 16");
  SceneOptions sceneOptions;
  sceneOptions.containerLayer = args.containerLayer;
  const LoadedScene input = tiled ? LoadedScene{tileScene(args.options.tile), tileLayout(args.options.tile), {}}
                                  : loadScene(args.container, sceneOptions);
  const Scene& scene = input.scene;
  Library library = loadLibrary(args.elements);
  Library secondaryLibrary = args.secondary.empty() ? Library{} : loadLibrary(args.secondary);
  for (const Warning& w : input.warnings)
    if (!args.quiet) std::fprintf(stderr, "pak: warning: %s: %s\n", w.where.c_str(), w.message.c_str());

  const bool tty = isatty(STDERR_FILENO);
  RepulsionCallbacks callbacks;
  if (!args.quiet) {
    callbacks.progressEvery = args.progressEvery > 0 ? args.progressEvery : (tty ? 50 : 1000);
    callbacks.onProgress = [&](const RepulsionProgress& p) {
      double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
      std::fprintf(stderr, "%spak pack: iteration %6d  fill %.3f  growing %3d/%d (blocked: %d by neighbours, %d by the wall)  %s%s",
                   tty ? "\r" : "", p.iteration, p.fill, p.growing, p.elements, p.touchingNeighbours, p.againstWall,
                   formatSeconds(elapsed).c_str(), tty ? "   " : "\n");
      std::fflush(stderr);
    };
  }
  if (!args.snapshots.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(args.snapshots, ec);
    if (ec) throw InputError(args.snapshots, "cannot create snapshot folder: " + ec.message());
    callbacks.snapshotEvery = std::max(1, args.every);
    callbacks.onSnapshot = [&](const Packing& p) {
      char name[64];
      std::snprintf(name, sizeof name, "snapshot-%06d.svg", p.iterations);
      writeSvgFile(packingDrawing(input.layout, p), (std::filesystem::path(args.snapshots) / name).string());
    };
  }

  auto simulationStart = Clock::now();
  Packing packing = packRepulsion(scene, library, secondaryLibrary, args.options, callbacks);
  double simulationSeconds = std::chrono::duration<double>(Clock::now() - simulationStart).count();
  if (!args.quiet && tty) std::fprintf(stderr, "\n");

  PackingDrawingOptions drawingOptions;
  drawingOptions.debugLayers = args.debugLayers;
  Drawing drawing = packingDrawing(input.layout, packing, drawingOptions);
  writeSvgFile(drawing, args.output);
  if (!args.png.empty()) {
    PngOptions png;
    png.width = args.pngWidth;
    writePngFile(drawing, args.png, png);
  }
  if (!args.tilePreview.empty()) {
    PngOptions png;
    png.width = args.pngWidth;
    int n = args.tilePreviewRepeat;
    writePngFile(tileRepetition(drawing, args.options.tile, n, n), args.tilePreview, png);
  }

  // Invariants of the result, on the art as drawn.
  std::vector<Region> outlines = artOutlines(packing);
  // A tile is checked on the torus: every clone's piece inside the tile, seams included.
  if (tiled) outlines = periodicRepetition(outlines, packing.tile, 1, 1);
  double containerArea = area(packing.container);
  PackingCheckOptions checkOptions;
  checkOptions.areaTolerance = 1e-6 * containerArea;
  // Fixed elements count as one more (immovable) element: overlapping them is an overlap.
  std::vector<Region> checked = outlines;
  if (!packing.fixedArt.empty()) checked.push_back(packing.fixedArt);
  PackingCheck check = verifyPacking(checked, packing.container, checkOptions);
  double artArea = area(packing.fixedArt);
  for (const Region& r : outlines) artArea += area(r);
  double maxEdgeStrain = 0.0, meanEdgeStrain = 0.0;
  int secondaryCount = 0;
  for (const PlacedElement& e : packing.elements) {
    maxEdgeStrain = std::max(maxEdgeStrain, e.maxEdgeStrain);
    meanEdgeStrain += e.meanEdgeStrain / static_cast<double>(packing.elements.size());
    secondaryCount += e.secondary ? 1 : 0;
  }
  double wall = std::chrono::duration<double>(Clock::now() - start).count();

  if (!args.quiet)
    std::fprintf(stderr,
                 "pak pack: %zu elements, %d vertices, %d iterations (%s), art fill %.3f, skin fill %.3f, "
                 "%d overlapping pairs, %d outside, %s\n",
                 packing.elements.size(), packing.vertexCount, packing.iterations, toString(packing.stopReason),
                 artArea / containerArea, packing.skinFill, check.overlappingPairs, check.elementsOutside,
                 formatSeconds(wall).c_str());

  if (!args.report.empty()) {
    nlohmann::json report;
    nlohmann::json parameters;
    kOptions.report(parameters, args.options);
    parameters["seed"] = args.seed;
    parameters["stall-on-measured-area"] = args.options.stallOnMeasuredArea;
    parameters["orientation"] = toString(args.options.orientation);
    parameters["orientation-field"] = args.orientationField;
    parameters["container-layer"] = args.containerLayer;
    parameters["shape-matching"] = args.options.shapeMatching;
    parameters["threads-used"] = args.options.threads > 0 ? args.options.threads
                                                          : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    report["parameters"] = parameters;
    report["units"] = "distances in canonical units: the container's bounding square is 1000 wide";
    report["container"] = args.container;
    if (tiled) report["tile"] = {args.options.tile.x, args.options.tile.y};
    report["elements-library"] = args.elements;
    report["seed"] = args.seed;
    report["iterations"] = packing.iterations;
    report["stop-reason"] = toString(packing.stopReason);
    report["wall-seconds"] = wall;
    report["simulation-seconds"] = simulationSeconds;
    report["fill-ratio-art"] = artArea / containerArea;
    report["fill-ratio-skin"] = packing.skinFill;
    report["fill-ratios-include"] = packing.fixedArt.empty()
                                        ? "elements (art or skins) over the container area"
                                        : "elements (art or skins) and fixed elements (art, or art offset by gap/2 for skin) over the container area";
    report["preset"] = args.preset.empty() ? "default" : args.preset;
    report["secondary-library"] = args.secondary;
    report["secondary-count"] = secondaryCount;
    report["fixed-count"] = scene.fixed.size();
    report["fixed-area-ratio"] = area(packing.fixedArt) / containerArea;
    report["max-edge-strain"] = maxEdgeStrain;    // over all edge springs: |length / (g × rest) − 1|
    report["mean-edge-strain"] = meanEdgeStrain;  // mean over elements of their mean
    nlohmann::json passes = nlohmann::json::array();
    for (std::size_t k = 0; k < packing.passes.size(); ++k) {
      const PackingPass& pass = packing.passes[k];
      passes.push_back({{"pass", k == 0 ? "primary" : "secondary"},
                        {"elements", pass.elements},
                        {"iterations", pass.iterations},
                        {"stop-reason", toString(pass.stopReason)},
                        {"seconds", pass.seconds},
                        {"fill-ratio-skin", pass.skinFill},
                        {"fill-ratio-art", pass.artFill}});
    }
    report["passes"] = passes;
    report["element-count"] = packing.elements.size();
    report["vertex-count"] = packing.vertexCount;
    report["spring-count"] = packing.springCount;
    report["overlap-count"] = check.overlappingPairs;
    report["overlap-area"] = check.overlapArea;
    report["elements-outside"] = check.elementsOutside;
    report["outside-area"] = check.outsideArea;
    report["problems"] = check.problems;
    report["canonical-scale"] = packing.canonicalScale;
    std::vector<int> perContainer(packing.containers.size(), 0);
    for (const PlacedElement& e : packing.elements)
      if (e.container >= 0 && e.container < static_cast<int>(perContainer.size())) ++perContainer[e.container];
    report["elements-per-container"] = perContainer;
    // Thesis 4.7's salient convex corners and how close the art comes to each (canonical
    // units), with or without shape matching, so runs can be compared.
    nlohmann::json corners = nlohmann::json::array();
    double cornerSum = 0.0;
    for (const SalientCorner& c : salientContainerCorners(packing.container)) {
      double nearest = std::numeric_limits<double>::infinity();
      for (const Region& r : outlines) nearest = std::min(nearest, closestPointOnBoundary(c.position, r).distance);
      nearest *= packing.canonicalScale;
      cornerSum += nearest;
      corners.push_back({{"x", c.position.x}, {"y", c.position.y}, {"art-distance", nearest}});
    }
    report["salient-corners"] = corners;
    report["corner-art-distance-mean"] = corners.empty() ? 0.0 : cornerSum / static_cast<double>(corners.size());
    if (args.options.shapeMatching) {
      report["shape-matching"] = {{"corners", packing.salientCorners.size()},
                                  {"docked-elements", packing.dockedElements},
                                  {"matching-seconds", packing.shapeMatchingSeconds}};
    }
    writeFileAtomically(args.report, report.dump(2) + "\n");
  }
  return 0;
}

const CommandRegistrar registrar{{"pack", [](CLI::App& app) {
  auto args = std::make_shared<PackArguments>();
  CLI::App* cmd = app.add_subcommand(
      "pack",
      "Fill a container with deformable elements (RepulsionPak, thesis ch. 4).\n"
      "Elements are meshed, seeded small, then repel, grow and deform until the container is full.\n"
      "Example: pak pack --container heart.svg --elements animals/ -o out.svg --png out.png");
  args->command = cmd;
  cmd->add_option("--container,-c", args->container, "scene or container file (.svg or .path); required unless --tile");
  cmd->add_option("--tile", args->tile,
                  "pack a tileable W,H rectangle (input units) instead of a container: elements crossing an edge "
                  "come back on the opposite one (thesis 4.8)");
  cmd->add_option("--tile-preview", args->tilePreview, "with --tile: also render an N x N repetition of the tile to this PNG");
  cmd->add_option("--tile-preview-repeat", args->tilePreviewRepeat, "N for --tile-preview")->capture_default_str();
  cmd->add_option("--elements,-e", args->elements, "element files and/or folders of .svg/.path files")->required();
  cmd->add_option("--secondary", args->secondary,
                  "secondary element files and/or folders: small elements packed into the pockets the primaries "
                  "leave, in a second pass with the primaries frozen (thesis 4.6)");
  std::string presetHelp = "force strength preset, applied before --config and flags:";
  for (const RepulsionPreset& p : repulsionPresets()) presetHelp += "\n  " + p.name + ": " + p.description;
  cmd->add_option("--preset", args->preset, presetHelp);
  cmd->add_flag("--rigid", args->rigid, "nearly rigid elements (very stiff edge springs, thesis 6.4): same as --preset rigid");
  cmd->add_option("-o,--output", args->output, "output SVG")->required();
  cmd->add_option("--png", args->png, "also render a PNG preview to this file");
  cmd->add_option("--png-width", args->pngWidth, "PNG width in pixels")->capture_default_str();
  cmd->add_option("--seed", args->seed, "random seed; the same seed gives the same packing")->capture_default_str();
  kOptions.addTo(*cmd, args->options);
  cmd->add_option("--config", args->config, "JSON file of option names to values (command-line flags win)");
  cmd->add_option("--report", args->report, "write a JSON report: parameters, iterations, times, fill ratios, overlaps");
  cmd->add_option("--snapshots", args->snapshots, "write intermediate SVGs into this folder");
  cmd->add_option("--every", args->every, "snapshot interval in iterations")->capture_default_str();
  cmd->add_option("--orientation", args->orientation,
                  "preferred orientation (eq. 4.6): random (random seeded angles, no torsion unless --k-torsion), "
                  "upright (seeded as drawn and held there), field (seeded at and held to --orientation-field)")
      ->capture_default_str();
  cmd->add_option("--orientation-field", args->orientationField,
                  "AXIS:FROM:TO, the rest angle in degrees (clockwise on screen, as SVG rotate) turning linearly "
                  "from the container's left (x) or top (y) edge to the opposite one; alone it implies --orientation field")
      ->capture_default_str();
  cmd->add_option("--container-layer", args->containerLayer,
                  "the scene layer holding the containers; 'elements' makes each element of a previous Pak "
                  "packing a container")
      ->capture_default_str();
  cmd->add_flag("--stall-on-measured-area", args->options.stallOnMeasuredArea,
                "apply eq. 4.7 to the measured skin area, as the thesis does, instead of the meshes' rest area");
  cmd->add_flag("--shape-matching", args->options.shapeMatching,
                "place elements that fit the container's sharp convex corners there first and dock them (thesis 4.7)");
  cmd->add_flag("--debug-layers", args->debugLayers, "add the skins and meshes as extra layers");
  cmd->add_flag("--quiet,-q", args->quiet, "no progress output");
  cmd->add_option("--progress-every", args->progressEvery,
                  "progress line interval in iterations (0: 50 on a terminal, 1000 otherwise)");
  return [args] { return runPack(*args); };
}}};

}  // namespace
}  // namespace pak::cli
