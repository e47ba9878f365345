#pragma once
// pak.animate: `pak animate` (AnimationPak) on the library, its options the CLI's option table.
#include <pybind11/pybind11.h>

#include "py_animation_result.hpp"

namespace pak::python {

namespace py = pybind11;

struct AnimateOutputs {
  int frames = 0, svgKeyframes = 60, evennessFrames = 10;  // as --frames, --svg-keyframes, --evenness-frames
};

// `animation`: an animation file's path, or its JSON as a dict (element paths relative to the
// working folder). `progress(dict)` (or None) is called every `progressEvery` iterations; an
// exception it raises, or Ctrl-C, stops the run and is raised.
AnimationResult animate(const py::object& container, const py::object& animation, const py::object& progress,
                        int progressEvery, const AnimateOutputs& outputs, const py::kwargs& options);

}  // namespace pak::python
