#include "pak/geom/blue_noise.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "pak/error.hpp"
#include "pak/geom/closest_point.hpp"
#include "pak/geom/distance_field.hpp"
#include "pak/geom/rng.hpp"

namespace pak {
namespace {

// Background grids beyond this many cells are refused rather than exhausting memory.
constexpr double kMaxGridCells = 1e8;
// Resolution of the coarse signed distance field that settles most inside tests in O(1).
constexpr int kMaxClassifierResolution = 1024;

void checkOptions(const BlueNoiseOptions& o) {
  if (!(o.radius > 0.0) || !std::isfinite(o.radius))
    throw InputError("", "blue-noise radius must be a positive number");
  if (o.attempts < 1) throw InputError("", "blue-noise attempts must be at least 1");
  if (!(o.boundaryMargin >= 0.0) || !std::isfinite(o.boundaryMargin))
    throw InputError("", "blue-noise boundary margin must be a non-negative number");
}

// Decides whether a point is inside the region and at least `margin` from its boundary.
// A signed distance field answers far from the boundary (it is 1-Lipschitz, so the value
// at the nearest cell centre bounds the true one); only points near the boundary pay for
// the exact polygon tests.
class RegionTest {
 public:
  RegionTest(const Region& region, const Box& box, double radius, double margin)
      : region_(region), margin_(margin) {
    const double side = std::max(box.width(), box.height());
    const int resolution = std::clamp(static_cast<int>(std::ceil(side / (0.5 * radius))), 8,
                                      kMaxClassifierResolution);
    field_ = signedDistanceField(region, box, resolution);
  }

  bool accepts(Vec2 p) const {
    const int i = std::clamp(static_cast<int>(std::floor((p.x - field_.origin.x) / field_.cell)), 0, field_.nx - 1);
    const int j = std::clamp(static_cast<int>(std::floor((p.y - field_.origin.y) / field_.cell)), 0, field_.ny - 1);
    const double v = field_.at(i, j);
    const double slack = distance(p, field_.center(i, j));
    // Accepted points satisfy signedDistance(p) < -margin (strictly inside when margin is 0).
    if (v + slack < -margin_) return true;
    if (v - slack > -margin_) return false;
    if (!pointInRegion(p, region_)) return false;
    return margin_ <= 0.0 || closestPointOnBoundary(p, region_).distance >= margin_;
  }

 private:
  const Region& region_;
  double margin_;
  DistanceGrid field_;
};

// Bridson's background grid: cells of side r/sqrt(2) hold at most one sample each. The
// cells store the sample's position itself (empty: +infinity) so the neighbour test reads
// one contiguous array instead of chasing indices.
class SampleGrid {
 public:
  SampleGrid(const Box& box, double radius) : origin_(box.min), radius_(radius) {
    cell_ = radius / std::numbers::sqrt2;
    const double nx = std::floor(box.width() / cell_) + 1.0, ny = std::floor(box.height() / cell_) + 1.0;
    if (nx * ny > kMaxGridCells) throw InputError("", "blue-noise radius is too small for the region's size");
    nx_ = static_cast<int>(nx);
    ny_ = static_cast<int>(ny);
    constexpr double inf = std::numeric_limits<double>::infinity();
    cells_.assign(static_cast<std::size_t>(nx_) * ny_, Vec2{inf, inf});
  }

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  double cell() const { return cell_; }
  Vec2 origin() const { return origin_; }
  bool occupied(int i, int j) const { return std::isfinite(cells_[index(i, j)].x); }

  bool cellOf(Vec2 p, int& i, int& j) const {
    const double u = (p.x - origin_.x) / cell_, v = (p.y - origin_.y) / cell_;
    if (!(u >= 0.0 && v >= 0.0 && u < nx_ && v < ny_)) return false;
    i = static_cast<int>(u);
    j = static_cast<int>(v);
    return true;
  }

  // True when no sample lies closer than the radius. A 5x5 block of cells covers the disc;
  // its corner cells are at least r away, so they are skipped.
  bool isFarFromSamples(Vec2 p, int i, int j) const {
    const double r2 = radius_ * radius_;
    const int j0 = std::max(j - 2, 0), j1 = std::min(j + 2, ny_ - 1);
    for (int jj = j0; jj <= j1; ++jj) {
      const int reach = (jj == j - 2 || jj == j + 2) ? 1 : 2;
      const int i0 = std::max(i - reach, 0), i1 = std::min(i + reach, nx_ - 1);
      const Vec2* row = &cells_[index(0, jj)];
      for (int ii = i0; ii <= i1; ++ii)
        if (lengthSquared(row[ii] - p) < r2) return false;
    }
    return true;
  }

  void insert(int i, int j, Vec2 p) { cells_[index(i, j)] = p; }

 private:
  std::size_t index(int i, int j) const { return static_cast<std::size_t>(j) * nx_ + i; }

  Vec2 origin_;
  double radius_;
  double cell_ = 1.0;
  int nx_ = 0, ny_ = 0;
  std::vector<Vec2> cells_;
};

class BridsonSampler {
 public:
  BridsonSampler(const Region& region, const Box& box, const BlueNoiseOptions& options)
      : options_(options), test_(region, box, options.radius, options.boundaryMargin),
        grid_(box, options.radius), rng_(options.seed) {}

  std::vector<Vec2> run() {
    // Seeds come from a sweep over the background grid, so every part of the region
    // (disjoint polygons, parts cut off by the margin) gets one; Bridson's growth from
    // each seed fills the rest, and the sweep also fills gaps the growth left behind.
    for (int j = 0; j < grid_.ny() && !full(); ++j)
      for (int i = 0; i < grid_.nx() && !full(); ++i) {
        if (grid_.occupied(i, j)) continue;
        for (int attempt = 0; attempt < kSeedAttemptsPerCell; ++attempt) {
          const Vec2 p = grid_.origin() + Vec2{(i + rng_.uniform()) * grid_.cell(), (j + rng_.uniform()) * grid_.cell()};
          if (tryAdd(p)) {
            grow();
            break;
          }
        }
      }
    return std::move(samples_);
  }

 private:
  static constexpr int kSeedAttemptsPerCell = 2;

  bool full() const { return options_.maxSamples > 0 && samples_.size() >= options_.maxSamples; }

  bool tryAdd(Vec2 p) {
    int i = 0, j = 0;
    if (!grid_.cellOf(p, i, j) || !grid_.isFarFromSamples(p, i, j) || !test_.accepts(p)) return false;
    grid_.insert(i, j, p);
    samples_.push_back(p);
    active_.push_back(samples_.size() - 1);
    return true;
  }

  // Candidates uniform by area in the annulus [r, 2r] around a random active sample; the
  // sample retires after `attempts` failures in a row.
  void grow() {
    const double r = options_.radius;
    while (!active_.empty() && !full()) {
      const std::size_t slot = rng_.below(active_.size());
      const Vec2 centre = samples_[active_[slot]];
      bool added = false;
      for (int k = 0; k < options_.attempts && !added; ++k) {
        added = tryAdd(centre + annulusOffset(r));
      }
      if (!added) {
        active_[slot] = active_.back();
        active_.pop_back();
      }
    }
    active_.clear();
  }

  // Rejection sampling instead of sin/cos: plain arithmetic gives the same bits everywhere.
  Vec2 annulusOffset(double r) {
    for (;;) {
      const Vec2 v{rng_.uniform(-2.0, 2.0), rng_.uniform(-2.0, 2.0)};
      const double l2 = lengthSquared(v);
      if (l2 >= 1.0 && l2 <= 4.0) return v * r;
    }
  }

  const BlueNoiseOptions& options_;
  RegionTest test_;
  SampleGrid grid_;
  Rng rng_;
  std::vector<Vec2> samples_;
  std::vector<std::size_t> active_;
};

}  // namespace

std::vector<Vec2> blueNoiseSample(const Region& region, const BlueNoiseOptions& options) {
  checkOptions(options);
  auto finite = [](const Ring& ring) {
    return std::all_of(ring.begin(), ring.end(), [](Vec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); });
  };
  for (const Polygon& polygon : region)
    if (!finite(polygon.outer) || !std::all_of(polygon.holes.begin(), polygon.holes.end(), finite))
      throw InputError("", "non-finite coordinate in the region to sample");
  const Box box = bounds(region);
  if (box.empty() || !(area(region) > 0.0)) return {};
  return BridsonSampler(region, box, options).run();
}

}  // namespace pak
