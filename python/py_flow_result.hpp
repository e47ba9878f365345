#pragma once
// What pak.flow returns: the FLOWPAK packing, its drawing as `pak flow` draws it, the SVG it
// writes and the --report JSON.
#include <string>

#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

#include "pak/flow/flow.hpp"
#include "pak/io/drawing.hpp"

namespace pak::python {

namespace py = pybind11;

struct FlowResult {
  FlowPacking packing;
  Drawing drawing;
  std::string svg;
  nlohmann::json report;
};

// Registers pak.FlowResult.
void bindFlowResult(py::module_& m);

}  // namespace pak::python
