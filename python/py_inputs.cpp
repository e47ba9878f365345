#include "py_inputs.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>

#include <pybind11/stl.h>

#include "pak/error.hpp"
#include "pak/io/warning_lines.hpp"
#include "pak/io/svg_reader.hpp"
#include "py_arrays.hpp"
#include "py_shapely.hpp"

namespace pak::python {
namespace {

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);  // round-trips exactly
  return text;
}

// `rings` as one even-odd <path>'s d.
std::string pathData(const std::vector<Ring>& rings) {
  std::string d;
  for (const Ring& ring : rings) {
    for (std::size_t i = 0; i < ring.size(); ++i)
      d += (i == 0 ? "M" : " L") + number(ring[i].x) + "," + number(ring[i].y);
    d += " Z ";
  }
  return d;
}

// `lines` as one open <path>'s d.
std::string lineData(const std::vector<Polyline>& lines) {
  std::string d;
  for (const Polyline& line : lines)
    for (std::size_t i = 0; i < line.size(); ++i)
      d += (i == 0 ? (d.empty() ? "M" : " M") : " L") + number(line[i].x) + "," + number(line[i].y);
  return d;
}

// A document of one path per item, its viewBox the items' (and guides') bounds. With guides,
// the item is the `container` layer and the guides a `guides` layer, as a flow scene has them.
SvgDocument documentOf(const std::vector<std::vector<Ring>>& items, const std::vector<std::string>& fills,
                       const std::string& name, const std::vector<Polyline>& guides = {}) {
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  auto extend = [&](const Polyline& points) {
    for (const Vec2& p : points) {
      x0 = std::min(x0, p.x), y0 = std::min(y0, p.y);
      x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
    }
  };
  for (const auto& rings : items)
    for (const Ring& ring : rings) extend(ring);
  for (const Polyline& line : guides) extend(line);
  const std::string w = number(std::max(x1 - x0, 1e-9)), h = number(std::max(y1 - y0, 1e-9));
  std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + w + "\" height=\"" + h + "\" viewBox=\"" +
                    number(x0) + " " + number(y0) + " " + w + " " + h + "\">\n";
  // A container layer is drawn as styled: an outline as the packers draw a container without
  // one, 1.5 canonical units wide (the container's larger side is 1000).
  const std::string paint = guides.empty() ? std::string()
                                           : "fill=\"none\" stroke=\"#000000\" stroke-width=\"" +
                                                 number(1.5e-3 * std::max(x1 - x0, y1 - y0)) + "\" ";
  if (!guides.empty()) svg += "<g id=\"container\">\n";
  for (std::size_t i = 0; i < items.size(); ++i)
    svg += "<path fill-rule=\"evenodd\" " + (paint.empty() ? "fill=\"" + fills[i] + "\" " : paint) + "d=\"" +
           pathData(items[i]) + "\"/>\n";
  if (!guides.empty())
    svg += "</g>\n<g id=\"guides\">\n<path fill=\"none\" stroke=\"#000000\" d=\"" + lineData(guides) + "\"/>\n</g>\n";
  return readSvgString(svg + "</svg>\n", name);
}

bool isPath(const py::handle& object) {
  return py::isinstance<py::str>(object) || py::hasattr(object, "__fspath__");
}

std::string pathText(const py::handle& object) {
  return py::cast<std::string>(py::module_::import("os").attr("fspath")(object));
}

// What the readers skipped or reinterpreted, as `pak` prints it on stderr ("pak: warning:
// …"): a pak.InputWarning each, which Python's warnings filters show once, silence or turn
// into errors.
void warnAbout(const std::vector<Warning>& warnings) {
  if (warnings.empty()) return;
  const py::object category = py::module_::import("pak").attr("InputWarning");
  for (const std::string& line : warningLines(warnings))
    if (PyErr_WarnEx(category.ptr(), line.c_str(), 1) < 0) throw py::error_already_set();
}

}  // namespace

SceneInput readScene(const std::string& path, const std::string& containerLayer) {
  SceneOptions options;
  options.containerLayer = containerLayer;
  SceneInput input{loadScene(path, options), path};
  warnAbout(input.loaded.warnings);
  return input;
}

ElementsInput readElements(const std::vector<std::string>& paths) {
  ElementsInput input{loadElements(paths), paths};
  std::vector<Warning> warnings;
  for (const LoadedElement& element : input.elements)
    warnings.insert(warnings.end(), element.warnings.begin(), element.warnings.end());
  warnAbout(warnings);
  return input;
}

SceneInput sceneFromRings(const py::handle& rings, const py::handle& guides) {
  const std::vector<Ring> container = ringsFromObject(rings, "container");
  const std::vector<Polyline> lines = guides.is_none() ? std::vector<Polyline>{} : polylinesFromObject(guides, "guides");
  if (!guides.is_none() && lines.empty()) throw InputError("guides", "no guide given");
  return {sceneFromDocument(documentOf({container}, {"#000000"}, "container", lines)), ""};
}

ElementsInput elementsFromRings(const py::handle& items, const std::vector<std::string>& colors) {
  // One geometry is one element (a MultiPolygon is not a list of them).
  if (isGeometry(items)) {
    const std::string fill = colors.empty() ? "#3b6ea5" : colors.front();
    return {{elementFromDocument(documentOf({ringsFromObject(items, "element 0")}, {fill}, "element 0"))}, {}};
  }
  ElementsInput input;
  std::size_t i = 0;
  for (const py::handle item : items) {
    const std::string name = "element " + std::to_string(i);
    const std::string fill = i < colors.size() ? colors[i] : "#3b6ea5";
    input.elements.push_back(elementFromDocument(documentOf({ringsFromObject(item, name)}, {fill}, name)));
    ++i;
  }
  if (input.elements.empty()) throw InputError("elements", "no element given");
  return input;
}

SceneInput sceneArgument(const py::handle& container, const std::string& containerLayer, const py::handle& guides) {
  if (!guides.is_none() && (py::isinstance<SceneInput>(container) || isPath(container)))
    throw InputError("guides", "are for a container given as rings or a geometry; a scene file has its own `guides` layer");
  if (py::isinstance<SceneInput>(container)) return py::cast<SceneInput>(container);
  if (isPath(container)) return readScene(pathText(container), containerLayer);
  return sceneFromRings(container, guides);
}

ElementsInput elementsArgument(const py::handle& elements) {
  if (py::isinstance<ElementsInput>(elements)) return py::cast<ElementsInput>(elements);
  if (isPath(elements)) return readElements({pathText(elements)});
  if (isGeometry(elements)) return elementsFromRings(elements);
  if (py::isinstance<py::sequence>(elements) && py::len(elements) > 0) {
    bool paths = true;
    for (const py::handle item : elements) paths = paths && isPath(item);
    if (paths) {
      std::vector<std::string> files;
      for (const py::handle item : elements) files.push_back(pathText(item));
      return readElements(files);
    }
  }
  return elementsFromRings(elements);
}

}  // namespace pak::python
