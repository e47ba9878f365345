#pragma once
// pak.flow: `pak flow` (FLOWPAK) on the library, its options the CLI's option table.
#include <pybind11/pybind11.h>

#include "py_flow_result.hpp"

namespace pak::python {

namespace py = pybind11;

// `progress(dict)` (or None) is called at each phase and refinement iteration with the
// progress line's figures; an exception it raises, or Ctrl-C, stops the run and is raised.
FlowResult flow(const py::object& container, const py::object& elements, const py::object& guides,
                const py::object& progress, const py::kwargs& options);

}  // namespace pak::python
