// Shape matching (thesis 4.7) alone, as `pak pack --shape-matching` runs it: element skins,
// descriptors, salient corners, k-d tree, fit scores. The thesis took 922 ms with a 4-element
// library: here the heart (1 corner) with four animals, and the star (5 corners) with all nine
// shared animals, both sized for 27 elements.
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>

#include "pak/io/scene_loader.hpp"
#include "pak/repulsion/shape_matching.hpp"
#include "pak/sim/element_mesh.hpp"

namespace {

// Run from the repository root, as bench/run.sh does: the shared data sits beside it.
const std::string kData = "../shared/data";

void matchCornersOf(benchmark::State& state, const std::string& containerFile, const std::vector<std::string>& elements) {
  if (!std::filesystem::exists(containerFile)) {
    state.SkipWithError("shared data not found");
    return;
  }
  using namespace pak;
  Scene scene = loadScene(containerFile).scene;
  Library library = loadLibrary(elements);
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
void BM_ShapeMatchingHeartFourAnimals(benchmark::State& state) {
  const std::string animals = kData + "/repulsionpak/animals/";
  matchCornersOf(state, kData + "/repulsionpak/containers/heart.path",
                 {animals + "bear.path", animals + "bird.path", animals + "cat.path", animals + "fox.path"});
}
BENCHMARK(BM_ShapeMatchingHeartFourAnimals)->Unit(benchmark::kMillisecond);

void BM_ShapeMatchingStarNineAnimals(benchmark::State& state) {
  matchCornersOf(state, kData + "/mdi/star.svg", {kData + "/repulsionpak/animals"});
}
BENCHMARK(BM_ShapeMatchingStarNineAnimals)->Unit(benchmark::kMillisecond);

}  // namespace
