// As-rigid-as-possible shape manipulation, the two-step closed-form method of Igarashi,
// Moscovich & Hughes (2005).
//
// Step 1 (similarity): each vertex of a triangle is expressed in the frame of its opposite
// edge, v₂ = v₀ + x·(v₁ − v₀) + y·R₉₀(v₁ − v₀), with (x, y) from the rest shape. The sum over
// every triangle and each of its three vertices of |v₂' − (v₀' + x·e' + y·R₉₀e')|² is zero for
// any similarity transform of the rest mesh; minimising it with the handles fixed gives a
// shape that may scale locally. x and y are coupled through R₉₀: one 2n×2n system.
// Step 2 (rigidity): each triangle's rest shape is fitted to its step-1 shape by a similarity,
// normalised to a rotation; the edges are then matched to the rotated rest edges,
// Σ |(vⱼ − vᵢ) − R·(rⱼ − rᵢ)|². That system is a graph Laplacian, the same for x and y.
//
// Both energies are quadratic in the vertex positions; with the handles eliminated their
// normal matrices depend only on the mesh and the handle set, so they are factorised here once.
//
// Null spaces: step 1 cannot tell the scale or rotation of a part held by fewer than two
// handles, and neither step can place a part held by none (including vertices in no
// triangle). Both systems therefore carry a tiny regulariser ε·|v − v_ref|², ε relative to
// the matrices' diagonal, which only decides those otherwise free directions: v_ref is the rest
// position moved by the displacement of the nearest handle (in the rest shape) for step 1, and
// the step-1 result for step 2. A single handle thus translates its part rigidly, and a
// vertex in no triangle follows its nearest handle.
#include "animation/arap.hpp"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <set>
#include <string>

#include "pak/error.hpp"
#include "pak/geom/best_fit_rotation.hpp"

namespace pak {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;
using Triplet = Eigen::Triplet<double>;

// Relative weight of the regulariser (see the header comment): small enough not to move a
// determined solution visibly, large enough for a well-conditioned factorisation.
constexpr double kRegularisation = 1e-8;

// Least-squares A·v ≈ b with some columns (the handles) given: the free part solves
// (A_fᵀA_f + εI)·u = A_fᵀ(b − A_c·q) + ε·u_ref, then one step of iterative refinement
// against the unregularised normal equations. The refinement removes the regulariser's pull
// where the problem is determined (to first order in ε) but cannot move the free directions,
// where the residual has no component.
struct EliminatedLeastSquares {
  Eigen::SimplicialLDLT<SparseMatrix> factor;
  SparseMatrix normal;   // A_fᵀA_f, unregularised
  SparseMatrix freeT;    // A_fᵀ
  SparseMatrix coupling; // A_fᵀA_c
  double epsilon = 0.0;

  void build(const SparseMatrix& a, const std::vector<int>& freeColumn, const std::vector<int>& fixedColumn,
             int freeCount, int fixedCount) {
    std::vector<Triplet> freeEntries, fixedEntries;
    for (int k = 0; k < a.outerSize(); ++k)
      for (SparseMatrix::InnerIterator it(a, k); it; ++it) {
        const int column = static_cast<int>(it.col());
        if (freeColumn[column] >= 0) freeEntries.emplace_back(it.row(), freeColumn[column], it.value());
        else fixedEntries.emplace_back(it.row(), fixedColumn[column], it.value());
      }
    SparseMatrix aFree(a.rows(), freeCount), aFixed(a.rows(), fixedCount);
    aFree.setFromTriplets(freeEntries.begin(), freeEntries.end());
    aFixed.setFromTriplets(fixedEntries.begin(), fixedEntries.end());
    freeT = aFree.transpose();
    coupling = freeT * aFixed;
    normal = freeT * aFree;
    double diagonal = 0.0;
    for (int i = 0; i < freeCount; ++i) diagonal += normal.coeff(i, i);
    epsilon = kRegularisation * (freeCount > 0 && diagonal > 0.0 ? diagonal / freeCount : 1.0);
    SparseMatrix identity(freeCount, freeCount);
    identity.setIdentity();
    if (freeCount > 0) {
      factor.compute(SparseMatrix(normal + epsilon * identity));
      assert(factor.info() == Eigen::Success);
    }
  }

  Eigen::VectorXd solve(const Eigen::VectorXd& b, const Eigen::VectorXd& fixed, const Eigen::VectorXd& reference) const {
    if (freeT.rows() == 0) return Eigen::VectorXd();
    const Eigen::VectorXd rhs = freeT * b - coupling * fixed;
    Eigen::VectorXd u = factor.solve(rhs + epsilon * reference);
    u += factor.solve(rhs - normal * u);
    return u;
  }
};

}  // namespace

struct ArapDeformation::Solver {
  TriMesh rest;
  std::vector<int> freeIndex;   // vertex → index among the free vertices, −1 for a handle
  std::vector<int> freeVertex;  // free index → vertex
  std::vector<int> nearestHandle;  // vertex → index into handles_ of the closest handle at rest
  EliminatedLeastSquares similarity;  // step 1, unknowns (x₀, y₀, x₁, y₁, …)
  EliminatedLeastSquares edges;       // step 2, one coordinate at a time
  std::vector<std::array<int, 2>> edgeList;  // the rows of step 2: (i, j) per triangle edge
  std::vector<int> edgeTriangle;             // the triangle each row belongs to
};

ArapDeformation::ArapDeformation(const TriMesh& rest, std::vector<int> handles)
    : handles_(std::move(handles)), solver_(std::make_unique<Solver>()) {
  const int n = static_cast<int>(rest.vertices.size());
  if (handles_.empty()) throw InputError("ARAP", "at least one handle is needed");
  std::set<int> seen;
  for (int h : handles_) {
    if (h < 0 || h >= n)
      throw InputError("ARAP", "handle vertex " + std::to_string(h) + " is not a vertex of the mesh (it has " +
                                   std::to_string(n) + ")");
    if (!seen.insert(h).second) throw InputError("ARAP", "vertex " + std::to_string(h) + " is a handle twice");
  }
#ifndef NDEBUG
  for (const auto& triangle : rest.triangles)
    for (int v : triangle) assert(v >= 0 && v < n);
#endif

  Solver& s = *solver_;
  s.rest = rest;
  s.freeIndex.assign(n, 0);
  for (int h : handles_) s.freeIndex[h] = -1;
  for (int v = 0; v < n; ++v)
    if (s.freeIndex[v] >= 0) {
      s.freeIndex[v] = static_cast<int>(s.freeVertex.size());
      s.freeVertex.push_back(v);
    }
  const int freeCount = static_cast<int>(s.freeVertex.size());
  const int handleCount = static_cast<int>(handles_.size());
  std::vector<int> handleIndex(n, -1);
  for (int k = 0; k < handleCount; ++k) handleIndex[handles_[k]] = k;

  s.nearestHandle.resize(n);
  for (int v = 0; v < n; ++v) {
    double best = std::numeric_limits<double>::infinity();
    for (int k = 0; k < handleCount; ++k) {
      const double d = lengthSquared(rest.vertices[v] - rest.vertices[handles_[k]]);
      if (d < best) best = d, s.nearestHandle[v] = k;  // ties: the first handle
    }
  }

  // Step 1: two rows per (triangle, vertex), columns interleaved x, y.
  std::vector<Triplet> entries;
  int row = 0;
  for (const auto& triangle : rest.triangles)
    for (int k = 0; k < 3; ++k) {
      const int i0 = triangle[k], i1 = triangle[(k + 1) % 3], i2 = triangle[(k + 2) % 3];
      const Vec2 p0 = rest.vertices[i0], e = rest.vertices[i1] - p0, d = rest.vertices[i2] - p0;
      const double len2 = lengthSquared(e);
      if (len2 <= 0.0) continue;  // a collapsed edge gives no frame
      const double x = dot(d, e) / len2, y = cross(e, d) / len2;  // d = x·e + y·R₉₀e
      // r = v₂ − v₀ − x(v₁ − v₀) − y·R₉₀(v₁ − v₀), with R₉₀(a) = (−a.y, a.x).
      // r.x = v₂x − (1 − x)v₀x − x·v₁x + y(v₁y − v₀y)
      entries.emplace_back(row, 2 * i2, 1.0);
      entries.emplace_back(row, 2 * i0, -(1.0 - x));
      entries.emplace_back(row, 2 * i1, -x);
      entries.emplace_back(row, 2 * i1 + 1, y);
      entries.emplace_back(row, 2 * i0 + 1, -y);
      ++row;
      // r.y = v₂y − (1 − x)v₀y − x·v₁y − y(v₁x − v₀x)
      entries.emplace_back(row, 2 * i2 + 1, 1.0);
      entries.emplace_back(row, 2 * i0 + 1, -(1.0 - x));
      entries.emplace_back(row, 2 * i1 + 1, -x);
      entries.emplace_back(row, 2 * i1, -y);
      entries.emplace_back(row, 2 * i0, y);
      ++row;
    }
  SparseMatrix a1(row, 2 * n);
  a1.setFromTriplets(entries.begin(), entries.end());
  std::vector<int> freeColumn(2 * n, -1), fixedColumn(2 * n, -1);
  for (int v = 0; v < n; ++v)
    for (int c = 0; c < 2; ++c) {
      if (s.freeIndex[v] >= 0) freeColumn[2 * v + c] = 2 * s.freeIndex[v] + c;
      else fixedColumn[2 * v + c] = 2 * handleIndex[v] + c;
    }
  s.similarity.build(a1, freeColumn, fixedColumn, 2 * freeCount, 2 * handleCount);

  // Step 2: one row per triangle edge (shared edges appear once per triangle, as in the paper).
  entries.clear();
  for (std::size_t t = 0; t < rest.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int i = rest.triangles[t][k], j = rest.triangles[t][(k + 1) % 3];
      const int r = static_cast<int>(s.edgeList.size());
      entries.emplace_back(r, j, 1.0);
      entries.emplace_back(r, i, -1.0);
      s.edgeList.push_back({i, j});
      s.edgeTriangle.push_back(static_cast<int>(t));
    }
  SparseMatrix a2(static_cast<int>(s.edgeList.size()), n);
  a2.setFromTriplets(entries.begin(), entries.end());
  std::vector<int> freeColumn2(n), fixedColumn2(n);
  for (int v = 0; v < n; ++v) {
    freeColumn2[v] = s.freeIndex[v];
    fixedColumn2[v] = handleIndex[v];
  }
  s.edges.build(a2, freeColumn2, fixedColumn2, freeCount, handleCount);
}

ArapDeformation::~ArapDeformation() = default;
ArapDeformation::ArapDeformation(ArapDeformation&&) noexcept = default;
ArapDeformation& ArapDeformation::operator=(ArapDeformation&&) noexcept = default;

void ArapDeformation::deform(const std::vector<Vec2>& handlePositions, std::vector<Vec2>& out) const {
  assert(handlePositions.size() == handles_.size());
  const Solver& s = *solver_;
  const int n = static_cast<int>(s.rest.vertices.size());
  const int handleCount = static_cast<int>(handles_.size());
  const int freeCount = static_cast<int>(s.freeVertex.size());

  // Step 1.
  Eigen::VectorXd fixed(2 * handleCount);
  for (int k = 0; k < handleCount; ++k) fixed[2 * k] = handlePositions[k].x, fixed[2 * k + 1] = handlePositions[k].y;
  Eigen::VectorXd reference(2 * freeCount);
  for (int f = 0; f < freeCount; ++f) {
    const int v = s.freeVertex[f], h = s.nearestHandle[v];
    const Vec2 moved = s.rest.vertices[v] + (handlePositions[h] - s.rest.vertices[handles_[h]]);
    reference[2 * f] = moved.x, reference[2 * f + 1] = moved.y;
  }
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(s.similarity.freeT.cols());
  const Eigen::VectorXd u1 = s.similarity.solve(zero, fixed, reference);
  std::vector<Vec2> intermediate(n);
  for (int k = 0; k < handleCount; ++k) intermediate[handles_[k]] = handlePositions[k];
  for (int f = 0; f < freeCount; ++f) intermediate[s.freeVertex[f]] = {u1[2 * f], u1[2 * f + 1]};

  // Step 2a: per triangle, the rotation that best maps its rest shape to its step-1 shape.
  std::vector<Vec2> rotation(s.rest.triangles.size(), Vec2{1.0, 0.0});  // (cos, sin)
  for (std::size_t t = 0; t < s.rest.triangles.size(); ++t) {
    const auto& tri = s.rest.triangles[t];
    Vec2 restCentre, nowCentre;
    for (int v : tri) restCentre += s.rest.vertices[v] / 3.0, nowCentre += intermediate[v] / 3.0;
    BestFitRotation fit;
    for (int v : tri) fit.add(s.rest.vertices[v] - restCentre, intermediate[v] - nowCentre);
    rotation[t] = fit.turn();
  }

  // Step 2b: edges matched to the rotated rest edges, x and y separately.
  const int rows = static_cast<int>(s.edgeList.size());
  Eigen::VectorXd bx(rows), by(rows);
  for (int r = 0; r < rows; ++r) {
    const auto [i, j] = s.edgeList[r];
    const Vec2 e = rotated(s.rest.vertices[j] - s.rest.vertices[i], rotation[s.edgeTriangle[r]]);
    bx[r] = e.x;
    by[r] = e.y;
  }
  Eigen::VectorXd fx(handleCount), fy(handleCount), rx(freeCount), ry(freeCount);
  for (int k = 0; k < handleCount; ++k) fx[k] = handlePositions[k].x, fy[k] = handlePositions[k].y;
  for (int f = 0; f < freeCount; ++f) rx[f] = u1[2 * f], ry[f] = u1[2 * f + 1];
  const Eigen::VectorXd ux = s.edges.solve(bx, fx, rx), uy = s.edges.solve(by, fy, ry);

  out.resize(n);
  for (int k = 0; k < handleCount; ++k) out[handles_[k]] = handlePositions[k];
  for (int f = 0; f < freeCount; ++f) out[s.freeVertex[f]] = {ux[f], uy[f]};
}

}  // namespace pak
