#include "repulsion/corner_docking.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pak {

namespace {

// The thesis sizes every element to area 0.6 A_c / n_e for matching; Pak's library is scaled
// so that the mean skin area is A_c / n_e, so √0.6 gives that size on average while keeping
// the library's relative sizes, which the packing also keeps.
constexpr double kMatchAreaFraction = 0.6;

Vec2 restOffset(const ElementMesh& mesh, int vertex) { return mesh.mesh.vertices[vertex] - mesh.restCentroid; }

}  // namespace

CornerDocking::CornerDocking(const Region& container, const std::vector<const ElementMesh*>& meshes,
                             const std::vector<const Region*>& outlines, double gap, std::vector<Seed>& seeds,
                             const ShapeMatchingOptions& options)
    : meshes_(meshes) {
  // Skins in the mesh frame (relative to the rest centroid, as the simulation places them).
  std::vector<Ring> skins;
  for (std::size_t t = 0; t < meshes.size(); ++t) {
    Ring skin = elementSkin(*outlines[t], gap, 0.5).outer;
    for (Vec2& p : skin) p -= meshes[t]->restCentroid;
    skins.push_back(std::move(skin));
  }
  match_ = matchCorners(container, skins, std::sqrt(kMatchAreaFraction), options);

  std::vector<bool> taken(seeds.size(), false);
  for (const CornerMatch& m : match_.matches) {
    const SalientCorner& corner = match_.corners[m.corner];
    int nearest = -1;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t s = 0; s < seeds.size(); ++s)
      if (!taken[s] && distance(seeds[s].position, corner.position) < best) {
        best = distance(seeds[s].position, corner.position);
        nearest = static_cast<int>(s);
      }
    if (nearest < 0) break;  // more corners than seeds
    taken[nearest] = true;
    const ElementMesh& mesh = *meshes[m.element];
    int tip = 0;
    for (int k = 1; k < mesh.boundaryCount; ++k)
      if (distance(restOffset(mesh, k), m.elementTip) < distance(restOffset(mesh, tip), m.elementTip)) tip = k;
    seeds[nearest].type = m.element;
    seeds[nearest].angle = m.angle;
    docked_.push_back({nearest, tip, corner.position, corner.inward});
  }
}

void CornerDocking::position(double growth, const RegionIndex& container, std::vector<Seed>& seeds) const {
  for (const Docked& d : docked_) {
    Seed& seed = seeds[d.seed];
    const ElementMesh& mesh = *meshes_[seed.type];
    const Vec2 tip = rotated(restOffset(mesh, d.tipVertex), seed.angle) * growth;
    double radius = 0.0;
    for (int k = 0; k < mesh.boundaryCount; ++k) radius = std::max(radius, length(restOffset(mesh, k)));
    // Slide in by small steps (a fraction of a mesh edge) until no skin vertex is outside.
    const double step = std::max(1e-3, 0.02 * radius * growth);
    for (double slide = 0.0; slide <= 2.0 * radius * growth; slide += step) {
      seed.position = d.corner + d.inward * slide - tip;
      bool inside = true;
      for (int k = 0; k < mesh.boundaryCount && inside; ++k)
        inside = container.query(seed.position + rotated(restOffset(mesh, k), seed.angle) * growth, false).inside;
      if (inside) break;
    }
  }
}

std::vector<PackingSimulation::Dock> CornerDocking::docks(const PackingSimulation& simulation) const {
  std::vector<PackingSimulation::Dock> docks;
  for (const Docked& d : docked_)
    docks.push_back({simulation.meshes()[d.seed].vertexBegin + d.tipVertex, d.corner});
  return docks;
}

}  // namespace pak
