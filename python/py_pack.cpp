#include "py_pack.hpp"

#include <algorithm>
#include <chrono>

#include <CLI/CLI.hpp>

#include "outline_output.hpp"
#include "pack_arguments.hpp"
#include "pack_report.hpp"
#include "pack_resolve.hpp"
#include "pak/error.hpp"
#include "pak/io/packing_drawing.hpp"
#include "pak/io/svg_writer.hpp"
#include "pak/io/tile_drawing.hpp"
#include "pak/repulsion/tiling.hpp"
#include "pak/sim/canonical_units.hpp"
#include "py_inputs.hpp"
#include "py_options.hpp"
#include "py_progress.hpp"

namespace pak::python {

using namespace pybind11::literals;

PackResult pack(const py::object& container, const py::object& elements, const py::object& secondary,
                const py::object& progress, int progressEvery, const py::kwargs& options) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  // The keyword arguments are a --config object, read by `pak pack`'s own table and rules; an
  // empty command line gives none of them.
  cli::PackArguments args;
  CLI::App command;
  cli::packOptions().addTo(command, args, &args.common.lengths);
  const nlohmann::json config = optionsObject(options, "pak.pack");
  cli::resolvePackOptions(args, command, &config, "pak.pack");

  const bool tiled = isTiled(args.options.tiling.size);
  if (tiled && !container.is_none()) throw InputError("tile", "packs its own rectangle; give no container");
  if (!tiled && container.is_none()) throw InputError("container", "is required (or tile=\"W,H\")");
  if (elements.is_none()) throw InputError("elements", "is required");
  const Vec2 tile = args.options.tiling.size;
  const SceneInput input =
      tiled ? SceneInput{LoadedScene{tileScene(tile), tileLayout(tile), {}}, ""} : sceneArgument(container, args.containerLayer);
  const Scene& scene = input.loaded.scene;
  cli::packOptions().resolveLengths(args, args.common.lengths,
                                    cli::lengthScale(input.loaded.layout, canonicalFrameBox(scene, false)));
  const ElementsInput primaries = elementsArgument(elements);
  const ElementsInput secondaries = secondary.is_none() ? ElementsInput{} : elementsArgument(secondary);
  const Library library = libraryOf(primaries.elements), secondaryLibrary = libraryOf(secondaries.elements);
  // What the report names as the inputs, as the CLI's does.
  args.container = input.file;
  args.elements = primaries.paths;
  args.secondary = secondaries.paths;

  ProgressHook hook(progress);
  RepulsionCallbacks callbacks;
  callbacks.progressEvery = std::max(1, progressEvery);
  callbacks.onProgress = [&](const RepulsionProgress& p) {
    hook([&] {
      return py::dict("iteration"_a = p.iteration, "fill"_a = p.fill, "growing"_a = p.growing,
                      "elements"_a = p.elements, "touching_neighbours"_a = p.touchingNeighbours,
                      "against_wall"_a = p.againstWall);
    });
  };
  args.options.run.stopRequest = hook.stopRequest();

  PackResult result;
  {
    py::gil_scoped_release release;
    const auto simulationStart = Clock::now();
    result.packing = packRepulsion(scene, library, secondaryLibrary, args.options, callbacks);
    cli::PackTimes times;
    times.simulation = std::chrono::duration<double>(Clock::now() - simulationStart).count();
    // What `pak pack -o` writes, drawn and written as it does.
    result.drawing = packingDrawing(input.loaded.layout, result.packing, {});
    SvgPathStats paths;
    result.svg = toSvgString(result.drawing,
                             cli::outlineWriteOptions(args.polyline, cli::kMeshCurveTolerance, result.packing.canonicalScale),
                             &paths);
    const cli::PackAudit audit = cli::auditPacking(result.packing, library, secondaryLibrary);
    times.wall = std::chrono::duration<double>(Clock::now() - start).count();
    result.report = cli::packReport(args, scene, result.packing, audit, times, paths);
  }
  hook.rethrow();
  return result;
}

}  // namespace pak::python
