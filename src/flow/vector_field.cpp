// The flow field of thesis 3.3.3. Palacios & Zhang design N-RoSy fields by interpolating the
// user's constraints smoothly; for N = 1 (plain vectors) that is a harmonic interpolation.
// On a grid: minimise Σ_edges |v_i − v_j|² + λ Σ_samples |B_s v − t_s|², where B_s spreads
// guide sample s bilinearly over its four nodes and t_s is the guide's unit tangent there.
// The x and y components share one sparse system, factored once.
#include "pak/flow/vector_field.hpp"

#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>

#include "pak/error.hpp"
#include "pak/geom/resample.hpp"

namespace pak {
namespace {

// The constraints' weight against the smoothness term: large enough that the field follows
// the guides closely, small enough that crossing guides blend instead of fighting.
constexpr double kConstraintWeight = 100.0;
constexpr int kMarginCells = 2;

struct Bilinear {
  int i = 0, j = 0;    // lower-left node
  double tx = 0, ty = 0;
};

Bilinear locate(const VectorField& f, Vec2 p) {
  const double fx = std::clamp((p.x - f.origin.x) / f.cell - 0.5, 0.0, f.nx - 1.0);
  const double fy = std::clamp((p.y - f.origin.y) / f.cell - 0.5, 0.0, f.ny - 1.0);
  Bilinear b;
  b.i = std::min(static_cast<int>(fx), std::max(0, f.nx - 2));
  b.j = std::min(static_cast<int>(fy), std::max(0, f.ny - 2));
  b.tx = fx - b.i;
  b.ty = fy - b.j;
  return b;
}

}  // namespace

Vec2 VectorField::at(Vec2 p) const {
  if (values.empty()) return {};
  Bilinear b = locate(*this, p);
  auto v = [&](int i, int j) {
    return values[static_cast<std::size_t>(std::min(j, ny - 1)) * nx + static_cast<std::size_t>(std::min(i, nx - 1))];
  };
  Vec2 sum = v(b.i, b.j) * ((1 - b.tx) * (1 - b.ty)) + v(b.i + 1, b.j) * (b.tx * (1 - b.ty)) +
             v(b.i, b.j + 1) * ((1 - b.tx) * b.ty) + v(b.i + 1, b.j + 1) * (b.tx * b.ty);
  return normalized(sum);
}

Vec2 VectorField::advance(Vec2 p, double step) const {
  Vec2 k1 = at(p);
  if (lengthSquared(k1) == 0.0) return p;
  Vec2 k2 = at(p + k1 * (0.5 * step));
  Vec2 k3 = at(p + k2 * (0.5 * step));
  Vec2 k4 = at(p + k3 * step);
  return p + (k1 + 2.0 * k2 + 2.0 * k3 + k4) * (step / 6.0);
}

VectorField buildVectorField(const Region& containers, const std::vector<Polyline>& guides,
                             const VectorFieldOptions& options) {
  if (!(options.sampleSpacing > 0.0) || !std::isfinite(options.sampleSpacing))
    throw InputError("", "the guide sample spacing must be positive");
  if (options.resolution < 2 || options.resolution > 4096) throw InputError("", "the field resolution must be 2 to 4096");
  Box box = bounds(containers);
  for (const Polyline& g : guides)
    for (Vec2 p : g) box.add(p);
  if (box.empty() || !(std::max(box.width(), box.height()) > 0.0)) throw InputError("", "the containers have no extent");

  // Unit tangents at guide samples (central differences along the resampled guide).
  struct Constraint {
    Vec2 p, t;
  };
  std::vector<Constraint> constraints;
  for (const Polyline& g : guides) {
    if (g.size() < 2 || !(polylineLength(g) > 0.0)) continue;
    Polyline s = resamplePolyline(g, options.sampleSpacing);
    for (std::size_t k = 0; k < s.size(); ++k) {
      Vec2 t = normalized(s[std::min(k + 1, s.size() - 1)] - s[k == 0 ? 0 : k - 1]);
      if (lengthSquared(t) > 0.0) constraints.push_back({s[k], t});
    }
  }
  if (constraints.empty()) throw InputError("", "no direction guide with two distinct points");

  VectorField field;
  field.cell = std::max(box.width(), box.height()) / options.resolution;
  field.origin = box.min - Vec2{1.0, 1.0} * (kMarginCells * field.cell);
  field.nx = static_cast<int>(std::ceil(box.width() / field.cell)) + 2 * kMarginCells;
  field.ny = static_cast<int>(std::ceil(box.height() / field.cell)) + 2 * kMarginCells;
  field.nx = std::max(field.nx, 2);
  field.ny = std::max(field.ny, 2);
  const int n = field.nx * field.ny;
  auto index = [&](int i, int j) { return j * field.nx + i; };

  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(n) * 5 + constraints.size() * 16);
  // Graph Laplacian of the 4-neighbour grid.
  for (int j = 0; j < field.ny; ++j)
    for (int i = 0; i < field.nx; ++i) {
      const int a = index(i, j);
      for (auto [di, dj] : {std::pair{1, 0}, std::pair{0, 1}}) {
        if (i + di >= field.nx || j + dj >= field.ny) continue;
        const int b = index(i + di, j + dj);
        entries.emplace_back(a, a, 1.0);
        entries.emplace_back(b, b, 1.0);
        entries.emplace_back(a, b, -1.0);
        entries.emplace_back(b, a, -1.0);
      }
    }
  // λ BᵀB and λ Bᵀt.
  Eigen::VectorXd bx = Eigen::VectorXd::Zero(n), by = Eigen::VectorXd::Zero(n);
  const double lambda = kConstraintWeight * field.cell / options.sampleSpacing;  // density-independent
  for (const Constraint& c : constraints) {
    Bilinear b = locate(field, c.p);
    const int nodes[4] = {index(b.i, b.j), index(b.i + 1, b.j), index(b.i, b.j + 1), index(b.i + 1, b.j + 1)};
    const double w[4] = {(1 - b.tx) * (1 - b.ty), b.tx * (1 - b.ty), (1 - b.tx) * b.ty, b.tx * b.ty};
    for (int r = 0; r < 4; ++r) {
      bx[nodes[r]] += lambda * w[r] * c.t.x;
      by[nodes[r]] += lambda * w[r] * c.t.y;
      for (int s = 0; s < 4; ++s) entries.emplace_back(nodes[r], nodes[s], lambda * w[r] * w[s]);
    }
  }
  Eigen::SparseMatrix<double> system(n, n);
  system.setFromTriplets(entries.begin(), entries.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(system);
  if (solver.info() != Eigen::Success) throw InputError("", "the vector field system could not be factored");
  Eigen::VectorXd x = solver.solve(bx), y = solver.solve(by);

  field.values.resize(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) field.values[static_cast<std::size_t>(k)] = normalized(Vec2{x[k], y[k]});
  return field;
}

}  // namespace pak
