#pragma once
// Interprets documents as scenes and element libraries (the input conventions of DESIGN.md).
#include <string>
#include <vector>

#include "pak/geom/scene.hpp"
#include "pak/io/svg_reader.hpp"

namespace pak {

// Reads .svg or .path by extension.
SvgDocument readDocument(const std::string& path, const SvgReadOptions& = {});

// Layers `container`, `fixed`, `guides`, `spines`; a file without such layers whose
// closed shapes form a region is a container by itself (.path: boundary paths minus holes).
// Throws InputError when no usable container is found.
Scene sceneFromDocument(const SvgDocument& document);
Scene loadScene(const std::string& path, const SvgReadOptions& = {});

struct SceneOptions {
  // The layer that holds the containers (matched lower-cased). Its disjoint parts are separate
  // containers. `elements` reads a previous Pak packing: each placed element (the silhouette of
  // what its art paints, inner holes filled) is one container.
  std::string containerLayer = "container";
};
// As above, and Scene::containers: one per container, with the files of its `data-elements`
// (comma-separated, relative to the scene file); loadScene also loads those libraries.
Scene sceneFromDocument(const SvgDocument& document, const SceneOptions& sceneOptions);
Scene loadScene(const std::string& path, const SceneOptions& sceneOptions, const SvgReadOptions& = {});

// All visible shapes of the document form one element; an optional <path id="spine">; shapes
// with an id `handle-NAME` are AnimationPak handles (their box's centre), not art, and a name
// given twice is an InputError.
// Throws InputError when the element paints no area.
ElementArt elementFromDocument(const SvgDocument& document);
// An SVG whose root has several top-level groups gives one element per group.
Library elementsFromDocument(const SvgDocument& document);
// Files and folders (every .svg and .path inside, sorted by name).
Library loadLibrary(const std::vector<std::string>& pathsOrFolders, const SvgReadOptions& = {});

}  // namespace pak
