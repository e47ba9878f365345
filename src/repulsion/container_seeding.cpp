#include "repulsion/container_seeding.hpp"

#include <algorithm>
#include <numeric>

#include "pak/geom/rng.hpp"

namespace pak {

std::vector<int> seedsPerContainer(const std::vector<double>& areas, int count, double minimumArea) {
  const std::size_t n = areas.size();
  std::vector<int> seeds(n, 0);
  const double total = std::accumulate(areas.begin(), areas.end(), 0.0);
  if (n == 0 || !(total > 0.0)) return seeds;
  std::vector<double> remainder(n, 0.0);
  int given = 0;
  for (std::size_t c = 0; c < n; ++c) {
    const double share = count * areas[c] / total;
    seeds[c] = static_cast<int>(share);
    remainder[c] = share - seeds[c];
    given += seeds[c];
  }
  // The rest by largest remainder (ties: the earlier container), so the sum is `count`.
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return remainder[a] > remainder[b]; });
  for (std::size_t k = 0; given < count && k < n; ++k, ++given) ++seeds[order[k]];
  for (std::size_t c = 0; c < n; ++c)
    if (seeds[c] == 0 && areas[c] >= minimumArea) seeds[c] = 1;
  return seeds;
}

std::vector<Seed> seedContainers(const std::vector<ContainerSeeding>& containers, std::uint64_t seed, Vec2 period) {
  std::vector<Seed> seeds;
  for (std::size_t c = 0; c < containers.size(); ++c) {
    const ContainerSeeding& container = containers[c];
    if (container.count <= 0 || container.types.empty()) continue;
    SeedingOptions options;
    options.count = container.count;
    options.types = static_cast<int>(container.types.size());
    options.seed = c == 0 ? seed : Rng(seed + c).next();
    options.period = period;
    for (Seed s : seedElements(*container.region, *container.index, options)) {
      s.type = container.types[static_cast<std::size_t>(s.type)];
      s.container = static_cast<int>(c);
      seeds.push_back(s);
    }
  }
  return seeds;
}

}  // namespace pak
