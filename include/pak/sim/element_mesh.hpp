#pragma once
// An element prepared for simulation (thesis 4.4): its skin, triangle mesh, springs and the
// barycentric binding of its art to the mesh.
#include <array>
#include <cstdint>
#include <vector>

#include "pak/geom/art.hpp"
#include "pak/geom/polygon.hpp"
#include "pak/geom/scene.hpp"
#include "pak/geom/tri_mesh.hpp"

namespace pak {

enum class SpringKind : std::uint8_t { Edge, Shear, NegativeSpace };

struct Spring {
  int a = 0, b = 0;
  double restLength = 0.0;  // at growth factor 1
  SpringKind kind = SpringKind::Edge;
};

// Where an art vertex sits relative to the mesh: weights of the enclosing (or nearest)
// triangle's corners. Weights may be slightly negative for art just outside the mesh.
struct ArtBinding {
  int triangle = 0;
  std::array<double, 3> weights{};
};

// A linear smoothing of mesh positions (art_replay.cpp): vertex i moves to
// Σ weights[k] · x[neighbours[k]] over k in [offsets[i], offsets[i + 1]), where its
// neighbourhood's least-squares quadratic map (rest → deformed) puts it.
struct NeighbourhoodFits {
  std::vector<int> offsets;  // one per vertex, plus the end
  std::vector<int> neighbours;
  std::vector<double> weights;
};

struct ElementMeshOptions {
  double gap = 10.0;          // d_gap: the skin is the art offset outward by gap/2
  double spacing = 10.0;      // distance between boundary samples and interior points
  double arcTolerance = 0.5;  // of the skin offset
  std::uint64_t seed = 1;     // interior blue noise
  // k > 1: the vertices are placed k-fold rotationally symmetric about the origin, so that a
  // turn by a multiple of 360°/k maps the mesh's vertices onto one another (a looping
  // animation that turns a star joins each vertex to the one a turn away). Used only when the
  // skin itself has that symmetry; ElementMesh::symmetry says whether it was.
  int symmetry = 1;
};

struct ElementMesh {
  // Vertices [0, boundaryCount) are the skin ring in order (positive signed area);
  // the rest are interior points.
  TriMesh mesh;
  int boundaryCount = 0;
  std::vector<Spring> springs;
  double skinArea = 0.0;   // area enclosed by the boundary ring
  double artArea = 0.0;    // area painted by the art
  Vec2 restCentroid;       // mean of the vertices (the "centre of mass" of unit masses)
  int symmetry = 1;        // the options' symmetry if the skin had it, else 1
  // One binding per art point, in the order shapes → subpaths → points.
  std::vector<ArtBinding> bindings;
  NeighbourhoodFits smoothing;  // of the mesh's vertices, for replaySmoothArt
};

// `art` and `outline` in the frame the mesh is wanted in (Pak uses canonical units, centred).
// Throws InputError if the outline is empty.
ElementMesh buildElementMesh(const std::vector<Shape>& art, const Region& outline,
                             const ElementMeshOptions& options);

// One common scale for a library that keeps its elements' relative sizes and makes their
// mean skin area (art offset by gap/2) `nominalSkinArea`: estimated from the art areas, then
// corrected once with real skins. Throws InputError for an element that paints no area.
double librarySkinScale(const Library& library, double nominalSkinArea, double gap);

// The skin of an outline: offset by gap/2, holes filled, pieces merged into one polygon.
Polygon elementSkin(const Region& outline, double gap, double arcTolerance);

// Replays the bindings on deformed vertex positions: art points in the same order. This is the
// thesis's piecewise-linear map: it is what the simulation's own checks of the art use.
void replayArt(const ElementMesh& mesh, const Vec2* deformedVertices, std::vector<Vec2>& artPoints);

// The neighbourhood fits of a triangle mesh (each vertex's 2-ring).
NeighbourhoodFits neighbourhoodFits(const TriMesh& mesh);

// The art as drawn: the same bindings replayed on a smoothed deformation, without the kinks
// a piecewise-linear map makes at every triangle edge (art_replay.cpp). Any affine
// deformation is reproduced exactly. `linear` gives replayArt's points instead.
void replayDrawnArt(const ElementMesh& mesh, const Vec2* deformedVertices, bool linear, std::vector<Vec2>& artPoints);

}  // namespace pak
