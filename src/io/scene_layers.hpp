#pragma once
// The layers of a scene that no method uses (a background, a title, a frame), for its outputs
// to show as the artist drew them.
#include <string>
#include <vector>

#include "pak/io/scene_layout.hpp"
#include "pak/io/svg_reader.hpp"
#include "pak/io/warning.hpp"

namespace pak {

// Every top-level group holding none of Pak's layers (container, fixed, guides, spines, holes,
// elements, nor `containerLayer`) goes to layout.layersBelow when it comes before the
// container layer in the file, else to layout.layersAbove. Pak copies such a layer as written
// and reads nothing of it, so the reader's warnings about it are dropped from `warnings`; a
// layer styled by a <style> sheet is re-drawn instead, and a group mixing Pak's layers with
// other shapes is left out, each with a warning.
void addSceneLayers(const SvgDocument& document, const std::string& containerLayer, SceneLayout& layout,
                    std::vector<Warning>& warnings);

}  // namespace pak
