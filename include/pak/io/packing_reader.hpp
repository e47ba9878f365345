#pragma once
// Reads any packing drawing as the geometry the metrics need: Pak's own output (a
// `container` layer and an `elements` layer of <g class="element"> groups), a third party's
// with other layer names, or, with neither layer, "the largest closed shape is the container
// and each top-level group or shape inside it is an element".
#include <string>
#include <vector>

#include "pak/io/svg_reader.hpp"
#include "pak/metrics/metrics.hpp"

namespace pak {

struct PackingReadOptions {
  std::string containerLayer = "container";  // matched lower-cased, like the reader's layers
  std::string elementsLayer = "elements";
  // What this layer paints is PackingGeometry::fixed (Pak writes fixed elements there); with
  // no container layer, its shapes are elements like any others.
  std::string fixedLayer = "fixed";
};

// Throws InputError when no container is found, there are no elements, or an element lies
// entirely outside the container.
PackingGeometry packingFromDocument(const SvgDocument& document, const PackingReadOptions& = {});
PackingGeometry readPacking(const std::string& path, const PackingReadOptions& = {});

// Unites the painted regions of shapes sharing a key (e.g. SvgShape::layerGroup: one placed
// element), in document order of first appearance; key -1 means "a shape on its own".
// Shapes that paint nothing are skipped, and so are groups of no area.
std::vector<Region> outlinesByKey(const std::vector<const Shape*>& shapes, const std::vector<int>& keys,
                                  const ClipOptions& clip);

}  // namespace pak
