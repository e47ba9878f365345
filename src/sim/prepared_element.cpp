#include "sim/prepared_element.hpp"

#include "pak/error.hpp"

namespace pak {

PreparedElement prepareElement(const ElementArt& element, double scale, const ElementMeshOptions& meshOptions) {
  const Vec2 centre = centroid(element.outline);
  PreparedElement prepared;
  prepared.source = element.source;
  prepared.art = element.shapes;
  for (Shape& shape : prepared.art) {
    shape.strokeWidth *= scale;
    for (Subpath& sub : shape.subpaths)
      for (Vec2& p : sub.points) p = (p - centre) * scale;
  }
  prepared.outline = transformed(element.outline, scale, -centre * scale);
  try {
    prepared.mesh = buildElementMesh(prepared.art, prepared.outline, meshOptions);
  } catch (const InputError& error) {
    throw InputError(element.source, error.what());
  }
  return prepared;
}

}  // namespace pak
