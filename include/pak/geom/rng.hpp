#pragma once
// Deterministic random numbers, identical on every platform and standard library
// (std::uniform_*_distribution is not), so a seed reproduces a run bit for bit.
#include <cstdint>

namespace pak {

class Rng {
 public:
  explicit Rng(std::uint64_t seed = 1) : state_(seed ^ 0x9E3779B97F4A7C15ull) { next(); }
  // splitmix64
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  // Uniform in [0, 1).
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  // Uniform integer in [0, n).
  std::uint64_t below(std::uint64_t n) { return n == 0 ? 0 : next() % n; }

 private:
  std::uint64_t state_;
};

}  // namespace pak
