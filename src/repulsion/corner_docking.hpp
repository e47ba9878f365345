#pragma once
// Shape-matched placement (thesis 4.7) applied to a packing run: the elements that fit the
// container's salient corners best replace the random seeds nearest to those corners, start
// with their matched tip on the corner, and are held there by docking springs.
#include <vector>

#include "pak/repulsion/shape_matching.hpp"
#include "pak/sim/element_mesh.hpp"
#include "repulsion/packing_simulation.hpp"
#include "repulsion/seeding.hpp"
#include "sim/region_index.hpp"

namespace pak {

class CornerDocking {
 public:
  // `meshes[t]` and `outlines[t]` are element type t as prepared for the simulation (canonical
  // units, outline centred as the mesh); the library is sized so that the mean skin area is
  // the nominal one. Matches, then rewrites the type and angle of the seeds it takes over.
  CornerDocking(const Region& container, const std::vector<const ElementMesh*>& meshes,
                const std::vector<const Region*>& outlines, double gap, std::vector<Seed>& seeds,
                const ShapeMatchingOptions& options = {});

  // Puts the docked seeds' tip vertices on their corners at growth g, each slid inward along
  // its corner's bisector just far enough for the whole skin to be inside the container.
  void position(double growth, const RegionIndex& container, std::vector<Seed>& seeds) const;
  // One spring per docked element, from its tip vertex to its corner. Mesh i is seed i.
  std::vector<PackingSimulation::Dock> docks(const PackingSimulation& simulation) const;

  const ShapeMatch& match() const { return match_; }
  int dockedCount() const { return static_cast<int>(docked_.size()); }

 private:
  struct Docked {
    int seed = 0;       // which seed (and so which simulation mesh) it took over
    int tipVertex = 0;  // skin vertex nearest the matched descriptor's centre point
    Vec2 corner, inward;
  };
  std::vector<const ElementMesh*> meshes_;
  ShapeMatch match_;
  std::vector<Docked> docked_;
};

}  // namespace pak
