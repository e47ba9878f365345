// FLOWPAK's per-placement geometry (thesis 3.3.2, 3.3.5): a blob's LR function, an element's,
// and fitting an element's width into its blob. fitWidthScale is the inner loop of the
// refinement (once per element per phase per iteration), so it must stay around a millisecond.
// The scene: a wobbly band of 2002 boundary vertices around an arc of radius 100, a
// 101-point streamline along it, and a leaf element of 300 vertices with a spine 10 long.
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include "pak/flow/lr_function.hpp"
#include "pak/flow/skeletal_stroke.hpp"

namespace {

using namespace pak;

struct FlowPlacementScene {
  Region blob, leaf;
  Polyline streamline;
  FlowPlacementScene() {
    Ring ring;
    const int n = 1000;
    for (int k = 0; k <= n; ++k) {
      double t = 1.2 * k / n, r = 112 + 2 * std::sin(37 * t);
      ring.push_back({r * std::cos(t), r * std::sin(t)});
    }
    for (int k = n; k >= 0; --k) {
      double t = 1.2 * k / n, r = 90 + 1.5 * std::sin(23 * t);
      ring.push_back({r * std::cos(t), r * std::sin(t)});
    }
    blob = {Polygon{ring, {}}};
    for (int k = 0; k <= 100; ++k) {
      double t = 0.05 + 1.1 * k / 100;
      streamline.push_back({100 * std::cos(t), 100 * std::sin(t)});
    }
    Ring outline;
    for (int k = 0; k < 300; ++k) {
      double t = 2 * std::numbers::pi * k / 300;
      outline.push_back({5 - 5 * std::cos(t), 1.5 * std::sin(t) * (1 + 0.3 * std::cos(t))});
    }
    leaf = {Polygon{outline, {}}};
  }
};

const FlowPlacementScene& scene() {
  static const FlowPlacementScene s;
  return s;
}

void BM_BlobLRFunction(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(blobLRFunction(scene().blob, scene().streamline, 100));
}
BENCHMARK(BM_BlobLRFunction)->Unit(benchmark::kMillisecond);

void BM_ElementLRFunction(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(elementLRFunction(scene().leaf, {0, 0}, {10, 0}, 100));
}
BENCHMARK(BM_ElementLRFunction)->Unit(benchmark::kMillisecond);

void BM_FitWidthScale(benchmark::State& state) {
  StrokeFrame frame = strokeFrameFor(scene().leaf, {0, 0}, {10, 0}, 0.05);
  frame.reflection = Reflection::AcrossSpine;
  double scale = 0.0;
  for (auto _ : state) {
    scale = fitWidthScale(scene().leaf, frame, scene().streamline, scene().blob, 0.05, 50.0);
    benchmark::DoNotOptimize(scale);
  }
  state.counters["widthScale"] = scale;
}
BENCHMARK(BM_FitWidthScale)->Unit(benchmark::kMillisecond);

}  // namespace
