#include "py_arrays.hpp"

#include <cmath>

#include "pak/error.hpp"
#include "py_shapely.hpp"

namespace pak::python {

using namespace pybind11::literals;

Polyline polylineFromArray(const py::handle& points, const std::string& where, int minPoints) {
  const char* what = minPoints >= 3 ? "a ring" : "a line";
  py::array_t<double, py::array::c_style | py::array::forcecast> array;
  try {
    array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(points);
  } catch (const py::error_already_set&) {
  }
  if (!array || array.ndim() != 2 || array.shape(1) != 2)
    throw InputError(where, std::string(what) + " must be an (N, 2) array of x, y coordinates");
  if (array.shape(0) < minPoints)
    throw InputError(where, std::string(what) + " needs at least " + std::to_string(minPoints) + " points");
  Polyline ring;
  auto xy = array.unchecked<2>();
  for (py::ssize_t i = 0; i < xy.shape(0); ++i) {
    if (!std::isfinite(xy(i, 0)) || !std::isfinite(xy(i, 1)))
      throw InputError(where, std::string(what) + "'s coordinates must be finite numbers");
    ring.push_back({xy(i, 0), xy(i, 1)});
  }
  return ring;
}

Ring ringFromArray(const py::handle& points, const std::string& where) { return polylineFromArray(points, where, 3); }

namespace {

// A list holding geometries: numpy would read those as arrays of objects, and warn.
bool holdsGeometry(const py::handle& object) {
  if (!py::isinstance<py::list>(object) && !py::isinstance<py::tuple>(object)) return false;
  for (const py::handle item : object)
    if (isGeometry(item)) return true;
  return false;
}

}  // namespace

std::vector<Ring> ringsFromObject(const py::handle& object, const std::string& where) {
  if (isGeometry(object)) return geometryRings(object, where);
  // One (N, 2) array, or a list of points (a ring given as a list of pairs)?
  py::object array;
  if (!holdsGeometry(object)) {
    try {
      array = py::module_::import("numpy").attr("asarray")(object, "dtype"_a = "float64");
    } catch (const py::error_already_set&) {  // ragged: a list of rings of different lengths
    }
  }
  if (array && py::cast<int>(array.attr("ndim")) == 2) return {ringFromArray(array, where)};
  if (!py::isinstance<py::sequence>(object) || py::isinstance<py::str>(object))
    throw InputError(where, "expects an (N, 2) array of points or a list of them");
  std::vector<Ring> rings;
  for (const py::handle item : object) {
    if (isGeometry(item)) {
      for (Ring& ring : geometryRings(item, where)) rings.push_back(std::move(ring));
    } else {
      rings.push_back(ringFromArray(item, where));
    }
  }
  if (rings.empty()) throw InputError(where, "has no ring");
  return rings;
}

std::vector<Polyline> polylinesFromObject(const py::handle& object, const std::string& where) {
  if (isGeometry(object)) return geometryLines(object, where);
  py::object array;
  if (!holdsGeometry(object)) {
    try {
      array = py::module_::import("numpy").attr("asarray")(object, "dtype"_a = "float64");
    } catch (const py::error_already_set&) {  // ragged: lines of different lengths
    }
  }
  if (array && py::cast<int>(array.attr("ndim")) == 2) return {polylineFromArray(array, where, 2)};
  if (!py::isinstance<py::sequence>(object) || py::isinstance<py::str>(object))
    throw InputError(where, "expects an (N, 2) array of points or a list of them");
  std::vector<Polyline> lines;
  for (const py::handle item : object) {
    if (isGeometry(item)) {
      for (Polyline& line : geometryLines(item, where)) lines.push_back(std::move(line));
    } else {
      lines.push_back(polylineFromArray(item, where, 2));
    }
  }
  return lines;
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
