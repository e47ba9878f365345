#pragma once
// FLOWPAK's output: the layout every packer shares (packing_drawing.hpp), and on request the
// debug layers `field`, `streamlines`, `spines` and `blobs` that show why each element went
// where it went.
#include "pak/flow/flow.hpp"
#include "pak/geom/scene.hpp"
#include "pak/io/drawing.hpp"

namespace pak {

struct FlowDrawingOptions {
  bool debugLayers = false;
};

Drawing flowDrawing(const Scene& scene, const FlowPacking& packing, const FlowDrawingOptions& options = {});

}  // namespace pak
