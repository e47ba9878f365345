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
// A container from rings: an (N, 2) array or a list of them, holes by the even-odd rule.
SceneInput sceneFromRings(const py::handle& rings);
// One element per item: an (N, 2) array or a list of rings (even-odd), filled with `colors[i]`
// (any SVG colour) or a default blue.
ElementsInput elementsFromRings(const py::handle& items, const std::vector<std::string>& colors = {});

// pak.pack's arguments as given: paths (str or os.PathLike), a SceneInput / ElementsInput, or
// rings. `containerLayer` applies to a scene read here.
SceneInput sceneArgument(const py::handle& container, const std::string& containerLayer);
ElementsInput elementsArgument(const py::handle& elements);

}  // namespace pak::python
