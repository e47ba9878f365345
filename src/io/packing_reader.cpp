#include "pak/io/packing_reader.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <vector>

#include "pak/error.hpp"
#include "pak/geom/art.hpp"
#include "pak/geom/clipping.hpp"
#include "pak/io/scene_loader.hpp"

namespace pak {
namespace {

std::string lowerCased(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

// Boolean-operation grid relative to the document, as the scene loader does, so drawings in
// millimetres and in thousands of units resolve alike.
ClipOptions clipFor(const Box& box) {
  ClipOptions clip;
  const double extent = box.empty() ? 0.0 : std::max(box.width(), box.height());
  if (extent > 0) clip.precision = std::min(clip.precision, extent * 1e-7);
  return clip;
}

bool hasClosedSubpath(const SvgShape& shape) {
  for (const Subpath& subpath : shape.subpaths)
    if (subpath.closed && subpath.points.size() >= 3) return true;
  return false;
}

bool hasLayer(const SvgDocument& document, const std::string& name) {
  return std::find(document.layers.begin(), document.layers.end(), name) != document.layers.end();
}

}  // namespace

// Unites the painted regions of shapes sharing a key, in document order of first appearance;
// key -1 means "a shape on its own".
std::vector<Region> outlinesByKey(const std::vector<const Shape*>& shapes, const std::vector<int>& keys,
                                  const ClipOptions& clip) {
  std::vector<std::vector<Region>> grouped;
  std::map<int, std::size_t> slot;
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    Region painted = paintedRegion(*shapes[i], clip);
    if (painted.empty()) continue;  // invisible art paints nothing: not an element
    if (keys[i] < 0 || !slot.count(keys[i])) {
      if (keys[i] >= 0) slot[keys[i]] = grouped.size();
      grouped.emplace_back();
    }
    grouped[keys[i] < 0 ? grouped.size() - 1 : slot[keys[i]]].push_back(std::move(painted));
  }
  std::vector<Region> outlines;
  for (auto& regions : grouped) {
    Region outline = regions.size() == 1 ? regions.front() : unite(regions, clip);
    if (area(outline) > 0.0) outlines.push_back(std::move(outline));
  }
  return outlines;
}

namespace {

// Pak's layout or named layers: the container layer minus any `holes` layer; one element per
// child group of the elements layer (a shape directly in the layer is an element by itself);
// the fixed layer's paint as the fixed art.
PackingGeometry fromLayers(const SvgDocument& document, const PackingReadOptions& options, const ClipOptions& clip) {
  PackingGeometry packing;
  packing.source = document.file;
  std::vector<Region> containerParts, holes, fixed;
  std::vector<const Shape*> elementShapes;
  std::vector<int> keys;
  for (const SvgShape& shape : document.shapes) {
    if (shape.layer == options.containerLayer) containerParts.push_back(filledRegion(shape, clip));
    else if (shape.layer == "holes") holes.push_back(filledRegion(shape, clip));
    else if (shape.layer == options.fixedLayer) fixed.push_back(paintedRegion(shape, clip));
    else if (shape.layer == options.elementsLayer) {
      elementShapes.push_back(&shape);
      keys.push_back(shape.layerGroup);
    }
  }
  packing.container = unite(containerParts, clip);
  if (!holes.empty()) packing.container = subtract(packing.container, unite(holes, clip), clip);
  if (area(packing.container) <= 0.0)
    throw InputError(document.file, "no container found: the '" + options.containerLayer + "' layer encloses no area");
  if (!hasLayer(document, options.elementsLayer))
    throw InputError(document.file, "no elements found: the file has no '" + options.elementsLayer +
                                        "' layer (name it with --elements-layer)");
  packing.elements = outlinesByKey(elementShapes, keys, clip);
  if (!fixed.empty()) packing.fixed = unite(fixed, clip);
  return packing;
}

// Third-party drawings without layers: the largest closed shape is the container; every other
// shape belongs to the element of its top-level group. When the container itself sits in a
// top-level group (an editor's wrapper layer), that group's child groups are the elements.
PackingGeometry fromLargestShape(const SvgDocument& document, const ClipOptions& clip) {
  PackingGeometry packing;
  packing.source = document.file;
  const SvgShape* container = nullptr;
  double best = 0.0;
  for (const SvgShape& shape : document.shapes) {
    if (!hasClosedSubpath(shape)) continue;
    Region region = filledRegion(shape, clip);
    double a = area(region);
    if (a > best) {
      best = a;
      container = &shape;
      packing.container = std::move(region);
    }
  }
  if (!container)
    throw InputError(document.file, "no container found: no container layer and no closed shape "
                                        "(name the layer with --container-layer)");
  std::vector<const Shape*> shapes;
  std::vector<int> keys;
  const bool wrapped = container->topGroup >= 0;
  for (const SvgShape& shape : document.shapes) {
    if (&shape == container) continue;
    if (shape.layer == "guides" || shape.layer == "spines" || shape.layer == "holes") continue;
    shapes.push_back(&shape);
    keys.push_back(wrapped && shape.topGroup == container->topGroup ? shape.layerGroup
                   : shape.topGroup >= 0                            ? 1000000 + shape.topGroup
                                                                    : -1);
  }
  packing.elements = outlinesByKey(shapes, keys, clip);
  return packing;
}

}  // namespace

PackingGeometry packingFromDocument(const SvgDocument& document, const PackingReadOptions& rawOptions) {
  PackingReadOptions options{lowerCased(rawOptions.containerLayer), lowerCased(rawOptions.elementsLayer),
                             lowerCased(rawOptions.fixedLayer)};
  if (document.shapes.empty()) throw InputError(document.file, "no usable shape in the packing");
  const Box box = document.viewBox.empty() ? bounds(document.shapes) : document.viewBox;
  const ClipOptions clip = clipFor(box);
  PackingGeometry packing = hasLayer(document, options.containerLayer) ? fromLayers(document, options, clip)
                                                                       : fromLargestShape(document, clip);
  normalizeOrientation(packing.container);
  if (packing.elements.empty()) throw InputError(document.file, "no elements found inside the container");
  // An element with no area inside the container is not part of this packing: most likely
  // the wrong container or a misplaced layer, so say so instead of measuring nonsense.
  const double containerArea = area(packing.container);
  for (std::size_t i = 0; i < packing.elements.size(); ++i) {
    normalizeOrientation(packing.elements[i]);
    if (area(intersect(packing.elements[i], packing.container, clip)) <= 1e-9 * containerArea)
      throw InputError(document.file, "element " + std::to_string(i + 1) + " of " +
                                          std::to_string(packing.elements.size()) +
                                          " lies entirely outside the container");
  }
  return packing;
}

PackingGeometry readPacking(const std::string& path, const PackingReadOptions& options) {
  return packingFromDocument(readDocument(path), options);
}

}  // namespace pak
