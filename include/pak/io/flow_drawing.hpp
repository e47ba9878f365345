#pragma once
// FLOWPAK's output: the layout every packer shares (packing_drawing.hpp), and on request the
// debug layers `field`, `streamlines`, `spines` and `blobs` that show why each element went
// where it went.
#include <vector>

#include "pak/flow/flow.hpp"
#include "pak/io/drawing.hpp"
#include "pak/io/scene_layout.hpp"
#include "pak/io/scene_loader.hpp"

namespace pak {

struct FlowDrawingOptions {
  bool debugLayers = false;
};

// `packing` drawn on its scene's layout (LoadedScene::layout). Unlike RepulsionPak's, FLOWPAK's
// output gives every copy of an element the SVG ids of its file's shapes: `elements` is the
// library packFlow took, as read (loadElements); an element whose FlowElement::libraryIndex
// does not lead to its own file there (an element of a container's own library) gets none.
Drawing flowDrawing(const SceneLayout& layout, const FlowPacking& packing, const std::vector<LoadedElement>& elements,
                    const FlowDrawingOptions& options = {});

}  // namespace pak
