#include "py_shapely.hpp"

#include "pak/error.hpp"
#include "py_arrays.hpp"

namespace pak::python {
namespace {

std::string typeOf(const py::dict& interface) {
  return interface.contains("type") ? py::cast<std::string>(py::str(interface["type"])) : std::string("?");
}

// A GeoJSON ring repeats its first point last; Pak's rings do not.
Ring openRing(const py::handle& coordinates, const std::string& where) {
  Polyline points = polylineFromArray(coordinates, where, 4);
  if (points.front() == points.back()) points.pop_back();
  return points;
}

void appendPolygon(std::vector<Ring>& rings, const py::handle& polygon, const std::string& where) {
  for (const py::handle ring : polygon) rings.push_back(openRing(ring, where));
}

}  // namespace

bool isGeometry(const py::handle& object) { return py::hasattr(object, "__geo_interface__"); }

std::vector<Ring> geometryRings(const py::handle& geometry, const std::string& where) {
  const py::dict interface = geometry.attr("__geo_interface__");
  const std::string type = typeOf(interface);
  std::vector<Ring> rings;
  if (type == "Polygon") appendPolygon(rings, interface["coordinates"], where);
  else if (type == "MultiPolygon")
    for (const py::handle polygon : interface["coordinates"]) appendPolygon(rings, polygon, where);
  else
    throw InputError(where, "a geometry must be a Polygon or a MultiPolygon, got a " + type);
  if (rings.empty()) throw InputError(where, "the " + type + " is empty");
  return rings;
}

std::vector<Polyline> geometryLines(const py::handle& geometry, const std::string& where) {
  const py::dict interface = geometry.attr("__geo_interface__");
  const std::string type = typeOf(interface);
  std::vector<Polyline> lines;
  if (type == "LineString") lines.push_back(polylineFromArray(interface["coordinates"], where, 2));
  else if (type == "MultiLineString")
    for (const py::handle line : interface["coordinates"]) lines.push_back(polylineFromArray(line, where, 2));
  else
    throw InputError(where, "a guide must be a LineString or a MultiLineString, got a " + type);
  return lines;
}

}  // namespace pak::python
