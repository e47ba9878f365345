#pragma once
// Folded elements, shared by both simulators: where an element's art, replayed on its deformed
// mesh, crosses itself (a limb pressed across its own body), and the schedule that relaxes the
// mesh toward its best-fit rest shape until it no longer does.
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "pak/geom/best_fit_rotation.hpp"
#include "pak/geom/polygon.hpp"
#include "sim/prepared_element.hpp"

namespace pak {

// Appends a crossing point of every filled ring of `element`'s art, replayed on `vertices`, that
// crosses itself where the ring as drawn does not (petals drawn as one ring are no fold).
// `artPoints` and `ring` are scratch.
void appendArtFolds(const PreparedElement& element, const Vec2* vertices, std::vector<Vec2>& folds,
                    std::vector<Vec2>& artPoints, Ring& ring);

// Moves each of `count` positions toward the rest shape's best rigid fit at `scale` (the rest
// offsets scaled, turned by the weighted least-squares rotation, about the weighted centre), to
// `keep` of the way from it at `around` and less farther out, to none at `radius`; an infinite
// radius moves all of them fully, and keep 0 then gives the rest shape. moved(v) is called for
// every position that moved.
template <class Moved>
void blendTowardRest(Vec2* positions, const Vec2* rest, int count, double scale, double keep, Vec2 around,
                     double radius, Moved&& moved) {
  auto weight = [&](int v) {  // 1 at `around`, falling to 0 at the radius
    return std::isinf(radius) ? 1.0 : std::max(0.0, 1.0 - distance(positions[v], around) / radius);
  };
  Vec2 centre, restMean;
  double total = 0.0;
  for (int v = 0; v < count; ++v) {
    const double w = weight(v);
    centre += positions[v] * w;
    restMean += rest[v] * w;
    total += w;
  }
  if (!(total > 0.0)) return;
  centre = centre / total;
  restMean = restMean / total;
  BestFitRotation fit;
  for (int v = 0; v < count; ++v) fit.add(rest[v] - restMean, positions[v] - centre, weight(v));
  const Vec2 turn = fit.turn();
  for (int v = 0; v < count; ++v) {
    const double w = weight(v);
    if (w == 0.0) continue;
    const Vec2 target = centre + rotated((rest[v] - restMean) * scale, turn);
    positions[v] += (target - positions[v]) * (w * (1.0 - keep));
    moved(v);
  }
}

// One folded mesh's relaxation: around the crossing first, in widening patches (× `cell`, the
// neighbour search's reach), each time a quarter of the way back; then the whole mesh, halfway
// and at last all the way. firstFold() is the mesh's first crossing now, if any;
// restore(keep, around, radius) is blendTowardRest on it. Returns whether it moved the mesh.
template <class FirstFold, class Restore>
bool relaxFold(double cell, FirstFold&& firstFold, Restore&& restore) {
  constexpr double kPatches[] = {1.5, 2.0, 3.0, 4.5};
  constexpr int kSteps = 6;
  bool moved = false;
  for (int step = 0; step < kSteps; ++step) {
    const std::optional<Vec2> at = firstFold();
    if (!at) break;
    if (step < 4) restore(0.25, *at, kPatches[step] * cell);
    else restore(step == 4 ? 0.5 : 0.0, *at, std::numeric_limits<double>::infinity());
    moved = true;
  }
  return moved;
}

}  // namespace pak
