#include "py_options.hpp"

#include <algorithm>

#include "pak/error.hpp"

namespace pak::python {

nlohmann::json optionsObject(const py::dict& options, const std::string& where) {
  nlohmann::json object = nlohmann::json::object();
  for (const auto& [key, value] : options) {
    std::string name = py::cast<std::string>(key);
    std::replace(name.begin(), name.end(), '_', '-');  // Python names cannot hold '-'
    // bool before int: Python's True is an int too.
    if (py::isinstance<py::bool_>(value)) object[name] = py::cast<bool>(value);
    else if (py::isinstance<py::int_>(value)) {
      // Seeds go up to 2^64 - 1; negative numbers stay signed for the table to refuse.
      if (py::cast<py::int_>(value) >= py::int_(0)) object[name] = py::cast<std::uint64_t>(value);
      else object[name] = py::cast<std::int64_t>(value);
    } else if (py::isinstance<py::float_>(value)) object[name] = py::cast<double>(value);
    else if (py::isinstance<py::str>(value)) object[name] = py::cast<std::string>(value);
    else
      throw InputError(where, "option \"" + name + "\" must be a number, True/False or a string, got " +
                                  py::cast<std::string>(py::str(py::type::of(value).attr("__name__"))));
  }
  return object;
}

}  // namespace pak::python
