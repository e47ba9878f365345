#include "pak/geom/distance_field.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "pak/error.hpp"

namespace pak {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Grids beyond this many cells are refused rather than exhausting memory.
constexpr double kMaxCells = 1e8;

struct Segment {
  Vec2 a, b;
  Vec2 ab;
  double inverseLengthSquared = 0.0;  // 0 for a degenerate segment
};

double squaredDistance(Vec2 p, const Segment& s) {
  double t = dot(p - s.a, s.ab) * s.inverseLengthSquared;
  t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
  return lengthSquared(p - (s.a + s.ab * t));
}

std::vector<Segment> boundarySegments(const Region& region) {
  std::vector<Segment> segments;
  auto addRing = [&](const Ring& ring) {
    const std::size_t n = ring.size();
    if (n < 2) return;
    for (std::size_t k = 0; k < n; ++k) {
      Segment s;
      s.a = ring[k];
      s.b = ring[(k + 1) % n];
      if (!std::isfinite(s.a.x) || !std::isfinite(s.a.y))
        throw InputError("", "non-finite coordinate in a distance field's region");
      s.ab = s.b - s.a;
      const double len2 = lengthSquared(s.ab);
      s.inverseLengthSquared = len2 > 0.0 ? 1.0 / len2 : 0.0;
      segments.push_back(s);
    }
  };
  for (const Polygon& p : region) {
    addRing(p.outer);
    for (const Ring& h : p.holes) addRing(h);
  }
  return segments;
}

// Unsigned distance from every cell centre to the nearest segment, by recursive splitting
// of the grid: for a block whose cell centres lie within `h` of its centre c, with the
// nearest segment at distance D from c, every cell's distance is at most D + h, so only
// segments within D + 2h of c can be nearest to any of its cells. Keeping a superset of the
// nearest segments makes the result identical to a brute-force minimum.
class UnsignedDistanceSolver {
 public:
  UnsignedDistanceSolver(const std::vector<Segment>& segments, DistanceGrid& grid)
      : segments_(segments), grid_(grid) {}

  void run() {
    std::vector<int> all(segments_.size());
    for (std::size_t s = 0; s < all.size(); ++s) all[s] = static_cast<int>(s);
    solve(0, grid_.nx, 0, grid_.ny, all);
  }

 private:
  static constexpr int kLeafCells = 64;
  static constexpr std::size_t kLeafSegments = 4;

  void solve(int i0, int i1, int j0, int j1, const std::vector<int>& candidates) {
    const double cell = grid_.cell;
    const Vec2 c = grid_.origin + Vec2{0.5 * (i0 + i1) * cell, 0.5 * (j0 + j1) * cell};
    const double h = std::hypot(0.5 * (i1 - i0 - 1) * cell, 0.5 * (j1 - j0 - 1) * cell);
    std::vector<double> d2(candidates.size());
    double nearest2 = kInfinity;
    for (std::size_t k = 0; k < candidates.size(); ++k) {
      d2[k] = squaredDistance(c, segments_[candidates[k]]);
      nearest2 = std::min(nearest2, d2[k]);
    }
    // A little slack so rounding can only keep extra segments, never drop the nearest.
    const double reach = (std::sqrt(nearest2) + 2.0 * h) * (1.0 + 1e-9) + 1e-12 * cell;
    const double reach2 = reach * reach;
    std::vector<int> kept;
    kept.reserve(candidates.size());
    for (std::size_t k = 0; k < candidates.size(); ++k)
      if (d2[k] <= reach2) kept.push_back(candidates[k]);

    const int cells = (i1 - i0) * (j1 - j0);
    if (cells <= kLeafCells || kept.size() <= kLeafSegments) {
      for (int j = j0; j < j1; ++j)
        for (int i = i0; i < i1; ++i) {
          const Vec2 p = grid_.center(i, j);
          double best = kInfinity;
          for (int s : kept) best = std::min(best, squaredDistance(p, segments_[s]));
          grid_.values[static_cast<std::size_t>(j) * grid_.nx + i] = std::sqrt(best);
        }
      return;
    }
    if (i1 - i0 >= j1 - j0) {
      const int mid = (i0 + i1) / 2;
      solve(i0, mid, j0, j1, kept);
      solve(mid, i1, j0, j1, kept);
    } else {
      const int mid = (j0 + j1) / 2;
      solve(i0, i1, j0, mid, kept);
      solve(i0, i1, mid, j1, kept);
    }
  }

  const std::vector<Segment>& segments_;
  DistanceGrid& grid_;
};

// Negates the distances at cell centres inside the region, by even-odd parity along each
// row (the crossing rule of pointInRing, so both agree off the boundary).
void applyInsideSign(const std::vector<Segment>& segments, DistanceGrid& grid) {
  std::vector<double> crossings;
  for (int j = 0; j < grid.ny; ++j) {
    const double y = grid.center(0, j).y;
    crossings.clear();
    for (const Segment& s : segments) {
      const Vec2 a = s.b, b = s.a;  // pointInRing's (vertex, previous vertex) order
      if ((a.y > y) != (b.y > y)) crossings.push_back(a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y));
    }
    if (crossings.empty()) continue;
    std::sort(crossings.begin(), crossings.end());
    std::size_t atOrLeft = 0;  // crossings with x <= the cell centre
    for (int i = 0; i < grid.nx; ++i) {
      const double x = grid.center(i, j).x;
      while (atOrLeft < crossings.size() && crossings[atOrLeft] <= x) ++atOrLeft;
      const bool inside = (crossings.size() - atOrLeft) % 2 == 1;
      if (inside) grid.values[static_cast<std::size_t>(j) * grid.nx + i] *= -1.0;
    }
  }
}

// Exact 1D squared distance transform (Felzenszwalb & Huttenlocher 2012) of f, in place.
// Infinite samples never lower the envelope, so they are skipped rather than approximated
// by a large number; a line with no finite sample stays infinite.
void squaredDistance1D(std::vector<double>& f, std::vector<double>& out, std::vector<int>& v,
                       std::vector<double>& z) {
  const int n = static_cast<int>(f.size());
  int k = -1;
  for (int q = 0; q < n; ++q) {
    if (f[q] == kInfinity) continue;
    const double fq = f[q] + static_cast<double>(q) * q;
    while (k >= 0) {
      const int p = v[k];
      const double s = (fq - (f[p] + static_cast<double>(p) * p)) / (2.0 * (q - p));
      if (s <= z[k]) {
        --k;
      } else {
        ++k;
        v[k] = q;
        z[k] = s;
        break;
      }
    }
    if (k < 0) {
      k = 0;
      v[0] = q;
      z[0] = -kInfinity;
    }
  }
  if (k < 0) {
    std::fill(out.begin(), out.end(), kInfinity);
  } else {
    int e = 0;
    for (int q = 0; q < n; ++q) {
      while (e < k && z[e + 1] < q) ++e;
      const double d = q - v[e];
      out[q] = d * d + f[v[e]];
    }
  }
  f.swap(out);
}

}  // namespace

double DistanceGrid::sample(Vec2 p) const {
  if (nx <= 0 || ny <= 0 || values.empty()) return kInfinity;
  auto axis = [](double coordinate, int n, int& i0, double& t) {
    const double u = std::clamp(coordinate - 0.5, 0.0, static_cast<double>(n - 1));
    i0 = std::min(static_cast<int>(u), std::max(n - 2, 0));
    t = n > 1 ? u - i0 : 0.0;
  };
  int i0 = 0, j0 = 0;
  double tx = 0.0, ty = 0.0;
  axis((p.x - origin.x) / cell, nx, i0, tx);
  axis((p.y - origin.y) / cell, ny, j0, ty);
  const int i1 = std::min(i0 + 1, nx - 1), j1 = std::min(j0 + 1, ny - 1);
  // Infinite values (a field with no boundary) must not turn into inf * 0 = NaN.
  auto lerp = [](double a, double b, double t) {
    if (t <= 0.0 || a == b) return a;
    if (t >= 1.0) return b;
    return a * (1.0 - t) + b * t;
  };
  return lerp(lerp(at(i0, j0), at(i1, j0), tx), lerp(at(i0, j1), at(i1, j1), tx), ty);
}

DistanceGrid signedDistanceField(const Region& region, const Box& area, int resolution) {
  if (resolution <= 0) throw InputError("", "distance field resolution must be positive");
  if (area.empty() || !std::isfinite(area.width()) || !std::isfinite(area.height()) ||
      std::max(area.width(), area.height()) <= 0.0)
    throw InputError("", "distance field area must be a finite box of positive size");
  DistanceGrid grid;
  grid.origin = area.min;
  grid.cell = std::max(area.width(), area.height()) / resolution;
  // The slack stops an exact multiple of the cell from gaining a column through rounding.
  auto cellsAlong = [&](double extent) {
    return std::max(1, static_cast<int>(std::ceil(extent / grid.cell - 1e-9)));
  };
  grid.nx = cellsAlong(area.width());
  grid.ny = cellsAlong(area.height());
  if (static_cast<double>(grid.nx) * grid.ny > kMaxCells)
    throw InputError("", "distance field resolution is too large");
  grid.values.assign(static_cast<std::size_t>(grid.nx) * grid.ny, kInfinity);

  const std::vector<Segment> segments = boundarySegments(region);
  if (segments.empty()) return grid;  // no boundary: everything is outside, infinitely far
  UnsignedDistanceSolver(segments, grid).run();
  applyInsideSign(segments, grid);
  return grid;
}

std::vector<double> euclideanDistanceTransform(const std::vector<std::uint8_t>& occupied, int nx, int ny) {
  if (nx <= 0 || ny <= 0) return {};
  assert(occupied.size() == static_cast<std::size_t>(nx) * ny);
  std::vector<double> grid(occupied.size());
  for (std::size_t k = 0; k < occupied.size(); ++k) grid[k] = occupied[k] ? 0.0 : kInfinity;

  const int longest = std::max(nx, ny);
  std::vector<double> line, scratch(longest);
  std::vector<int> v(longest);
  std::vector<double> z(longest + 1);
  // Rows, then columns: the 2D squared distance separates into two 1D passes.
  line.resize(nx);
  scratch.resize(nx);
  for (int j = 0; j < ny; ++j) {
    std::copy_n(grid.begin() + static_cast<std::ptrdiff_t>(j) * nx, nx, line.begin());
    squaredDistance1D(line, scratch, v, z);
    std::copy_n(line.begin(), nx, grid.begin() + static_cast<std::ptrdiff_t>(j) * nx);
  }
  line.resize(ny);
  scratch.resize(ny);
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j) line[j] = grid[static_cast<std::size_t>(j) * nx + i];
    squaredDistance1D(line, scratch, v, z);
    for (int j = 0; j < ny; ++j) grid[static_cast<std::size_t>(j) * nx + i] = line[j];
  }
  for (double& d : grid) d = std::sqrt(d);
  return grid;
}

}  // namespace pak
