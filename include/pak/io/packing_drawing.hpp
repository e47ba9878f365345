#pragma once
// The output layout every packer shares: <g id="container">, <g id="fixed"> when present,
// <g id="elements"> with one <g class="element" data-source="…"> per placed element, and the
// debug layers <g id="skins">, <g id="meshes"> on request; the scene's other layers as drawn,
// under the container or over the elements.
#include "pak/io/drawing.hpp"
#include "pak/io/scene_layout.hpp"
#include "pak/sim/packing.hpp"

namespace pak {

struct PackingDrawingOptions {
  bool debugLayers = false;
};

// `packing` drawn on its scene's layout (LoadedScene::layout).
Drawing packingDrawing(const SceneLayout& layout, const Packing& packing, const PackingDrawingOptions& options = {});

}  // namespace pak
