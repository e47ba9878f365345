#pragma once
// Rings between numpy and the core: (N, 2) float64 arrays of x, y in the SVG's coordinates
// (y down), the closing vertex not repeated.
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "pak/geom/polygon.hpp"

namespace pak::python {

namespace py = pybind11;

// Anything numpy reads as an (N, 2) array of numbers, N >= minPoints; else an InputError
// naming `where`.
Polyline polylineFromArray(const py::handle& points, const std::string& where, int minPoints);
// The same with N >= 3.
Ring ringFromArray(const py::handle& points, const std::string& where);
// One ring (an (N, 2) array) or a sequence of rings; a shapely (Multi)Polygon gives its
// rings, holes included (py_shapely.hpp), in a sequence too.
std::vector<Ring> ringsFromObject(const py::handle& object, const std::string& where);
// Open lines: one (N, 2) array, a sequence of them, or shapely (Multi)LineStrings.
std::vector<Polyline> polylinesFromObject(const py::handle& object, const std::string& where);
py::array_t<double> arrayFromRing(const Ring& ring);

}  // namespace pak::python
