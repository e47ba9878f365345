#include "pak/sim/run_options.hpp"

#include <algorithm>
#include <string>
#include <thread>

#include "pak/error.hpp"
#include "pak/limits.hpp"

namespace pak {

int maxThreads() {
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return limits::kThreadsPerCore * cores;
}

void checkRunOptions(const RunOptions& options) {
  if (options.threads < 0 || options.threads > maxThreads())
    throw InputError("--threads", "must be 0 (all cores) to " + std::to_string(maxThreads()) + " (" +
                                      std::to_string(limits::kThreadsPerCore) + " per core)");
}

}  // namespace pak
