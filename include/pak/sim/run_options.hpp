#pragma once
// How a simulation runs, apart from what it computes.
#include <cstdint>

namespace pak {

struct RunOptions {
  std::uint64_t seed = 1;  // the same seed gives the same result
  int threads = 0;         // 0: all cores; results do not depend on it
};

}  // namespace pak
