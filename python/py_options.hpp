#pragma once
// Keyword arguments as the JSON object a --config file holds, so that the CLI's option table
// reads them: max_iterations=200 is {"max-iterations": 200}.
#include <string>

#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

namespace pak::python {

namespace py = pybind11;

// Numbers, bools and strings; anything else is an InputError naming `where` and the option.
nlohmann::json optionsObject(const py::dict& options, const std::string& where);

}  // namespace pak::python
