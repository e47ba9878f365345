// A frame of an animated packing (thesis 5.6): slices interpolated at t, art replayed.
#include <algorithm>
#include <cmath>

#include "animation/frame_separation.hpp"
#include "animation/slice_bracket.hpp"
#include "pak/animation/animation.hpp"

namespace pak {

Packing animationFrame(const AnimatedPacking& animation, double t) {
  Packing packing;
  packing.container = animation.container;
  packing.containers = {animation.container};
  packing.fixedArt = animation.fixedArt;
  packing.canonicalScale = animation.canonicalScale;
  packing.iterations = animation.iterations;
  std::vector<Vec2> vertices, artPoints;
  double skinArea = 0.0;
  for (std::size_t e = 0; e < animation.elements.size(); ++e) {
    const AnimatedElement& element = animation.elements[e];
    const auto [s, w] = sliceBracket(element.sliceTimes, t);
    const std::vector<Vec2>& a = element.slices[s];
    const std::vector<Vec2>& b = element.slices[s + 1];
    vertices.resize(a.size());
    for (std::size_t v = 0; v < a.size(); ++v) vertices[v] = a[v] + (b[v] - a[v]) * w;
    replayArt(element.mesh, vertices.data(), artPoints);

    PlacedElement placed;
    placed.libraryIndex = static_cast<int>(e);
    placed.source = element.source;
    placed.growth = element.sliceGrowth[s] + (element.sliceGrowth[s + 1] - element.sliceGrowth[s]) * w;
    placed.meshVertices = vertices;
    placed.meshTriangles = element.mesh.mesh.triangles;
    placed.skin.assign(vertices.begin(), vertices.begin() + element.mesh.boundaryCount);
    const double areaHere = std::abs(signedArea(placed.skin)) * animation.canonicalScale * animation.canonicalScale;
    const double separation = separationScaleAt(animation, e, t);
    skinArea += areaHere * separation * separation;
    // Strokes scale with the element's linear size in this frame.
    const double strokeScale =
        element.restSkinArea > 0.0 ? std::sqrt(areaHere / element.restSkinArea) / animation.canonicalScale : 1.0;
    placed.art = element.art;
    std::size_t k = 0;
    for (Shape& shape : placed.art) {
      scaleStroke(shape, strokeScale);
      for (Subpath& sub : shape.subpaths)
        for (Vec2& p : sub.points) p = artPoints[k++];
    }
    scaleAboutCentre(placed, separation);  // frame separation (separateAnimation)
    translateElement(placed, separationShiftAt(animation, e, t));
    placed.leavesContainer = element.leavesContainer;
    placed.guided = element.guided;
    packing.elements.push_back(std::move(placed));
  }
  // An element whose loop moves it is also where it was one loop ago and will be one loop on
  // (a bird leaving on the right is entering on the left). The copies come after the
  // elements, so indices into AnimatedPacking::elements stay those of the frame.
  const std::size_t count = packing.elements.size();
  for (std::size_t e = 0; e < count; ++e) {
    const Vec2 shift = animation.elements[e].loopShift;
    if (shift.x == 0.0 && shift.y == 0.0) continue;
    for (const double side : {-1.0, 1.0}) {
      PlacedElement copy = packing.elements[e];
      const Vec2 by = shift * side;
      for (Vec2& p : copy.skin) p += by;
      for (Vec2& p : copy.meshVertices) p += by;
      for (Shape& shape : copy.art)
        for (Subpath& sub : shape.subpaths)
          for (Vec2& p : sub.points) p += by;
      packing.elements.push_back(std::move(copy));
    }
  }
  // Mirror symmetry: everything so far, reflected across the line (rings reversed, so that
  // they keep their orientation).
  if (animation.mirrorX) {
    const double m = *animation.mirrorX;
    auto reflect = [m](Vec2 p) { return Vec2{2.0 * m - p.x, p.y}; };
    const std::size_t packed = packing.elements.size();
    for (std::size_t e = 0; e < packed; ++e) {
      PlacedElement twin = packing.elements[e];
      for (Vec2& p : twin.skin) p = reflect(p);
      std::reverse(twin.skin.begin(), twin.skin.end());
      for (Vec2& p : twin.meshVertices) p = reflect(p);
      for (std::array<int, 3>& tri : twin.meshTriangles) std::swap(tri[1], tri[2]);
      for (Shape& shape : twin.art)
        for (Subpath& sub : shape.subpaths) {
          for (Vec2& p : sub.points) p = reflect(p);
          std::reverse(sub.points.begin(), sub.points.end());
        }
      packing.elements.push_back(std::move(twin));
    }
    skinArea *= 2.0;
  }
  const double containerArea = area(animation.container) * animation.canonicalScale * animation.canonicalScale;
  packing.skinFill = containerArea > 0.0 ? skinArea / containerArea : 0.0;
  return packing;
}

}  // namespace pak
