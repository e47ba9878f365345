#pragma once
// pak.metrics: `pak metrics` on packings (files, or pak.pack / pak.flow results), its options
// the CLI's option table; the figures of its --json as a dict, curves as numpy arrays.
#include <pybind11/pybind11.h>

namespace pak::python {

namespace py = pybind11;

// `packings`: one packing or a list (measured together, as `pak metrics A B` does: with
// calibrate=True to their mean negative space). `report`: a Pak report (a dict or a path) to
// read d_gap from, as --report; None takes a result's own report.
py::object metrics(const py::object& packings, const py::object& report, const py::kwargs& options);

}  // namespace pak::python
