#pragma once
// Results as Python sees them: a list made from each of a result's items, and a report (JSON)
// as the dict json.loads gives.
#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

namespace pak::python {

namespace py = pybind11;

template <class Items, class ToPython>
py::list listOf(const Items& items, ToPython&& toPython) {
  py::list all;
  for (const auto& item : items) all.append(toPython(item));
  return all;
}

inline py::object dictOf(const nlohmann::json& report) {
  return py::module_::import("json").attr("loads")(report.dump());
}

}  // namespace pak::python
