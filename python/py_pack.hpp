#pragma once
// pak.pack: `pak pack` on the library, its options the CLI's option table.
#include <pybind11/pybind11.h>

#include "py_result.hpp"

namespace pak::python {

namespace py = pybind11;

// `progress(dict)` (or None) is called every `progressEvery` iterations with the progress
// line's figures; an exception it raises, or Ctrl-C, stops the run and is raised again.
PackResult pack(const py::object& container, const py::object& elements, const py::object& secondary,
                const py::object& progress, int progressEvery, const py::kwargs& options);

}  // namespace pak::python
