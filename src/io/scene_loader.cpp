// Interprets read documents as scenes and element libraries, following the input
// conventions of DESIGN.md: layers `container`, `fixed`, `guides`, `spines` (and `holes`
// for legacy .path files); everything else in an element file is the element's art.
#include "pak/io/scene_loader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "io/drawing_layers.hpp"
#include "io/scene_layers.hpp"
#include "pak/error.hpp"
#include "pak/io/packing_reader.hpp"
#include "pak/io/path_reader.hpp"

namespace pak {
namespace {

namespace fs = std::filesystem;

std::string lowerCased(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

std::string extensionOf(const std::string& path) { return lowerCased(fs::path(path).extension().string()); }

// Layers that never hold container or element art.
bool isHelperLayer(const std::string& layer) {
  return layer == "fixed" || layer == "guides" || layer == "spines" || layer == "holes" || layer == "elements";
}

// How a shape is named in messages: its id, else its tag and position.
std::string shapeName(const SvgShape& shape, std::size_t index) {
  if (!shape.id.empty()) return shape.id;
  return shape.tag + " #" + std::to_string(index + 1);
}

// Where a shape is, for errors: "file:line" when the reader knows its line.
std::string placeOf(const std::string& file, const SvgShape& shape) {
  return shape.line > 0 ? file + ":" + std::to_string(shape.line) : file;
}

// An AnimationPak handle: a shape whose id starts with `handle-` marks a point (its bounding
// box's centre) and is not art. Nothing else: nullopt.
std::optional<ElementHandle> handleOf(const SvgShape& shape, const std::string& file, std::size_t index) {
  static const std::string prefix = "handle-";
  if (lowerCased(shape.id.substr(0, prefix.size())) != prefix) return std::nullopt;
  const std::string name = shape.id.substr(prefix.size());
  if (name.empty())
    throw InputError(placeOf(file, shape), "shape " + shapeName(shape, index) + ": a handle needs a name after \"handle-\"");
  Box box;
  for (const Subpath& subpath : shape.subpaths)
    for (Vec2 p : subpath.points) box.add(p);
  if (box.empty()) throw InputError(placeOf(file, shape), "handle \"" + name + "\" (" + shape.tag + ") has no points");
  return ElementHandle{name, box.center()};
}

// Grid of the boolean operations: fine relative to the document, so that icons drawn in a
// 24 × 24 box and posters in millimetres are resolved alike.
ClipOptions clipOptionsFor(const Box& box) {
  ClipOptions options;
  const double extent = box.empty() ? 0.0 : std::max(box.width(), box.height());
  if (extent > 0) options.precision = std::min(options.precision, extent * 1e-7);
  return options;
}

// A subpath that returns to its start (within a hair of the document) encloses a region
// even without an explicit close.
bool isEffectivelyClosed(const Subpath& subpath, double epsilon) {
  if (subpath.closed) return true;
  return subpath.points.size() >= 3 && distance(subpath.points.front(), subpath.points.back()) <= epsilon;
}

// The region a closed shape encloses, whatever its paint (a container drawn as an outline
// with fill="none" is still a container). A filled shape's open subpaths enclose what every
// renderer fills, as if closed (the reader warns); an open outline encloses nothing.
Region enclosedRegion(const SvgShape& shape, const std::string& file, std::size_t index, double epsilon,
                      const ClipOptions& clip) {
  std::vector<Ring> rings;
  for (const Subpath& subpath : shape.subpaths) {
    if (subpath.points.size() < 2) continue;
    if (!shape.fill && !isEffectivelyClosed(subpath, epsilon))
      throw InputError(placeOf(file, shape), "container path '" + shapeName(shape, index) +
                                                 "' is not closed and not filled (end it with Z, or close it in your editor)");
    if (subpath.points.size() >= 3) rings.push_back(subpath.points);
  }
  if (rings.empty()) return {};
  return regionFromRings(rings, shape.fillRule, clip);
}

Polyline polylineOf(const Subpath& subpath) {
  Polyline line = subpath.points;
  if (subpath.closed && line.size() > 2) line.push_back(line.front());
  return line;
}

std::string stemOf(const std::string& file) { return fs::path(file).stem().string(); }

}  // namespace

SvgDocument readDocument(const std::string& path, const SvgReadOptions& options) {
  const std::string extension = extensionOf(path);
  if (extension == ".svg") return readSvgFile(path, options);
  if (extension == ".path") return readPathFile(path);
  std::error_code error;
  if (!fs::exists(path, error)) throw InputError(path, "no such file");
  throw InputError(path, "unknown file type '" + extension + "' (Pak reads .svg and .path files)");
}

LoadedScene sceneFromDocument(const SvgDocument& document) { return sceneFromDocument(document, SceneOptions{}); }

namespace {

// `data-gap="30"`: a positive number (canonical units). `where`: the shape that has it.
double gapOf(const std::string& attribute, const std::string& where) {
  char* end = nullptr;
  const double gap = std::strtod(attribute.c_str(), &end);
  while (end && (*end == ' ' || *end == '\t')) ++end;
  if (end == attribute.c_str() || (end && *end != '\0') || !std::isfinite(gap) || !(gap > 0.0))
    throw InputError(where, "data-gap=\"" + attribute + "\" must be a positive number (canonical units)");
  return gap;
}

// `data-elements="a.svg, b/"`: the files and folders, relative to the scene file. `where`: the
// shape that has it.
std::vector<std::string> elementFilesOf(const std::string& attribute, const std::string& sceneFile,
                                        const std::string& where) {
  std::vector<std::string> files;
  std::size_t begin = 0;
  while (begin <= attribute.size()) {
    std::size_t end = std::min(attribute.find(',', begin), attribute.size());
    std::string name = attribute.substr(begin, end - begin);
    name.erase(0, name.find_first_not_of(" \t\n\r"));
    name.erase(name.find_last_not_of(" \t\n\r") + 1);
    if (!name.empty()) {
      fs::path path(name);
      files.push_back(path.is_absolute() ? name : (fs::path(sceneFile).parent_path() / path).string());
    }
    begin = end + 1;
  }
  if (files.empty()) throw InputError(where, "data-elements=\"" + attribute + "\" names no file");
  return files;
}

// A region's outer rings only: the silhouette of an element's art.
Region silhouette(const Region& region) {
  Region filled;
  for (const Polygon& polygon : region) filled.push_back(Polygon{polygon.outer, {}});
  return filled;
}

}  // namespace

LoadedScene sceneFromDocument(const SvgDocument& document, const SceneOptions& sceneOptions) {
  const std::string containerLayer = lowerCased(sceneOptions.containerLayer);
  if (containerLayer.empty() || (containerLayer != "elements" && isHelperLayer(containerLayer)))
    throw InputError(document.file, "--container-layer '" + sceneOptions.containerLayer +
                                        "' cannot hold containers (use container, elements or your own layer name)");
  // `elements`: a previous packing; each placed element is one container.
  const bool elementContainers = containerLayer == "elements";
  LoadedScene loaded;
  Scene& scene = loaded.scene;
  SceneLayout& layout = loaded.layout;
  scene.source = document.file;
  layout.viewBox = document.viewBox;
  layout.width = document.width;
  layout.height = document.height;
  layout.widthText = document.widthText;
  layout.heightText = document.heightText;
  layout.fixedMarkup = document.fixedMarkup;
  loaded.warnings = document.warnings;

  const Box box = document.viewBox.empty() ? bounds(document.shapes) : document.viewBox;
  const ClipOptions clip = clipOptionsFor(box);
  const double closeEpsilon = std::max(clip.precision, 1e-9 * std::max(box.width(), box.height()));

  const bool hasContainerLayer = std::any_of(document.shapes.begin(), document.shapes.end(),
                                             [&](const SvgShape& s) { return s.layer == containerLayer; });
  if (!hasContainerLayer && containerLayer != "container")
    throw InputError(document.file, "no usable container: the file has no shape in a layer named '" + containerLayer + "'");
  std::vector<Region> containerRegions, holeRegions;
  std::vector<std::string> regionElements;  // data-elements of each container region's shape
  std::vector<std::string> regionGaps;      // and its data-gap
  std::vector<std::string> regionPlaces;    // and where that shape is, for errors
  std::vector<const Shape*> elementShapes;  // --container-layer elements: the placed elements' art
  std::vector<int> elementKeys;
  for (std::size_t i = 0; i < document.shapes.size(); ++i) {
    const SvgShape& shape = document.shapes[i];
    if (elementContainers && shape.layer == containerLayer) {
      layout.containerShapes.push_back({shape, true});  // drawn as the artist drew it, under the new elements
      elementShapes.push_back(&shape);
      elementKeys.push_back(shape.layerGroup);
    } else if (shape.layer == "fixed") {
      scene.fixed.push_back(shape);
      layout.fixedShapes.push_back(shape);
    } else if (shape.layer == "guides" || shape.layer == "spines") {
      for (const Subpath& subpath : shape.subpaths)
        if (subpath.points.size() >= 2)
          (shape.layer == "guides" ? scene.guides : scene.spines).push_back(polylineOf(subpath));
    } else if (shape.layer == "holes") {
      Region hole = enclosedRegion(shape, document.file, i, closeEpsilon, clip);
      if (!hole.empty()) holeRegions.push_back(std::move(hole));
    } else if (elementContainers) {
      continue;  // the previous packing's own container and other layers: not containers now
    } else if (hasContainerLayer ? shape.layer == containerLayer : !isHelperLayer(shape.layer)) {
      // Without a container layer, every shape outside the helper layers outlines the container.
      // A container layer keeps the artist's styling; a file that is a container by itself is
      // drawn as an outline, and what it does not paint is not part of it (icon sets such as
      // Tabler draw an invisible bounding square first).
      if (!hasContainerLayer && !shape.fill && (!shape.stroke || !(shape.strokeWidth > 0.0))) {
        loaded.warnings.push_back({document.file + ": " + shapeName(shape, i),
                                   "paints nothing (no fill, no stroke); not part of the container"});
        continue;
      }
      layout.containerShapes.push_back({shape, shape.layer == "container"});
      Region region = enclosedRegion(shape, document.file, i, closeEpsilon, clip);
      if (area(region) <= 0.0) {
        loaded.warnings.push_back({document.file + ": " + shapeName(shape, i), "container shape encloses no area; ignored"});
        continue;
      }
      containerRegions.push_back(std::move(region));
      regionElements.push_back(shape.elements);
      regionGaps.push_back(shape.gap);
      regionPlaces.push_back(placeOf(document.file, shape));
    }
  }
  if (elementContainers) {
    for (Region& outline : outlinesByKey(elementShapes, elementKeys, clip))
      containerRegions.push_back(silhouette(outline));
    if (containerRegions.empty()) throw InputError(document.file, "no usable container: the elements paint no area");
  }

  if (layout.containerShapes.empty())
    throw InputError(document.file, hasContainerLayer || document.shapes.empty()
                                        ? "no usable container: the file has no shape to use as a container"
                                        : "no usable container: every shape is in a fixed/guides/spines/holes layer "
                                          "(put the outline in a layer named 'container')");
  if (containerRegions.empty())
    throw InputError(document.file, "no usable container: the container shapes enclose no area");
  scene.container = containerRegions.size() == 1 ? containerRegions.front() : unite(containerRegions, clip);
  if (!holeRegions.empty()) scene.container = subtract(scene.container, unite(holeRegions, clip), clip);
  normalizeOrientation(scene.container);
  if (area(scene.container) <= 0.0)
    throw InputError(document.file, "no usable container: the holes cover the whole container");

  // The separate containers: each placed element of a previous packing, else each disjoint
  // part of the union (with its holes), asking for the library of the first shape that
  // overlaps it and names one.
  const Region holes = holeRegions.empty() ? Region{} : unite(holeRegions, clip);
  if (elementContainers) {
    for (const Region& region : containerRegions) {
      Region part = holes.empty() ? region : subtract(region, holes, clip);
      normalizeOrientation(part);
      if (area(part) > 0.0) scene.containers.push_back({std::move(part), {}, {}});
    }
  } else {
    for (const Polygon& polygon : scene.container) {
      ContainerPart part{Region{polygon}, {}, {}};
      for (std::size_t r = 0; r < containerRegions.size() && part.elementFiles.empty(); ++r)
        if (!regionElements[r].empty() && area(intersect(part.region, containerRegions[r], clip)) > 0.0)
          part.elementFiles = elementFilesOf(regionElements[r], document.file, regionPlaces[r]);
      for (std::size_t r = 0; r < containerRegions.size() && part.gap == 0.0; ++r)
        if (!regionGaps[r].empty() && area(intersect(part.region, containerRegions[r], clip)) > 0.0)
          part.gap = gapOf(regionGaps[r], regionPlaces[r]);
      scene.containers.push_back(std::move(part));
    }
  }
  if (hasContainerLayer) addSceneLayers(document, containerLayer, layout, loaded.warnings);
  // A document always has a box (else it has no shapes and so no container); a hand-made one
  // may not.
  if (layout.viewBox.empty()) layout.viewBox = bounds(scene.container);
  return loaded;
}

LoadedScene loadScene(const std::string& path, const SvgReadOptions& options) {
  return sceneFromDocument(readDocument(path, options));
}

LoadedScene loadScene(const std::string& path, const SceneOptions& sceneOptions, const SvgReadOptions& options) {
  LoadedScene loaded = sceneFromDocument(readDocument(path, options), sceneOptions);
  // Each distinct data-elements list is read once; its warnings are the scene's.
  std::map<std::vector<std::string>, Library> libraries;
  for (ContainerPart& part : loaded.scene.containers) {
    if (part.elementFiles.empty()) continue;
    auto found = libraries.find(part.elementFiles);
    if (found == libraries.end()) {
      std::vector<LoadedElement> elements;
      try {
        elements = loadElements(part.elementFiles, options);
      } catch (const InputError& error) {
        throw InputError(path, std::string("data-elements: ") + error.what());
      }
      for (const LoadedElement& e : elements) loaded.warnings.insert(loaded.warnings.end(), e.warnings.begin(), e.warnings.end());
      found = libraries.emplace(part.elementFiles, libraryOf(elements)).first;
    }
    part.library = found->second;
  }
  return loaded;
}

LoadedElement elementFromDocument(const SvgDocument& document) {
  LoadedElement loaded;
  ElementArt& element = loaded.element;
  element.source = document.file;
  element.name = stemOf(document.file);

  std::vector<std::size_t> artIndices;
  for (std::size_t i = 0; i < document.shapes.size(); ++i) {
    const SvgShape& shape = document.shapes[i];
    if (std::optional<ElementHandle> handle = handleOf(shape, document.file, i)) {
      for (const ElementHandle& other : element.handles)
        if (other.name == handle->name)
          throw InputError(placeOf(document.file, shape),
                           "handle \"" + handle->name + "\" is given twice (id \"" + shape.id + "\")");
      element.handles.push_back(std::move(*handle));
      continue;
    }
    const bool namedSpine = lowerCased(shape.id) == "spine";
    if (namedSpine || shape.layer == "spines" || shape.layer == "guides") {
      // The FLOWPAK spine: from its first to its last point.
      if (!element.spine && shape.layer != "guides" && !shape.subpaths.empty() &&
          shape.subpaths.front().points.size() >= 2) {
        const auto& points = shape.subpaths.front().points;
        element.spine = std::array<Vec2, 2>{points.front(), points.back()};
      }
      continue;
    }
    // A shape with neither fill nor stroke shows nothing and is no mistake: outline icon sets
    // put an invisible frame in every icon (tabler's `M0 0h24v24H0z`).
    if (!shape.fill && !shape.stroke) continue;
    element.shapes.push_back(shape);
    loaded.shapes.push_back(shape);
    artIndices.push_back(i);
  }

  const ClipOptions clip = clipOptionsFor(bounds(element.shapes));
  std::vector<Region> painted;
  std::vector<Warning>& warnings = loaded.warnings;
  warnings = document.warnings;
  for (std::size_t k = 0; k < loaded.shapes.size(); ++k) {
    const SvgShape& shape = loaded.shapes[k];
    const std::string where = document.file + ": " + shapeName(shape, artIndices[k]);
    if (shape.fill)
      for (const Subpath& subpath : shape.subpaths)
        if (!subpath.closed && subpath.points.size() >= 3) {
          warnings.push_back({where, "open path used as a fill: filled as if it were closed"});
          break;
        }
    Region region = paintedRegion(shape, clip);
    if (area(region) <= 0.0) {
      warnings.push_back({where, "path paints no area (zero-area fill, no stroke); ignored for the outline"});
      continue;
    }
    painted.push_back(std::move(region));
  }
  if (painted.empty())
    throw InputError(document.file, document.shapes.empty() ? "the element has no shapes"
                                                            : "the element paints no area (every shape has zero area "
                                                              "or no fill and no stroke)");
  element.outline = painted.size() == 1 ? painted.front() : unite(painted, clip);
  normalizeOrientation(element.outline);
  if (area(element.outline) <= 0.0) throw InputError(document.file, "the element paints no area");
  return loaded;
}

std::vector<LoadedElement> elementsFromDocument(const SvgDocument& document) {
  const std::vector<std::vector<int>> drawings = drawingsOfGroups(document);
  if (drawings.size() < 2) return {elementFromDocument(document)};

  std::vector<LoadedElement> elements;
  std::vector<std::string> failures;
  for (const std::vector<int>& groups : drawings) {
    SvgDocument part = document;
    part.shapes.clear();
    for (const SvgShape& shape : document.shapes)
      if (std::find(groups.begin(), groups.end(), shape.topGroup) != groups.end()) part.shapes.push_back(shape);
    // Named by its first group: the layer name the reader gave its shapes when they share one.
    const int group = groups.front();
    std::string name = stemOf(document.file);
    const std::string& layer = part.shapes.front().layer;
    const bool shared = !layer.empty() && std::all_of(part.shapes.begin(), part.shapes.end(), [&](const SvgShape& s) {
      return s.layer == layer || s.topGroup != group;
    });
    if (group >= 0) name = shared ? layer : name + "-" + std::to_string(group + 1);
    try {
      LoadedElement element = elementFromDocument(part);
      element.element.name = name;
      elements.push_back(std::move(element));
    } catch (const InputError& error) {
      failures.push_back(error.what());
    }
  }
  if (elements.empty())
    throw InputError(document.file, "no group paints any area" + (failures.empty() ? "" : " (" + failures.front() + ")"));
  return elements;
}

std::vector<LoadedElement> loadElements(const std::vector<std::string>& pathsOrFolders, const SvgReadOptions& options) {
  std::vector<std::string> files;
  for (const std::string& path : pathsOrFolders) {
    std::error_code error;
    if (fs::is_directory(path, error)) {
      std::vector<std::string> inFolder;
      for (const fs::directory_entry& entry : fs::directory_iterator(path, error)) {
        const std::string extension = extensionOf(entry.path().string());
        if (entry.is_regular_file(error) && (extension == ".svg" || extension == ".path"))
          inFolder.push_back(entry.path().string());
      }
      if (error) throw InputError(path, "cannot list the folder: " + error.message());
      std::sort(inFolder.begin(), inFolder.end());
      files.insert(files.end(), inFolder.begin(), inFolder.end());
    } else if (fs::exists(path, error)) {
      files.push_back(path);
    } else {
      throw InputError(path, "no such file or folder");
    }
  }
  if (files.empty()) {
    std::string where;
    for (const std::string& path : pathsOrFolders) where += (where.empty() ? "" : ", ") + path;
    throw InputError(where, "no element files found (expected .svg or .path files)");
  }
  std::vector<LoadedElement> elements;
  for (const std::string& file : files)
    for (LoadedElement& element : elementsFromDocument(readDocument(file, options))) elements.push_back(std::move(element));
  return elements;
}

Library loadLibrary(const std::vector<std::string>& pathsOrFolders, const SvgReadOptions& options) {
  Library library;
  for (LoadedElement& element : loadElements(pathsOrFolders, options)) library.push_back(std::move(element.element));
  return library;
}

Library libraryOf(const std::vector<LoadedElement>& elements) {
  Library library;
  for (const LoadedElement& element : elements) library.push_back(element.element);
  return library;
}

}  // namespace pak
