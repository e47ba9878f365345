#include "py_flow.hpp"

#include <chrono>

#include <CLI/CLI.hpp>

#include "flow_arguments.hpp"
#include "flow_report.hpp"
#include "flow_resolve.hpp"
#include "outline_output.hpp"
#include "pak/error.hpp"
#include "pak/io/flow_drawing.hpp"
#include "pak/io/svg_writer.hpp"
#include "pak/sim/canonical_units.hpp"
#include "py_inputs.hpp"
#include "py_options.hpp"
#include "py_progress.hpp"

namespace pak::python {

using namespace pybind11::literals;

FlowResult flow(const py::object& container, const py::object& elements, const py::object& guides,
                const py::object& progress, const py::kwargs& options) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  // The keyword arguments are a --config object, read by `pak flow`'s own table and rules.
  cli::FlowArguments args;
  CLI::App command;
  cli::flowOptions().addTo(command, args, &args.common.lengths);
  const nlohmann::json config = optionsObject(options, "pak.flow");
  cli::resolveFlowOptions(args, command, &config, "pak.flow");

  if (container.is_none()) throw InputError("container", "is required");
  if (elements.is_none()) throw InputError("elements", "is required");
  const SceneInput input = sceneArgument(container, "container", guides);
  const Scene& scene = input.loaded.scene;
  cli::flowOptions().resolveLengths(args, args.common.lengths,
                                    cli::lengthScale(input.loaded.layout, canonicalFrameBox(scene, true)));
  const ElementsInput loaded = elementsArgument(elements);
  const Library library = libraryOf(loaded.elements);
  // What the report names as the inputs, as the CLI's does.
  args.scene = input.file;
  args.elements = loaded.paths;

  ProgressHook hook(progress);
  FlowCallbacks callbacks;
  callbacks.onProgress = [&](const FlowProgress& p) {
    hook([&] {
      return py::dict("phase"_a = p.phase, "iteration"_a = p.iteration, "iterations"_a = p.iterations,
                      "elements"_a = p.elements, "element_area"_a = p.elementArea);
    });
  };
  args.options.run.stopRequest = hook.stopRequest();

  FlowResult result;
  {
    py::gil_scoped_release release;
    result.packing = packFlow(scene, library, args.options, callbacks);
    // What `pak flow -o` writes, drawn and written as it does.
    result.drawing = flowDrawing(input.loaded.layout, result.packing, loaded.elements);
    SvgPathStats paths;
    result.svg = toSvgString(
        result.drawing, cli::outlineWriteOptions(args.polyline, cli::kFlowCurveTolerance, result.packing.canonicalScale),
        &paths);
    const PackingCheck check = cli::auditFlowPacking(result.packing, library);
    result.report =
        cli::flowReport(args, result.packing, check, paths, std::chrono::duration<double>(Clock::now() - start).count());
  }
  hook.rethrow();
  return result;
}

}  // namespace pak::python
