#include "sim/prepared_element.hpp"

#include "pak/error.hpp"
#include "pak/geom/hairline_cusps.hpp"

namespace pak {

PreparedElement prepareElement(const ElementArt& element, double scale, const ElementMeshOptions& meshOptions) {
  const Vec2 centre = centroid(element.outline);
  PreparedElement prepared;
  prepared.source = element.source;
  prepared.art = element.shapes;
  for (Shape& shape : prepared.art) {
    scaleStroke(shape, scale);
    for (Subpath& sub : shape.subpaths)
      for (Vec2& p : sub.points) p = (p - centre) * scale;
  }
  // A cusp drawn as a hairline (the MDI rabbit's ear touching its head) would cross itself as
  // soon as the mesh bends; a fifth of a canonical unit is below a pixel at 1000 px.
  constexpr double kHairlineWidth = 0.2;
  removeHairlineCusps(prepared.art, kHairlineWidth);
  prepared.outline = transformed(element.outline, scale, -centre * scale);
  try {
    prepared.mesh = buildElementMesh(prepared.art, prepared.outline, meshOptions);
  } catch (const InputError& error) {
    throw InputError(element.source, error.what());
  }
  return prepared;
}

}  // namespace pak
