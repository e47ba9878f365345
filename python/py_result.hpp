#pragma once
// What pak.pack returns: the packing, its drawing as the CLI draws it, the SVG the CLI writes
// and the --report JSON.
#include <string>

#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

#include "pak/io/drawing.hpp"
#include "pak/sim/packing.hpp"

namespace pak::python {

namespace py = pybind11;

struct PackResult {
  Packing packing;
  Drawing drawing;
  std::string svg;
  nlohmann::json report;
};

// Registers pak.PackResult.
void bindPackResult(py::module_& m);
// Each region as a list of its rings (each polygon's outer ring, then its holes) as arrays.
py::list ringArrays(const Region& region);

}  // namespace pak::python
