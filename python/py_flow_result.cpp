#include "py_flow_result.hpp"

#include "py_arrays.hpp"
#include "py_lists.hpp"
#include "py_result.hpp"

namespace pak::python {

void bindFlowResult(py::module_& m) {
  py::class_<FlowResult>(m, "FlowResult", "A FLOWPAK packing: pak.flow's result.")
      .def_property_readonly(
          "outlines",
          [](const FlowResult& r) {
            return listOf(r.packing.elements, [](const FlowElement& e) { return ringArrays(e.outline); });
          },
          "each placed element's bent outline as a list of (N, 2) arrays: outer rings and holes")
      .def_property_readonly(
          "spines",
          [](const FlowResult& r) {
            return listOf(r.packing.elements, [](const FlowElement& e) { return arrayFromRing(e.streamline); });
          },
          "the streamline each element is bent along, an (N, 2) array")
      .def_property_readonly(
          "gap_outlines",
          [](const FlowResult& r) {
            return listOf(r.packing.gapElements, [](const FlowElement& e) { return ringArrays(e.outline); });
          },
          "with fill_gaps=True: the shapes made from the negative space, as outlines")
      .def_property_readonly(
          "colors",
          [](const FlowResult& r) {
            return listOf(r.packing.elements, [](const FlowElement& e) { return colorOf(e.art); });
          },
          "each placed element's colour, '#rrggbb' (its first fill, else stroke), or None")
      .def_property_readonly(
          "sources",
          [](const FlowResult& r) {
            return listOf(r.packing.elements, [](const FlowElement& e) { return py::str(e.source); });
          },
          "the file (or name) each placed element came from")
      .def_property_readonly(
          "report", [](const FlowResult& r) { return dictOf(r.report); },
          "the report `pak flow --report` writes, as a dict")
      .def("__len__", [](const FlowResult& r) { return r.packing.elements.size(); })
      .def("to_svg", [](const FlowResult& r) { return r.svg; }, "the SVG `pak flow -o` writes")
      .def("save", [](const FlowResult& r, const py::object& path) { saveText(path, r.svg); }, py::arg("path"),
           "writes to_svg() to `path`")
      .def("to_png", [](const FlowResult& r, int width) { return pngBytes(r.drawing, width); }, py::arg("width") = 1200,
           "the PNG `pak flow --png` writes, as bytes")
      .def("_repr_png_", [](const FlowResult& r) { return pngBytes(r.drawing, 800); })
      .def("__repr__", [](const FlowResult& r) {
        return "<pak.FlowResult: " + std::to_string(r.packing.elements.size()) + " elements, " +
               std::to_string(r.packing.iterations) + " refinement iterations, " + toString(r.packing.stopReason) + ">";
      });
}

}  // namespace pak::python
