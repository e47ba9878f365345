#include "py_metrics.hpp"

#include <CLI/CLI.hpp>
#include <pybind11/numpy.h>

#include "metrics_measure.hpp"
#include "metrics_resolve.hpp"
#include "pak/error.hpp"
#include "pak/io/packing_reader.hpp"
#include "py_flow_result.hpp"
#include "py_lists.hpp"
#include "py_options.hpp"
#include "py_result.hpp"

namespace pak::python {
namespace {

bool isPath(const py::handle& object) { return py::isinstance<py::str>(object) || py::hasattr(object, "__fspath__"); }
bool isResult(const py::handle& object) {
  return py::isinstance<PackResult>(object) || py::isinstance<FlowResult>(object);
}

// A packing to read: a file, or a result's SVG (read from memory, as the file it would write).
struct Source {
  std::string file, svg, name;
};

Source sourceOf(const py::handle& packing) {
  if (isPath(packing)) return {py::cast<std::string>(py::module_::import("os").attr("fspath")(packing)), "", ""};
  if (py::isinstance<PackResult>(packing)) return {"", py::cast<const PackResult&>(packing).svg, "pak.pack result"};
  if (py::isinstance<FlowResult>(packing)) return {"", py::cast<const FlowResult&>(packing).svg, "pak.flow result"};
  throw InputError("pak.metrics", "expects a packing: a path, a pak.pack or pak.flow result, or a list of them");
}

// A pak.pack result's report gives d_gap; FLOWPAK's gap is the streamlines' spacing, not
// d_gap, so a flow result's is estimated.
const nlohmann::json* reportOf(const py::handle& packing) {
  if (py::isinstance<PackResult>(packing)) return &py::cast<const PackResult&>(packing).report;
  return nullptr;
}

// JSON as Python, with every array of numbers a float64 numpy array.
py::object toPython(const nlohmann::json& value) {
  if (value.is_array()) {
    bool numbers = !value.empty();
    for (const nlohmann::json& item : value) numbers = numbers && item.is_number();
    if (numbers) {
      py::array_t<double> array(static_cast<py::ssize_t>(value.size()));
      auto a = array.mutable_unchecked<1>();
      for (std::size_t i = 0; i < value.size(); ++i) a(i) = value[i].get<double>();
      return array;
    }
    py::list list;
    for (const nlohmann::json& item : value) list.append(toPython(item));
    return list;
  }
  if (value.is_object()) {
    py::dict dict;
    for (const auto& item : value.items()) dict[py::str(item.key())] = toPython(item.value());
    return dict;
  }
  if (value.is_boolean()) return py::bool_(value.get<bool>());
  if (value.is_number_integer()) return py::int_(value.get<std::int64_t>());
  if (value.is_number()) return py::float_(value.get<double>());
  if (value.is_string()) return py::str(value.get<std::string>());
  return py::none();
}

}  // namespace

py::object metrics(const py::object& packings, const py::object& report, const py::kwargs& options) {
  cli::MetricsArguments args;
  CLI::App command;
  cli::metricsOptions().addTo(command, args);
  const nlohmann::json config = optionsObject(options, "pak.metrics");

  const bool many = !isPath(packings) && !isResult(packings) && py::isinstance<py::sequence>(packings);
  std::vector<Source> sources;
  if (many)
    for (const py::handle p : packings) sources.push_back(sourceOf(p));
  else
    sources.push_back(sourceOf(packings));
  if (sources.empty()) throw InputError("pak.metrics", "no packing given");

  // A gap given wins over the report's: --report's (a dict or a file), else the (first)
  // result's own.
  if (!cli::resolveMetricsOptions(args, command, &config, "pak.metrics")) {
    if (isPath(report)) {
      const std::string file = py::cast<std::string>(py::module_::import("os").attr("fspath")(report));
      args.metrics.gap = cli::gapFromReport(cli::readReportFile(file), file);
    } else if (!report.is_none()) {
      const std::string text = py::cast<std::string>(py::module_::import("json").attr("dumps")(report));
      args.metrics.gap = cli::gapFromReport(nlohmann::json::parse(text), "report");
    } else if (const nlohmann::json* own = reportOf(many ? py::object(packings[py::int_(0)]) : packings)) {
      args.metrics.gap = cli::gapFromReport(*own, "the result's report");
    }
  }

  std::vector<nlohmann::json> measured;
  {
    py::gil_scoped_release release;
    std::vector<PackingGeometry> geometries;
    for (const Source& s : sources)
      geometries.push_back(s.file.empty() ? packingFromDocument(readSvgString(s.svg, s.name), args.layers)
                                          : readPacking(s.file, args.layers));
    for (const cli::MeasuredPacking& m : cli::measurePackings(geometries, args)) measured.push_back(cli::packingJson(m));
  }
  if (!many) return toPython(measured.front());
  return listOf(measured, [](const nlohmann::json& m) { return toPython(m); });
}

}  // namespace pak::python
