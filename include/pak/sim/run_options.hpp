#pragma once
// How a simulation runs, apart from what it computes.
#include <atomic>
#include <cstdint>

namespace pak {

struct RunOptions {
  std::uint64_t seed = 1;  // the same seed gives the same result
  int threads = 0;         // 0: all cores; results do not depend on it
  // Set by the caller while the run goes on (pak sets it on Ctrl-C) to stop it as a time
  // limit does: the result is the state then, cleaned up. Null: never.
  const std::atomic<bool>* stopRequest = nullptr;
};

// The most worker threads a run may ask for: limits::kThreadsPerCore per core.
int maxThreads();
// Throws InputError("--threads", …) for a negative count or one above maxThreads().
void checkRunOptions(const RunOptions& options);

}  // namespace pak
