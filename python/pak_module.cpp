// The `pak` Python module: the library's packers on scenes and elements read from files or
// made from numpy arrays (docs/python.md).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "pak/error.hpp"
#include "py_animate.hpp"
#include "py_flow.hpp"
#include "py_inputs.hpp"
#include "py_metrics.hpp"
#include "py_pack.hpp"
#include "py_result.hpp"

namespace py = pybind11;
using namespace pak::python;

namespace {

// A path or a list of them.
std::vector<std::string> pathList(const py::object& paths) {
  const py::module_ os = py::module_::import("os");
  if (py::isinstance<py::str>(paths) || py::hasattr(paths, "__fspath__"))
    return {py::cast<std::string>(os.attr("fspath")(paths))};
  std::vector<std::string> list;
  for (const py::handle p : paths) list.push_back(py::cast<std::string>(os.attr("fspath")(p)));
  return list;
}

}  // namespace

PYBIND11_MODULE(pak, m) {
  m.doc() = "Pak: packs deformable elements into containers (RepulsionPak; docs/python.md).";
  m.attr("__version__") = PAK_VERSION;
  // What the CLI prints after "pak: error: ", as the exception's message.
  py::register_exception<pak::InputError>(m, "InputError", PyExc_ValueError);
  // What the readers skipped in an input (the CLI's "pak: warning: …" lines).
  m.attr("InputWarning") = py::reinterpret_steal<py::object>(PyErr_NewExceptionWithDoc(
      "pak.InputWarning", "Something an input file holds that Pak skipped or reinterpreted, and why.", PyExc_UserWarning, nullptr));

  py::class_<SceneInput>(m, "Scene", "A container (and the scene around it), as `pak pack --container` reads it.")
      .def_property_readonly("file", [](const SceneInput& s) { return s.file; })
      .def_property_readonly("container", [](const SceneInput& s) { return ringArrays(s.loaded.scene.container); },
                             "the container's rings (outer rings and holes) as (N, 2) arrays")
      .def("__repr__", [](const SceneInput& s) {
        return "<pak.Scene " + (s.file.empty() ? std::string("from rings") : s.file) + ">";
      });
  py::class_<ElementsInput>(m, "Elements", "Elements, as `pak pack --elements` reads them.")
      .def("__len__", [](const ElementsInput& e) { return e.elements.size(); })
      .def_property_readonly("sources",
                             [](const ElementsInput& e) {
                               std::vector<std::string> sources;
                               for (const auto& l : e.elements) sources.push_back(l.element.source);
                               return sources;
                             })
      .def("__repr__", [](const ElementsInput& e) { return "<pak.Elements: " + std::to_string(e.elements.size()) + ">"; });
  bindPackResult(m);
  bindFlowResult(m);
  bindAnimationResult(m);

  m.def(
      "read_scene",
      [](const py::object& path, const std::string& containerLayer) {
        return readScene(pathList(path).at(0), containerLayer);
      },
      py::arg("path"), py::arg("container_layer") = "container",
        "Reads a scene (.svg or .path), as `pak pack --container PATH` does.");
  m.def(
      "read_elements", [](const py::object& paths) { return readElements(pathList(paths)); }, py::arg("paths"),
      "Reads element files and folders, as `pak pack --elements PATHS...` does.");
  m.def(
      "scene", [](const py::object& rings, const py::object& guides) { return sceneFromRings(rings, guides); },
      py::arg("rings"), py::arg("guides") = py::none(),
      "A container from an (N, 2) array or a list of them (holes by the even-odd rule) or a shapely (Multi)Polygon, "
      "SVG coordinates (y down); guides (lines: (N, 2) arrays or shapely LineStrings) make it a pak.flow scene.");
  m.def(
      "elements",
      [](const py::object& items, const std::vector<std::string>& colors) { return elementsFromRings(items, colors); },
      py::arg("items"), py::arg("colors") = std::vector<std::string>{},
      "Elements, one per item: an (N, 2) array, a list of rings (even-odd) or a shapely (Multi)Polygon, each filled "
      "with colors[i].");
  m.def("pack", &pack, py::arg("container") = py::none(), py::arg("elements") = py::none(), py::kw_only(),
        py::arg("secondary") = py::none(), py::arg("progress") = py::none(), py::arg("progress_every") = 50,
        R"(Packs `elements` into `container` (RepulsionPak), as `pak pack` does.

container: a path, a pak.Scene, rings (an (N, 2) array or a list of them) or a shapely
(Multi)Polygon; None with tile="W,H".
elements: a path or list of paths (files, folders), a pak.Elements, or a list of elements as rings
or shapely geometries.
options: `pak pack`'s options by the same names, '-' written '_' (seed=3, max_iterations=500,
threads=2, gap="2mm", preset="rigid"), read as a --config file is.
progress: called with a dict (iteration, fill, growing, ...) every progress_every iterations;
an exception it raises stops the run and propagates.
Raises pak.InputError with the message `pak pack` prints.)");
  m.def("flow", &flow, py::arg("container") = py::none(), py::arg("elements") = py::none(), py::kw_only(),
        py::arg("guides") = py::none(), py::arg("progress") = py::none(),
        R"(Fills `container` with `elements` bent along a flow (FLOWPAK), as `pak flow` does.

container: a scene path (layers container and guides), a pak.Scene, or rings / a shapely
geometry with guides= (lines: (N, 2) arrays or shapely LineStrings).
elements: paths, a pak.Elements, or a list of elements as rings or shapely geometries.
options: `pak flow`'s options by the same names, '-' written '_' (seed=3, iterations=5, count=40,
gap="4mm", mirror="x=100"), read as a --config file is.
progress: called with a dict (phase, iteration, iterations, elements, element_area) at each
phase and refinement iteration; an exception it raises stops the run and propagates.
Raises pak.InputError with the message `pak flow` prints.)");
  m.def(
      "animate",
      [](const py::object& container, const py::object& animation, const py::object& progress, int progressEvery,
         int frames, int svgKeyframes, int evennessFrames, const py::kwargs& options) {
        return animate(container, animation, progress, progressEvery, {frames, svgKeyframes, evennessFrames}, options);
      },
      py::arg("container") = py::none(), py::arg("animation") = py::none(), py::kw_only(),
      py::arg("progress") = py::none(), py::arg("progress_every") = 50, py::arg("frames") = 0,
      py::arg("svg_keyframes") = 60, py::arg("evenness_frames") = 10,
      R"(Packs animated elements into `container` (AnimationPak), as `pak animate` does.

container: a path, a pak.Scene, or rings / a shapely geometry.
animation: an animation file's path, or its JSON as a dict (element paths relative to the
working folder; docs/animation-format.md).
frames, svg_keyframes, evenness_frames: as --frames, --svg-keyframes, --evenness-frames.
options: `pak animate`'s options by the same names, '-' written '_' (seed=3, slices=10,
max_iterations=200, threads=2), read as a --config file is.
progress: called with a dict (iteration, fill, growing_slices, ...) every progress_every
iterations; an exception it raises stops the run and propagates.
Raises pak.InputError with the message `pak animate` prints.)");
  m.def("metrics", &metrics, py::arg("packings"), py::kw_only(), py::arg("report") = py::none(),
        R"(Measures how even the negative space of a packing is, as `pak metrics --json` does.

packings: a packing SVG's path, a pak.pack or pak.flow result, or a list of them.
report: a Pak report (dict or path) to read d_gap from, as --report; None: a pak.pack result's own.
options: `pak metrics`'s options by the same names (grid=500, gap=4.0, calibrate=True, ...).
Returns the --json entry of each packing as a dict (a list of them for a list): Q, H, O as
curves {"r": array, "value": array}, "evenness" with P1-P3 and h, ratios as floats.)");
}
