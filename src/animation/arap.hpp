#pragma once
// As-rigid-as-possible shape manipulation (Igarashi, Moscovich & Hughes 2005), which
// AnimationPak uses to animate an element's mesh from a few handle trajectories (thesis
// 5.3.2): step one finds the positions that keep every triangle as similar as possible to its
// rest shape; step two fits a rotation per triangle and keeps edge lengths. Both are sparse
// least-squares problems whose matrices depend only on the mesh and the handle set, so they
// are factorised once (Eigen) and each deformation is two back-substitutions.
#include <memory>
#include <vector>

#include "pak/geom/tri_mesh.hpp"

namespace pak {

class ArapDeformation {
 public:
  // `handles`: indices of the constrained vertices (at least one; duplicates are an error).
  ArapDeformation(const TriMesh& rest, std::vector<int> handles);
  ~ArapDeformation();
  ArapDeformation(ArapDeformation&&) noexcept;
  ArapDeformation& operator=(ArapDeformation&&) noexcept;

  // All vertex positions with handle i at handlePositions[i]. With every handle at its rest
  // position this returns the rest mesh; with one handle the mesh translates rigidly.
  void deform(const std::vector<Vec2>& handlePositions, std::vector<Vec2>& out) const;

  const std::vector<int>& handles() const { return handles_; }

 private:
  struct Solver;
  std::vector<int> handles_;
  std::unique_ptr<Solver> solver_;
};

}  // namespace pak
