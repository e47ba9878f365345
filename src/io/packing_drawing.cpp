#include "pak/io/packing_drawing.hpp"

#include <filesystem>

#include "pak/io/tile_drawing.hpp"
#include "pak/repulsion/tiling.hpp"

namespace pak {
namespace {

// A scene's own layer: copied as written (the PNG previews draw what Pak read of it), else
// re-drawn as a layer of the same name.
DrawingGroup sceneLayerGroup(const SceneLayer& layer) {
  DrawingGroup group;
  group.shapes = drawnShapes(layer.shapes);
  if (!layer.markup.empty()) {
    group.markup = layer.markup;
    group.markupReplacesGroup = true;
  } else if (!layer.name.empty()) {
    group.attributes = {{"inkscape:groupmode", "layer"}, {"inkscape:label", layer.name}};
  }
  return group;
}

}  // namespace

Drawing packingDrawing(const SceneLayout& layout, const Packing& packing, const PackingDrawingOptions& options) {
  Drawing drawing;
  drawing.viewBox = layout.viewBox;
  drawing.width = layout.width;
  drawing.height = layout.height;
  drawing.widthText = layout.widthText;
  drawing.heightText = layout.heightText;
  for (const SceneLayer& layer : layout.layersBelow) drawing.groups.push_back(sceneLayerGroup(layer));

  // A container shape that keeps its paint is drawn as the artist styled it; the others are
  // drawn as outlines, or their fill would hide the elements.
  DrawingGroup container{"container", "", {}, {}, {}};
  const double outlineWidth = 1.5 / packing.canonicalScale;
  for (const ContainerShape& shape : layout.containerShapes) {
    DrawnShape drawn{shape.shape, shape.shape.id};
    if (!shape.keepsPaint) {
      drawn.stroke = drawn.fill ? *drawn.fill : (drawn.stroke ? *drawn.stroke : Color{});
      drawn.stroke->alpha = 1.0;
      drawn.fill.reset();
      drawn.strokeWidth = outlineWidth;
    }
    container.shapes.push_back(std::move(drawn));
  }
  drawing.groups.push_back(std::move(container));
  // SVG input: the writer copies the artist's fixed layer as written; .path input: re-drawn.
  if (!layout.fixedShapes.empty() || !layout.fixedMarkup.empty()) {
    DrawingGroup fixed{"fixed", "", {}, drawnShapes(layout.fixedShapes), {}};
    if (!layout.fixedMarkup.empty()) fixed.markup = layout.fixedMarkup;
    drawing.groups.push_back(std::move(fixed));
  }

  DrawingGroup elements{"elements", "", {}, {}, {}};
  for (const PlacedElement& e : packing.elements) {
    std::string name = std::filesystem::path(e.source).filename().string();
    elements.children.push_back({"", e.secondary ? "element secondary" : "element", {{"data-source", name}}, drawnShapes(e.art), {}});
  }
  if (isTiled(packing.tile)) addPeriodicClones(elements, packing.tile);  // one seamless tile
  drawing.groups.push_back(std::move(elements));
  for (const SceneLayer& layer : layout.layersAbove) drawing.groups.push_back(sceneLayerGroup(layer));

  if (options.debugLayers) {
    // Line widths relative to the canonical frame so they read at any input scale.
    double hairline = 0.6 / packing.canonicalScale;
    DrawingGroup skins{"skins", "", {}, {}, {}};
    DrawingGroup meshes{"meshes", "", {}, {}, {}};
    for (const PlacedElement& e : packing.elements) {
      skins.shapes.push_back(strokedLines({Subpath{e.skin, true}}, Color{0, 120, 255, 0.9}, hairline));
      std::vector<Subpath> triangles;
      for (const auto& t : e.meshTriangles)
        triangles.push_back({{e.meshVertices[t[0]], e.meshVertices[t[1]], e.meshVertices[t[2]]}, true});
      meshes.shapes.push_back(strokedLines(std::move(triangles), Color{60, 60, 60, 0.6}, hairline * 0.5));
    }
    drawing.groups.push_back(std::move(skins));
    drawing.groups.push_back(std::move(meshes));
  }
  return drawing;
}

}  // namespace pak
