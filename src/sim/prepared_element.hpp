#pragma once
// A library element as the simulators take it: its art and outline scaled into canonical units
// about the outline's centroid, and the mass-spring mesh built around its skin (thesis 4.4).
// RepulsionPak and AnimationPak prepare their libraries alike.
#include <string>
#include <vector>

#include "pak/geom/art.hpp"
#include "pak/geom/scene.hpp"
#include "pak/sim/element_mesh.hpp"

namespace pak {

struct PreparedElement {
  std::string source;
  std::vector<Shape> art;  // canonical units, centred on the outline's centroid
  Region outline;          // likewise
  ElementMesh mesh;
};

// `scale`: canonical units per input unit (librarySkinScale). Mesh errors name the element's file.
PreparedElement prepareElement(const ElementArt& element, double scale, const ElementMeshOptions& meshOptions);

}  // namespace pak
