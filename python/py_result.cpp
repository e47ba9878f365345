#include "py_result.hpp"

#include <cstdio>
#include <fstream>

#include "pak/error.hpp"
#include "pak/io/atomic_file.hpp"
#include "pak/io/png_renderer.hpp"
#include "py_arrays.hpp"
#include "py_lists.hpp"

namespace pak::python {
namespace {

py::bytes png(const PackResult& result, int width) { return pngBytes(result.drawing, width); }

}  // namespace

py::object colorOf(const std::vector<Shape>& art) {
  for (const Shape& shape : art)
    if (const std::optional<Color>& c = shape.fill ? shape.fill : shape.stroke) {
      char text[8];
      std::snprintf(text, sizeof text, "#%02x%02x%02x", c->r, c->g, c->b);
      return py::str(text);
    }
  return py::none();
}

py::bytes pngBytes(const Drawing& drawing, int width) {
  PngOptions options;
  options.width = width;
  std::string bytes;
  {
    py::gil_scoped_release release;
    bytes = renderPng(drawing, options, "to_png");
  }
  return py::bytes(bytes);
}

void saveText(const py::object& path, const std::string& text) {
  writeFileAtomically(py::cast<std::string>(py::module_::import("os").attr("fspath")(path)), text);
}

py::list ringArrays(const Region& region) {
  py::list rings;
  for (const Polygon& polygon : region) {
    rings.append(arrayFromRing(polygon.outer));
    for (const Ring& hole : polygon.holes) rings.append(arrayFromRing(hole));
  }
  return rings;
}

void bindPackResult(py::module_& m) {
  py::class_<PackResult>(m, "PackResult", "A packing: pak.pack's result.")
      .def_property_readonly(
          "outlines",
          [](const PackResult& r) {
            return listOf(artOutlines(r.packing), [](const Region& outline) { return ringArrays(outline); });
          },
          "each placed element's outline (what its art paints) as a list of (N, 2) arrays: outer rings and holes")
      .def_property_readonly(
          "skins",
          [](const PackResult& r) {
            return listOf(r.packing.elements, [](const PlacedElement& e) { return arrayFromRing(e.skin); });
          },
          "each placed element's deformed skin, an (N, 2) array")
      .def_property_readonly(
          "colors",
          [](const PackResult& r) {
            return listOf(r.packing.elements, [](const PlacedElement& e) { return colorOf(e.art); });
          },
          "each placed element's colour, '#rrggbb' (its first fill, else stroke), or None")
      .def_property_readonly(
          "sources",
          [](const PackResult& r) {
            return listOf(r.packing.elements, [](const PlacedElement& e) { return py::str(e.source); });
          },
          "the file (or name) each placed element came from")
      .def_property_readonly(
          "report",
          [](const PackResult& r) { return dictOf(r.report); },
          "the report `pak pack --report` writes, as a dict")
      .def("__len__", [](const PackResult& r) { return r.packing.elements.size(); })
      .def("to_svg", [](const PackResult& r) { return r.svg; }, "the SVG `pak pack -o` writes")
      .def(
          "save",
          [](const PackResult& r, const py::object& path) { saveText(path, r.svg); },
          py::arg("path"), "writes to_svg() to `path`")
      .def("to_png", &png, py::arg("width") = 1200, "the PNG `pak pack --png` writes, as bytes")
      .def("_repr_png_", [](const PackResult& r) { return png(r, 800); })
      .def("__repr__", [](const PackResult& r) {
        return "<pak.PackResult: " + std::to_string(r.packing.elements.size()) + " elements, " +
               std::to_string(r.packing.iterations) + " iterations, " + toString(r.packing.stopReason) + ">";
      });
}

}  // namespace pak::python
