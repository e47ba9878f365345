// The art as drawn on a deformed mesh. The thesis replays each art point with its triangle's
// barycentric weights, a piecewise-linear map: its gradient jumps at every triangle edge, so a
// smooth curve comes out with a small kink wherever it crosses one, and the mesh's
// vertex-to-vertex jitter shows as wobble. Fitted Béziers then need several times the points
// the art was drawn with (docs/repulsionpak.md, "Smooth art and editable curves"). Here the
// deformation is first smoothed, each vertex moved to where the least-squares quadratic map
// (rest → deformed) of its 2-ring puts it (twice), then interpolated with Phong deformation
// (James 2020: each corner's affine map, the vertex position plus its averaged gradient,
// blended with the barycentric weights), which is smooth across triangle edges to first order.
// The smoothing keeps any quadratic deformation (a bend) exactly, and both steps any affine
// one, so only the mesh-scale wobble goes and the art keeps its area.
#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "pak/sim/element_mesh.hpp"

namespace pak {
namespace {

// Rounds of neighbourhood smoothing, each reaching two rings further. One takes the demo's
// fitted curves from 6,629–7,043 points to 4,346–4,538 (seeds 1–5, at 654650a), two to
// 4,142–4,496.
constexpr int kSmoothingRounds = 2;

// A 2 × 2 matrix, row-major: a deformation gradient.
struct Gradient {
  double xx = 0.0, xy = 0.0, yx = 0.0, yy = 0.0;
  Vec2 apply(Vec2 d) const { return {xx * d.x + xy * d.y, yx * d.x + yy * d.y}; }
};

// Each vertex's gradient: the area-weighted mean of its triangles' constant gradients.
void vertexGradients(const TriMesh& rest, const std::vector<Vec2>& deformed, std::vector<Gradient>& gradients,
                     std::vector<double>& weights) {
  gradients.assign(rest.vertices.size(), Gradient{});
  weights.assign(rest.vertices.size(), 0.0);
  for (const auto& tri : rest.triangles) {
    const Vec2 r1 = rest.vertices[tri[1]] - rest.vertices[tri[0]], r2 = rest.vertices[tri[2]] - rest.vertices[tri[0]];
    const Vec2 d1 = deformed[tri[1]] - deformed[tri[0]], d2 = deformed[tri[2]] - deformed[tri[0]];
    const double det = cross(r1, r2);
    if (!(std::abs(det) > 0.0)) continue;
    // F = [d1 d2] · [r1 r2]⁻¹
    const double ixx = r2.y / det, ixy = -r2.x / det, iyx = -r1.y / det, iyy = r1.x / det;
    const Gradient f{d1.x * ixx + d2.x * iyx, d1.x * ixy + d2.x * iyy, d1.y * ixx + d2.y * iyx, d1.y * ixy + d2.y * iyy};
    const double area = 0.5 * std::abs(det);
    for (int v : tri) {
      Gradient& g = gradients[v];
      g.xx += area * f.xx, g.xy += area * f.xy, g.yx += area * f.yx, g.yy += area * f.yy;
      weights[v] += area;
    }
  }
  for (std::size_t v = 0; v < gradients.size(); ++v)
    if (weights[v] > 0.0) {
      Gradient& g = gradients[v];
      g.xx /= weights[v], g.xy /= weights[v], g.yx /= weights[v], g.yy /= weights[v];
    }
}

}  // namespace

NeighbourhoodFits neighbourhoodFits(const TriMesh& mesh) {
  const std::size_t n = mesh.vertices.size();
  std::vector<std::vector<int>> ring(n);
  for (std::size_t i = 0; i < n; ++i) ring[i].push_back(static_cast<int>(i));
  for (const auto& tri : mesh.triangles)
    for (int a : tri)
      for (int b : tri)
        if (std::find(ring[a].begin(), ring[a].end(), b) == ring[a].end()) ring[a].push_back(b);
  NeighbourhoodFits fits;
  fits.offsets.push_back(0);
  for (std::size_t i = 0; i < n; ++i) {
    // The 2-ring: enough points for a quadratic even at the skin, where the 1-ring is one-sided.
    std::vector<int> near = ring[i];
    for (int j : ring[i])
      for (int k : ring[j])
        if (std::find(near.begin(), near.end(), k) == near.end()) near.push_back(k);
    constexpr int terms = 6;  // 1, x, y, x², xy, y²
    // Scale offsets to the neighbourhood's size so the normal equations are well conditioned.
    double extent = 0.0;
    for (int j : near) extent = std::max(extent, length(mesh.vertices[j] - mesh.vertices[i]));
    if (!(extent > 0.0)) extent = 1.0;
    Eigen::MatrixXd basis(near.size(), terms);
    for (std::size_t k = 0; k < near.size(); ++k) {
      const Vec2 d = (mesh.vertices[near[k]] - mesh.vertices[i]) / extent;
      basis(k, 0) = 1, basis(k, 1) = d.x, basis(k, 2) = d.y;
      basis(k, 3) = d.x * d.x, basis(k, 4) = d.x * d.y, basis(k, 5) = d.y * d.y;
    }
    const Eigen::MatrixXd normal = basis.transpose() * basis;
    Eigen::FullPivLU<Eigen::MatrixXd> lu(normal);
    const bool solvable = static_cast<std::size_t>(terms) <= near.size() && lu.rank() == terms;
    Eigen::VectorXd row;
    if (solvable) row = (lu.inverse().row(0) * basis.transpose()).transpose();  // value at the vertex
    for (std::size_t k = 0; k < near.size(); ++k) {
      fits.neighbours.push_back(near[k]);
      fits.weights.push_back(solvable ? row(static_cast<Eigen::Index>(k)) : (near[k] == static_cast<int>(i) ? 1.0 : 0.0));
    }
    fits.offsets.push_back(static_cast<int>(fits.neighbours.size()));
  }
  return fits;
}

void replayDrawnArt(const ElementMesh& mesh, const Vec2* deformed, bool linear, std::vector<Vec2>& artPoints) {
  if (linear) return replayArt(mesh, deformed, artPoints);
  const TriMesh& rest = mesh.mesh;
  const NeighbourhoodFits& fits = mesh.smoothing;
  const std::size_t n = rest.vertices.size();
  std::vector<Vec2> smooth(deformed, deformed + n), next(n);
  for (int round = 0; round < kSmoothingRounds; ++round) {
    for (std::size_t i = 0; i < n; ++i) {
      Vec2 p;
      for (int k = fits.offsets[i]; k < fits.offsets[i + 1]; ++k) p += smooth[fits.neighbours[k]] * fits.weights[k];
      next[i] = p;
    }
    smooth.swap(next);
  }
  std::vector<Gradient> gradients;
  std::vector<double> weights;
  vertexGradients(rest, smooth, gradients, weights);
  artPoints.resize(mesh.bindings.size());
  for (std::size_t i = 0; i < mesh.bindings.size(); ++i) {
    const ArtBinding& b = mesh.bindings[i];
    const auto& tri = rest.triangles[b.triangle];
    const Vec2 at = rest.vertices[tri[0]] * b.weights[0] + rest.vertices[tri[1]] * b.weights[1] +
                    rest.vertices[tri[2]] * b.weights[2];
    Vec2 p;
    for (int k = 0; k < 3; ++k) p += (smooth[tri[k]] + gradients[tri[k]].apply(at - rest.vertices[tri[k]])) * b.weights[k];
    artPoints[i] = p;
  }
}

}  // namespace pak
