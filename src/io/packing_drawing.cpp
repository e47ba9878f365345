#include "pak/io/packing_drawing.hpp"

#include <filesystem>

#include "pak/io/tile_drawing.hpp"
#include "pak/repulsion/tiling.hpp"

namespace pak {

Drawing packingDrawing(const Scene& scene, const Packing& packing, const PackingDrawingOptions& options) {
  Drawing drawing;
  drawing.viewBox = scene.viewBox.empty() ? bounds(scene.container) : scene.viewBox;
  drawing.width = scene.width;
  drawing.height = scene.height;

  // A container drawn on a `container` layer keeps the artist's styling; a file that is a
  // container by itself (an icon, a .path outline) is drawn as an outline, or its fill
  // would hide the elements.
  DrawingGroup container{"container", "", {}, scene.containerShapes, {}};
  double outlineWidth = 1.5 / packing.canonicalScale;
  for (Shape& s : container.shapes)
    if (s.layer != "container") {
      s.stroke = s.fill ? *s.fill : (s.stroke ? *s.stroke : Color{});
      s.stroke->alpha = 1.0;
      s.fill.reset();
      s.strokeWidth = outlineWidth;
    }
  drawing.groups.push_back(std::move(container));
  // SVG input: the writer copies the artist's fixed layer as written; .path input: re-drawn.
  if (!scene.fixed.empty() || !scene.fixedMarkup.empty()) {
    DrawingGroup fixed{"fixed", "", {}, scene.fixed, {}};
    if (!scene.fixedMarkup.empty()) fixed.markup = scene.fixedMarkup;
    drawing.groups.push_back(std::move(fixed));
  }

  DrawingGroup elements{"elements", "", {}, {}, {}};
  for (const PlacedElement& e : packing.elements) {
    std::string name = std::filesystem::path(e.source).filename().string();
    elements.children.push_back({"", e.secondary ? "element secondary" : "element", {{"data-source", name}}, e.art, {}});
  }
  if (isTiled(packing.tile)) addPeriodicClones(elements, packing.tile);  // one seamless tile
  drawing.groups.push_back(std::move(elements));

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
