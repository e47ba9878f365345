#include "sim/fold_relaxation.hpp"

#include "pak/geom/verify.hpp"

namespace pak {

void appendArtFolds(const PreparedElement& element, const Vec2* vertices, std::vector<Vec2>& folds,
                    std::vector<Vec2>& artPoints, Ring& ring) {
  replayArt(element.mesh, vertices, artPoints);
  std::size_t k = 0;
  for (const Shape& shape : element.art)
    for (const Subpath& sub : shape.subpaths) {
      ring.assign(artPoints.begin() + static_cast<std::ptrdiff_t>(k),
                  artPoints.begin() + static_cast<std::ptrdiff_t>(k + sub.points.size()));
      k += sub.points.size();
      if (!shape.fill) continue;
      if (const auto crossing = ringSelfCrossing(ring); crossing && !ringSelfIntersects(sub.points))
        folds.push_back(*crossing);
    }
}

}  // namespace pak
