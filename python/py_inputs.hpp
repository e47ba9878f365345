#pragma once
// What pak.pack packs: a scene (a container) and elements, read from files as the CLI reads
// them, or made from rings (numpy arrays), which become a small SVG document read by the same
// reader, so both kinds of input go through one path.
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "pak/io/scene_loader.hpp"

namespace pak::python {

namespace py = pybind11;

struct SceneInput {
  LoadedScene loaded;
  std::string file;  // the file it was read from; "" when made from rings
};

struct ElementsInput {
  std::vector<LoadedElement> elements;
  std::vector<std::string> paths;  // the files and folders read; empty when made from rings
};

SceneInput readScene(const std::string& path, const std::string& containerLayer = "container");
ElementsInput readElements(const std::vector<std::string>& paths);
// A container from rings: an (N, 2) array or a list of them, holes by the even-odd rule, or
// a shapely (Multi)Polygon; `guides` (None, or lines: py_arrays.hpp) make it a flow scene.
SceneInput sceneFromRings(const py::handle& rings, const py::handle& guides = py::none());
// One element per item: an (N, 2) array, a list of rings (even-odd) or a shapely
// (Multi)Polygon, filled with `colors[i]` (any SVG colour) or a default blue. One geometry
// alone is one element.
ElementsInput elementsFromRings(const py::handle& items, const std::vector<std::string>& colors = {});

// The packers' arguments as given: paths (str or os.PathLike), a SceneInput / ElementsInput,
// rings or shapely geometries. `containerLayer` applies to a scene read here; `guides` to one
// made from rings.
SceneInput sceneArgument(const py::handle& container, const std::string& containerLayer,
                         const py::handle& guides = py::none());
ElementsInput elementsArgument(const py::handle& elements);

}  // namespace pak::python
