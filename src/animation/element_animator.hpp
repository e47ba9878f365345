#pragma once
// The scripted, in-place animation of one element's slice mesh (thesis 5.3.2): handle
// trajectories drive an as-rigid-as-possible deformation of the mesh, then the transform
// track scales, rotates and moves it about the mesh's own origin.
#include <optional>
#include <vector>

#include "animation/arap.hpp"
#include "pak/animation/animation_script.hpp"
#include "pak/geom/scene.hpp"
#include "pak/geom/tri_mesh.hpp"

namespace pak {

class ElementAnimator {
 public:
  // `mesh`: the slice mesh at rest, in the frame the shapes are wanted in. Element-file
  // coordinates (handles, translation track) map to it by (p − fileOrigin) × fileScale.
  // `periodic`: the animation loops, so its tracks are sampled as loops.
  // Throws InputError when the animation names a handle the element does not have.
  ElementAnimator(const TriMesh& mesh, const std::vector<ElementHandle>& handles, const ElementAnimation& animation,
                  Vec2 fileOrigin, double fileScale, bool periodic);

  // The mesh's vertex positions at time t ∈ [0, 1]. The y axis points down (SVG), so a
  // positive rotation turns counter-clockwise on screen.
  void shapeAt(double t, std::vector<Vec2>& out) const;

 private:
  std::vector<Vec2> rest_;
  ElementAnimation animation_;  // translation converted to mesh units
  std::vector<Vec2> handleRest_;  // mesh units, one per animation handle track
  std::optional<ArapDeformation> arap_;
  bool periodic_ = false;
};

}  // namespace pak
