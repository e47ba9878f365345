#include "io/scene_layers.hpp"

#include <algorithm>
#include <set>

namespace pak {
namespace {

bool isPakLayer(const std::string& name, const std::string& containerLayer) {
  static const char* const names[] = {"container", "fixed", "guides", "spines", "holes", "elements"};
  return name == containerLayer || std::find(std::begin(names), std::end(names), name) != std::end(names);
}

std::string layerPlace(const SvgDocument& document, const SvgTopGroup& group) {
  return document.file + ": layer '" + group.name + "'";
}

}  // namespace

void addSceneLayers(const SvgDocument& document, const std::string& containerLayer, SceneLayout& layout,
                    std::vector<Warning>& warnings) {
  // Where the container layer starts: the first top-level group holding one of its shapes.
  int containerGroup = -1;
  for (const SvgShape& shape : document.shapes)
    if (shape.layer == containerLayer && shape.topGroup >= 0 && (containerGroup < 0 || shape.topGroup < containerGroup))
      containerGroup = shape.topGroup;
  std::set<int> copied;  // read no further: what the reader said of them no longer applies
  for (std::size_t k = 0; k < document.topGroups.size(); ++k) {
    const SvgTopGroup& group = document.topGroups[k];
    const int index = static_cast<int>(k);
    std::vector<SvgShape> shapes;
    for (const SvgShape& shape : document.shapes)
      if (shape.topGroup == index) shapes.push_back(shape);
    const bool holdsPakLayers = std::any_of(group.layers.begin(), group.layers.end(),
                                            [&](const std::string& name) { return isPakLayer(name, containerLayer); });
    if (holdsPakLayers) {
      // Pak draws its own layers; the rest of such a group has nowhere to go.
      if (std::any_of(shapes.begin(), shapes.end(), [&](const SvgShape& s) { return !isPakLayer(s.layer, containerLayer); }))
        warnings.push_back({layerPlace(document, group),
                            "holds Pak's layers and other shapes; the output leaves the others out "
                            "(give them a layer of their own)"});
      continue;
    }
    if (group.markup.empty() && shapes.empty()) continue;
    if (group.styledBySheet)
      warnings.push_back({layerPlace(document, group),
                          "styled by a <style> sheet: the output re-draws it instead of copying it"});
    if (!group.markup.empty()) copied.insert(index);
    SceneLayer layer{group.name, std::move(shapes), group.markup};
    (containerGroup >= 0 && index > containerGroup ? layout.layersAbove : layout.layersBelow).push_back(std::move(layer));
  }
  warnings.erase(std::remove_if(warnings.begin(), warnings.end(), [&](const Warning& w) { return copied.count(w.topGroup) > 0; }),
                 warnings.end());
}

}  // namespace pak
