#include "repulsion/seeding.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "pak/geom/blue_noise.hpp"
#include "pak/geom/rng.hpp"
#include "pak/repulsion/tiling.hpp"

namespace pak {

std::vector<Seed> seedElements(const Region& region, const RegionIndex& index, const SeedingOptions& options) {
  const double free = area(region);
  const int n = std::max(1, options.count);
  // Dense candidates (about 16 per seed), then farthest-point selection among them.
  BlueNoiseOptions noise;
  noise.radius = std::sqrt(free / n) / 4.0;
  noise.seed = options.seed;
  std::vector<Vec2> candidates = blueNoiseSample(region, noise);
  for (int attempt = 0; static_cast<int>(candidates.size()) < n && attempt < 8; ++attempt) {
    noise.radius *= 0.5;
    candidates = blueNoiseSample(region, noise);
  }
  std::vector<Seed> seeds;
  if (candidates.empty()) return seeds;

  // Score = distance to the nearest chosen seed, with the boundary counting as a seed at
  // half the distance (so seeds keep about half a spacing from the container's edge).
  std::vector<double> score(candidates.size());
  const bool periodic = isTiled(options.period);  // a tile has no boundary
  for (std::size_t i = 0; i < candidates.size(); ++i)
    score[i] = periodic ? std::numeric_limits<double>::infinity() : 2.0 * index.query(candidates[i], true).distance;
  Rng rng(options.seed);
  std::vector<Vec2> chosen;
  std::size_t next = static_cast<std::size_t>(rng.below(candidates.size()));
  while (static_cast<int>(chosen.size()) < n) {
    if (chosen.empty()) {
      // Start from a random candidate among the roomiest ones.
      double best = *std::max_element(score.begin(), score.end());
      for (std::size_t tries = 0; score[next] < 0.5 * best && tries < candidates.size(); ++tries)
        next = (next + 1) % candidates.size();
    } else {
      next = static_cast<std::size_t>(std::max_element(score.begin(), score.end()) - score.begin());
      if (score[next] <= 0.0) break;  // fewer distinct candidates than seeds wanted
    }
    Vec2 p = candidates[next];
    chosen.push_back(p);
    for (std::size_t i = 0; i < candidates.size(); ++i) score[i] = std::min(score[i], periodic ? periodicDistance(candidates[i], p, options.period)
                                                                                 : distance(candidates[i], p));
  }
  // Random order, types cycled, random orientation.
  for (std::size_t i = chosen.size(); i > 1; --i) std::swap(chosen[i - 1], chosen[rng.below(i)]);
  for (std::size_t i = 0; i < chosen.size(); ++i)
    seeds.push_back({chosen[i], rng.uniform(0.0, 2.0 * std::numbers::pi), static_cast<int>(i % std::max(1, options.types))});
  return seeds;
}

}  // namespace pak
