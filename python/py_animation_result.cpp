#include "py_animation_result.hpp"

#include <pybind11/numpy.h>

#include "outline_output.hpp"
#include "pak/error.hpp"
#include "pak/io/animation_output.hpp"
#include "pak/io/svg_writer.hpp"
#include "py_arrays.hpp"
#include "py_lists.hpp"
#include "py_result.hpp"

namespace pak::python {
namespace {

py::list outlinesOf(const Packing& frame) {
  return listOf(artOutlines(frame), [](const Region& outline) { return ringArrays(outline); });
}

void checkTime(double t) {
  if (!(t >= 0.0 && t <= 1.0)) throw InputError("t", "must be a time between 0 and 1");
}

Drawing drawingAt(const AnimationResult& r, double t) {
  checkTime(t);
  py::gil_scoped_release release;
  return r.render().drawingAt(t);
}

const Packing& firstFrame(const AnimationResult& r) {
  if (r.frames.packings.empty()) throw InputError("frames", "there are none");
  return r.frames.packings.front();
}

}  // namespace

void bindAnimationResult(py::module_& m) {
  py::class_<AnimationResult>(m, "AnimationResult",
                              "An AnimationPak animation: pak.animate's result, its frames at evenly spaced t.")
      .def_property_readonly(
          "times",
          [](const AnimationResult& r) {
            return py::array_t<double>(static_cast<py::ssize_t>(r.frames.times.size()), r.frames.times.data());
          },
          "each frame's t in [0, 1]")
      .def_property_readonly(
          "outlines",
          [](const AnimationResult& r) {
            py::list frames;
            for (const Packing& frame : r.frames.packings) frames.append(outlinesOf(frame));
            return frames;
          },
          "for each frame, each element's outline (what its art paints) as a list of (N, 2) arrays")
      .def(
          "outlines_at",
          [](const AnimationResult& r, double t) {
            checkTime(t);
            cli::FrameShrink shrink;
            Packing frame;
            {
              py::gil_scoped_release release;
              frame = r.render().packingAt(t, shrink);
            }
            return outlinesOf(frame);
          },
          py::arg("t"), "the outlines of the frame at any t in [0, 1], rendered as the frames are")
      .def_property_readonly(
          "colors",
          [](const AnimationResult& r) {
            return listOf(firstFrame(r).elements, [](const PlacedElement& e) { return colorOf(e.art); });
          },
          "each element's colour in a frame, '#rrggbb' (its first fill, else stroke), or None")
      .def_property_readonly(
          "sources",
          [](const AnimationResult& r) {
            return listOf(firstFrame(r).elements, [](const PlacedElement& e) { return py::str(e.source); });
          },
          "the file each element in a frame came from")
      .def_property_readonly(
          "report",
          [](const AnimationResult& r) { return dictOf(r.report); },
          "the report `pak animate --report` writes, as a dict")
      .def("__len__", [](const AnimationResult& r) { return r.frames.packings.size(); })
      .def("to_svg", [](const AnimationResult& r) { return r.svg; },
           "the animated SVG (plays in a browser) `pak animate` writes as OUT/animation.svg")
      .def("save", [](const AnimationResult& r, const py::object& path) { saveText(path, r.svg); }, py::arg("path"),
           "writes to_svg() to `path`")
      .def(
          "frame_svg",
          [](const AnimationResult& r, double t) {
            const Drawing drawing = drawingAt(r, t);
            return toSvgString(drawing, cli::outlineWriteOptions(r.args.polyline, cli::kMeshCurveTolerance,
                                                                 r.animation.canonicalScale));
          },
          py::arg("t") = 0.0, "a static SVG of the frame at t (outlines as fitted curves), for a plotter")
      .def(
          "save_gif",
          [](const AnimationResult& r, const py::object& path, int width) {
            AnimationOutputOptions output = cli::animationOutputOptions(r.args, r.script, r.animation);
            output.width = width;
            const std::string file = py::cast<std::string>(py::module_::import("os").attr("fspath")(path));
            py::gil_scoped_release release;
            writeGif(r.frames.drawings, file, output);
          },
          py::arg("path"), py::arg("width") = 480, "writes the frames as the GIF `pak animate` writes")
      .def(
          "to_png", [](const AnimationResult& r, int width, double t) { return pngBytes(drawingAt(r, t), width); },
          py::arg("width") = 1200, py::arg("t") = 0.0, "the frame at t as a PNG (as `pak animate --png --png-at t`)")
      .def("_repr_png_", [](const AnimationResult& r) { return pngBytes(drawingAt(r, 0.0), 800); })
      .def("__repr__", [](const AnimationResult& r) {
        return "<pak.AnimationResult: " + std::to_string(r.animation.elements.size()) + " elements, " +
               std::to_string(r.frames.packings.size()) + " frames, " + std::to_string(r.animation.iterations) +
               " iterations, " + toString(r.animation.stopReason) + ">";
      });
}

}  // namespace pak::python
