// A RepulsionPak packing as the geometry the metrics measure.
#include "pak/metrics/packing_geometry.hpp"

#include "pak/repulsion/repulsion.hpp"

namespace pak {

PackingGeometry packingGeometry(const Packing& packing, const std::string& source) {
  PackingGeometry geometry;
  geometry.source = source;
  geometry.container = packing.container;
  geometry.elements = artOutlines(packing);
  geometry.fixed = packing.fixedArt;
  return geometry;
}

}  // namespace pak
