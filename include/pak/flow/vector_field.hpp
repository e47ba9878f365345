#pragma once
// A smooth unit-vector field over the containers, interpolated from the tangents of the
// artist's direction guides (thesis 3.3.3: a 1-RoSy field in the manner of Palacios & Zhang
// [PZ07], solved as a Laplacian-smooth interpolation on a grid with the guide tangents as
// constraints). Fixed elements do not influence it.
#include <vector>

#include "pak/geom/box.hpp"
#include "pak/geom/polygon.hpp"

namespace pak {

struct VectorFieldOptions {
  // Distance between guide samples whose tangents constrain the field (thesis: 0.005 l_canvas).
  double sampleSpacing = 1.0;
  // Grid cells along the longer side of the containers' bounds.
  int resolution = 256;
};

// Unit vectors at the centres of a regular grid (row-major, sample (i, j) at
// origin + ((i + 0.5) cell, (j + 0.5) cell)); the grid covers the containers with a margin.
struct VectorField {
  Vec2 origin;
  double cell = 1.0;
  int nx = 0, ny = 0;
  std::vector<Vec2> values;

  // Bilinear interpolation clamped at the grid's border, renormalised to unit length
  // (the zero vector only where the interpolated vector vanishes).
  Vec2 at(Vec2 p) const;
  // One classical Runge–Kutta (RK4) step of length `step` along the field (`step` < 0 goes
  // against it). Returns p itself when the field vanishes there.
  Vec2 advance(Vec2 p, double step) const;
};

// Throws InputError when there is no guide with at least two distinct points.
VectorField buildVectorField(const Region& containers, const std::vector<Polyline>& guides,
                             const VectorFieldOptions& options = {});

}  // namespace pak
