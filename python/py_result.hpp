#pragma once
// What pak.pack returns: the packing, its drawing as the CLI draws it, the SVG the CLI writes
// and the --report JSON; and what every result shares (colours, PNG, saving).
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
// "#rrggbb" of what an element's art paints first (its first fill, else stroke); None if nothing.
py::object colorOf(const std::vector<Shape>& art);
// The PNG `--png` writes of `drawing`, `width` pixels wide, rendered without the GIL.
py::bytes pngBytes(const Drawing& drawing, int width);
// Writes `text` to the path (str or os.PathLike) atomically, as the CLI writes its outputs.
void saveText(const py::object& path, const std::string& text);

}  // namespace pak::python
