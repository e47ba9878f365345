#include "py_arrays.hpp"

#include <cmath>

#include "pak/error.hpp"

namespace pak::python {

using namespace pybind11::literals;

Ring ringFromArray(const py::handle& points, const std::string& where) {
  py::array_t<double, py::array::c_style | py::array::forcecast> array;
  try {
    array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(points);
  } catch (const py::error_already_set&) {
  }
  if (!array || array.ndim() != 2 || array.shape(1) != 2)
    throw InputError(where, "a ring must be an (N, 2) array of x, y coordinates");
  if (array.shape(0) < 3) throw InputError(where, "a ring needs at least 3 points");
  Ring ring;
  auto xy = array.unchecked<2>();
  for (py::ssize_t i = 0; i < xy.shape(0); ++i) {
    if (!std::isfinite(xy(i, 0)) || !std::isfinite(xy(i, 1)))
      throw InputError(where, "a ring's coordinates must be finite numbers");
    ring.push_back({xy(i, 0), xy(i, 1)});
  }
  return ring;
}

std::vector<Ring> ringsFromObject(const py::handle& object, const std::string& where) {
  // One (N, 2) array, or a list of points (a ring given as a list of pairs)?
  py::object array;
  try {
    array = py::module_::import("numpy").attr("asarray")(object, "dtype"_a = "float64");
  } catch (const py::error_already_set&) {  // ragged: a list of rings of different lengths
  }
  if (array && py::cast<int>(array.attr("ndim")) == 2) return {ringFromArray(array, where)};
  if (!py::isinstance<py::sequence>(object) || py::isinstance<py::str>(object))
    throw InputError(where, "expects an (N, 2) array of points or a list of them");
  std::vector<Ring> rings;
  for (const py::handle item : object) rings.push_back(ringFromArray(item, where));
  if (rings.empty()) throw InputError(where, "has no ring");
  return rings;
}

py::array_t<double> arrayFromRing(const Ring& ring) {
  py::array_t<double> array({static_cast<py::ssize_t>(ring.size()), py::ssize_t{2}});
  auto xy = array.mutable_unchecked<2>();
  for (std::size_t i = 0; i < ring.size(); ++i) {
    xy(i, 0) = ring[i].x;
    xy(i, 1) = ring[i].y;
  }
  return array;
}

}  // namespace pak::python
