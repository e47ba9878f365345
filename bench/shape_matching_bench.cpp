// Shape matching (thesis 4.7) alone, on the thesis's setting of a 4-element library (it took
// 922 ms there): the heart container, four of the shared animals sized for 27 elements.
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>

#include "pak/element_mesh.hpp"
#include "pak/scene_loader.hpp"
#include "pak/shape_matching.hpp"

namespace {

const std::string kData = "/work/shared/data/repulsionpak";

void BM_ShapeMatchingHeartFourAnimals(benchmark::State& state) {
  if (!std::filesystem::exists(kData + "/containers/heart.path")) {
    state.SkipWithError("shared data not found");
    return;
  }
  using namespace pak;
  Scene scene = loadScene(kData + "/containers/heart.path");
  Library library = loadLibrary({kData + "/animals/bear.path", kData + "/animals/bird.path",
                                 kData + "/animals/cat.path", kData + "/animals/fox.path"});
  // The canonical frame (bounding square 1000 wide), elements sized as the packing sizes them.
  Box box = bounds(scene.container);
  const double scale = 1000.0 / std::max(box.width(), box.height());
  Region container = transformed(scene.container, scale, -box.min * scale);
  const double nominal = area(container) / 27.0;
  std::vector<Region> outlines;
  for (const ElementArt& e : library) {
    const double s = std::sqrt(nominal / area(e.outline));
    outlines.push_back(transformed(e.outline, s, -centroid(e.outline) * s));
  }
  std::size_t corners = 0;
  for (auto _ : state) {
    std::vector<Ring> skins;
    for (const Region& o : outlines) skins.push_back(elementSkin(o, 10.0, 0.5).outer);
    ShapeMatch match = matchCorners(container, skins, std::sqrt(0.6));
    corners = match.matches.size();
    benchmark::DoNotOptimize(match);
  }
  state.counters["corners"] = static_cast<double>(corners);
}
BENCHMARK(BM_ShapeMatchingHeartFourAnimals)->Unit(benchmark::kMillisecond);

}  // namespace
