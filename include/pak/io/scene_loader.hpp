#pragma once
// Interprets documents as scenes and element libraries (the input conventions of DESIGN.md).
// A scene comes with its layout (what the output draws of it) and the reader's warnings; an
// element with its shapes' SVG attributes and warnings. The core takes just the Scene and
// the ElementArt.
#include <string>
#include <vector>

#include "pak/geom/scene.hpp"
#include "pak/io/scene_layout.hpp"
#include "pak/io/svg_reader.hpp"
#include "pak/io/svg_shape.hpp"
#include "pak/io/warning.hpp"

namespace pak {

// Reads .svg or .path by extension.
SvgDocument readDocument(const std::string& path, const SvgReadOptions& = {});

struct LoadedScene {
  Scene scene;                    // what the packers take
  SceneLayout layout;             // what packingDrawing and flowDrawing draw around the packing
  std::vector<Warning> warnings;  // the reader's and the scene's: what was ignored and why
};

// Layers `container`, `fixed`, `guides`, `spines`; a file without such layers whose
// closed shapes form a region is a container by itself (.path: boundary paths minus holes).
// Throws InputError when no usable container is found.
LoadedScene sceneFromDocument(const SvgDocument& document);
LoadedScene loadScene(const std::string& path, const SvgReadOptions& = {});

struct SceneOptions {
  // The layer that holds the containers (matched lower-cased). Its disjoint parts are separate
  // containers. `elements` reads a previous Pak packing: each placed element (the silhouette of
  // what its art paints, inner holes filled) is one container.
  std::string containerLayer = "container";
};
// As above, and Scene::containers: one per container, with the files of its `data-elements`
// (comma-separated, relative to the scene file); loadScene also loads those libraries.
LoadedScene sceneFromDocument(const SvgDocument& document, const SceneOptions& sceneOptions);
LoadedScene loadScene(const std::string& path, const SceneOptions& sceneOptions, const SvgReadOptions& = {});

struct LoadedElement {
  ElementArt element;             // what the packers take
  std::vector<SvgShape> shapes;   // element.shapes as the document gives them (ids, tags, layers)
  std::vector<Warning> warnings;  // the reader's and the element's: what was ignored and why
};

// All visible shapes of the document form one element; an optional <path id="spine">; shapes
// with an id `handle-NAME` are AnimationPak handles (their box's centre), not art, and a name
// given twice is an InputError.
// Throws InputError when the element paints no area.
LoadedElement elementFromDocument(const SvgDocument& document);
// An SVG whose root has several top-level groups gives one element per group, except that
// groups that are layers of one drawing (their painted boxes overlap, or they are Inkscape
// layers: src/io/drawing_layers.hpp) make one element together.
std::vector<LoadedElement> elementsFromDocument(const SvgDocument& document);
// Files and folders (every .svg and .path inside, sorted by name), each element as read.
std::vector<LoadedElement> loadElements(const std::vector<std::string>& pathsOrFolders, const SvgReadOptions& = {});
// The same elements alone: what the packers take.
Library loadLibrary(const std::vector<std::string>& pathsOrFolders, const SvgReadOptions& = {});
Library libraryOf(const std::vector<LoadedElement>& elements);

}  // namespace pak
