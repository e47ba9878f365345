#include "pak/io/flow_drawing.hpp"

#include <cmath>
#include <string>

#include "pak/io/packing_drawing.hpp"

namespace pak {
namespace {

// Short line segments along the field on a coarse grid inside the containers, each with a
// small barb at its head so the direction reads.
DrawingGroup fieldLayer(const FlowPacking& packing, double hairline) {
  DrawingGroup group{"field", "", {}, {}, {}};
  Box box = bounds(packing.container);
  const double spacing = std::max(box.width(), box.height()) / 40.0;
  std::vector<Subpath> arrows;
  for (std::size_t k = 0; k < packing.containers.size() && k < packing.fields.size(); ++k) {
    const VectorField& field = packing.fields[k];
    if (field.values.empty()) continue;
    for (double y = box.min.y + 0.5 * spacing; y < box.max.y; y += spacing)
      for (double x = box.min.x + 0.5 * spacing; x < box.max.x; x += spacing) {
        Vec2 p{x, y};
        if (!pointInRegion(p, packing.containers[k])) continue;
        Vec2 v = field.at(p);
        if (lengthSquared(v) == 0.0) continue;
        Vec2 a = p - v * (0.35 * spacing), b = p + v * (0.35 * spacing);
        arrows.push_back({{a, b}, false});
        arrows.push_back({{b - rotated(v, 0.5) * (0.15 * spacing), b, b - rotated(v, -0.5) * (0.15 * spacing)}, false});
      }
  }
  group.shapes.push_back(strokedLines(std::move(arrows), Color{200, 40, 40, 0.8}, hairline));
  return group;
}

// An element's shapes keep the ids of the library element they copy (when libraryIndex finds
// it: same file, same shapes), made unique with the element's number: "blade-12".
void nameShapes(DrawingGroup& group, const FlowElement& e, std::size_t number, const std::vector<LoadedElement>& elements) {
  if (e.libraryIndex < 0 || e.libraryIndex >= static_cast<int>(elements.size())) return;
  const LoadedElement& original = elements[static_cast<std::size_t>(e.libraryIndex)];
  if (original.element.source != e.source || original.shapes.size() != group.shapes.size()) return;
  for (std::size_t k = 0; k < group.shapes.size(); ++k)
    if (!original.shapes[k].id.empty()) group.shapes[k].id = original.shapes[k].id + "-" + std::to_string(number);
}

}  // namespace

Drawing flowDrawing(const SceneLayout& layout, const FlowPacking& packing, const std::vector<LoadedElement>& elements,
                    const FlowDrawingOptions& options) {
  // The shared layout from a Packing that holds just the art.
  Packing view;
  view.container = packing.container;
  view.containers = packing.containers;
  view.canonicalScale = packing.canonicalScale;
  view.fixedArt = packing.fixedArt;
  for (const auto* list : {&packing.elements, &packing.gapElements})
    for (const FlowElement& e : *list) {
      PlacedElement placed;
      placed.libraryIndex = e.libraryIndex;
      placed.source = e.source;
      placed.art = e.art;
      placed.container = e.container;
      view.elements.push_back(std::move(placed));
    }
  Drawing drawing = packingDrawing(layout, view);
  DrawingGroup* drawnElements = nullptr;
  for (DrawingGroup& group : drawing.groups)
    if (group.id == "elements") drawnElements = &group;
  std::size_t k = 0;
  for (const auto* list : {&packing.elements, &packing.gapElements})
    for (const FlowElement& e : *list) {
      nameShapes(drawnElements->children[k], e, k + 1, elements);
      ++k;
    }
  if (!options.debugLayers) return drawing;

  const double hairline = 0.8 / packing.canonicalScale;
  drawing.groups.push_back(fieldLayer(packing, hairline));
  DrawingGroup streamlines{"streamlines", "", {}, {}, {}};
  std::vector<Subpath> traced;
  for (const Polyline& s : packing.streamlines) traced.push_back({s, false});
  streamlines.shapes.push_back(strokedLines(std::move(traced), Color{30, 90, 220, 0.9}, 1.5 * hairline));
  drawing.groups.push_back(std::move(streamlines));
  DrawingGroup spines{"spines", "", {}, {}, {}};
  DrawingGroup blobs{"blobs", "", {}, {}, {}};
  std::vector<Subpath> used, outlines;
  for (const FlowElement& e : packing.elements) {
    used.push_back({e.streamline, false});
    for (const Polygon& p : e.blob) {
      outlines.push_back({p.outer, true});
      for (const Ring& h : p.holes) outlines.push_back({h, true});
    }
  }
  spines.shapes.push_back(strokedLines(std::move(used), Color{0, 150, 60, 0.9}, 1.5 * hairline));
  blobs.shapes.push_back(strokedLines(std::move(outlines), Color{120, 60, 200, 0.8}, hairline));
  drawing.groups.push_back(std::move(spines));
  drawing.groups.push_back(std::move(blobs));
  return drawing;
}

}  // namespace pak
