#include "repulsion/secondary_seeding.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "pak/geom/distance_field.hpp"

namespace pak {

std::vector<SecondarySeed> secondarySeeds(const Region& freeSpace, const Box& area,
                                          const SecondarySeedingOptions& options) {
  std::vector<SecondarySeed> seeds;
  if (freeSpace.empty() || area.empty()) return seeds;
  // Negative inside the free space: −value is the distance to the nearest skin or wall,
  // exact to the polygons (the thesis approximates it on the grid).
  const DistanceGrid field = signedDistanceField(freeSpace, area, options.resolution);

  struct Candidate { double distance; int cell; };
  std::vector<Candidate> candidates;
  for (int c = 0; c < static_cast<int>(field.values.size()); ++c)
    if (-field.values[c] >= options.minDistance) candidates.push_back({-field.values[c], c});
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    return a.distance != b.distance ? a.distance > b.distance : a.cell < b.cell;
  });

  // Chosen seeds hashed on a d_sep grid: a candidate only checks the 3 × 3 cells around it.
  const double bucket = std::max(options.separation, field.cell);
  auto key = [&](Vec2 p) {
    long long i = static_cast<long long>(std::floor((p.x - area.min.x) / bucket));
    long long j = static_cast<long long>(std::floor((p.y - area.min.y) / bucket));
    return std::pair{i, j};
  };
  auto hash = [](long long i, long long j) { return (i << 32) ^ (j & 0xffffffffll); };
  std::unordered_map<long long, std::vector<int>> buckets;
  const double separation2 = options.separation * options.separation;
  for (const Candidate& c : candidates) {
    const Vec2 p = field.center(c.cell % field.nx, c.cell / field.nx);
    auto [i, j] = key(p);
    bool clear = true;
    for (long long di = -1; di <= 1 && clear; ++di)
      for (long long dj = -1; dj <= 1 && clear; ++dj) {
        auto it = buckets.find(hash(i + di, j + dj));
        if (it == buckets.end()) continue;
        for (int s : it->second)
          if (lengthSquared(seeds[s].position - p) < separation2) { clear = false; break; }
      }
    if (!clear) continue;
    buckets[hash(i, j)].push_back(static_cast<int>(seeds.size()));
    seeds.push_back({p, c.distance});
  }

  // Discs of neighbouring seeds must not overlap either: cap each radius at half the
  // distance to the nearest other seed.
  for (std::size_t a = 0; a < seeds.size(); ++a)
    for (std::size_t b = a + 1; b < seeds.size(); ++b) {
      const double half = 0.5 * distance(seeds[a].position, seeds[b].position);
      seeds[a].radius = std::min(seeds[a].radius, half);
      seeds[b].radius = std::min(seeds[b].radius, half);
    }
  return seeds;
}

}  // namespace pak
