#pragma once
// Shapely geometries (and anything else with __geo_interface__) as rings and polylines, so
// that pak.scene, pak.elements and the packers take them where they take numpy arrays.
// Shapely itself is not needed: the interface is a dict of plain coordinates.
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "pak/geom/polygon.hpp"

namespace pak::python {

namespace py = pybind11;

bool isGeometry(const py::handle& object);
// A Polygon's exterior and holes, a MultiPolygon's every polygon's (even-odd, as pak.scene
// reads rings); anything else is an InputError naming `where`.
std::vector<Ring> geometryRings(const py::handle& geometry, const std::string& where);
// A LineString, or a MultiLineString's lines (flow guides).
std::vector<Polyline> geometryLines(const py::handle& geometry, const std::string& where);

}  // namespace pak::python
