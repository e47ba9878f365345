#include "io/drawing_layers.hpp"

#include <algorithm>
#include <cstddef>
#include <map>
#include <numeric>
#include <set>

namespace pak {
namespace {

double boxArea(const Box& box) { return box.empty() ? 0.0 : box.width() * box.height(); }

// The box of what a shape paints; empty for a shape with neither fill nor stroke (such as the
// invisible 24 × 24 frame that outline icon sets put in every icon).
Box paintedBox(const SvgShape& shape) {
  const bool painted = shape.fill || (shape.stroke && shape.strokeWidth > 0.0);
  return painted ? bounds(shape) : Box{};
}

// Overlapping or touching boxes; touching within a rounding error of their size, because
// abutting shapes placed by transforms meet only to the last bits.
bool overlapAsLayers(const Box& a, const Box& b) {
  if (boxArea(a) <= 0.0 || boxArea(b) <= 0.0) return false;
  const double slack = 1e-6 * std::max({a.width(), a.height(), b.width(), b.height()});
  return a.min.x <= b.max.x + slack && b.min.x <= a.max.x + slack && a.min.y <= b.max.y + slack &&
         b.min.y <= a.max.y + slack;
}

}  // namespace

std::vector<std::vector<int>> drawingsOfGroups(const SvgDocument& document) {
  std::map<int, Box> boxes;  // by topGroup, -1 first
  for (const SvgShape& shape : document.shapes) boxes[shape.topGroup].add(paintedBox(shape));
  std::vector<int> groups;
  std::vector<Box> groupBoxes;
  for (const auto& [group, box] : boxes) {
    groups.push_back(group);
    groupBoxes.push_back(box);
  }
  auto isInkscapeLayer = [&](std::size_t i) {
    const int group = groups[i];
    return group >= 0 && static_cast<std::size_t>(group) < document.inkscapeLayers.size() &&
           document.inkscapeLayers[static_cast<std::size_t>(group)];
  };

  // Union-find over the groups: each joins the drawing of every group it is a layer with.
  std::vector<std::size_t> parent(groups.size());
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  auto root = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (std::size_t i = 0; i < groups.size(); ++i)
    for (std::size_t j = i + 1; j < groups.size(); ++j) {
      const bool layers = (isInkscapeLayer(i) && isInkscapeLayer(j) && boxArea(groupBoxes[i]) > 0.0 &&
                           boxArea(groupBoxes[j]) > 0.0) ||
                          overlapAsLayers(groupBoxes[i], groupBoxes[j]);
      if (layers) parent[root(j)] = root(i);
    }

  // One drawing: the groups that paint nothing (a spine layer, a handle) belong to it too.
  std::set<std::size_t> paintingDrawings;
  for (std::size_t i = 0; i < groups.size(); ++i)
    if (boxArea(groupBoxes[i]) > 0.0) paintingDrawings.insert(root(i));
  if (paintingDrawings.size() <= 1) return {groups};

  std::vector<std::vector<int>> drawings;
  std::map<std::size_t, std::size_t> drawingOfRoot;
  for (std::size_t i = 0; i < groups.size(); ++i) {
    const auto [found, added] = drawingOfRoot.emplace(root(i), drawings.size());
    if (added) drawings.emplace_back();
    drawings[found->second].push_back(groups[i]);
  }
  return drawings;
}

}  // namespace pak
