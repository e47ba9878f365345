// Spreads independent per-radius measurements over the cores (each owns its Clipper state),
// through the project's one ThreadPool; an exception in any item is re-thrown here.
#include <algorithm>
#include <exception>
#include <thread>
#include <vector>

#include "metrics/metrics_internal.hpp"
#include "sim/parallel.hpp"

namespace pak::metrics_internal {

void parallelFor(int count, const std::function<void(int)>& body) {
  if (count <= 0) return;
  ThreadPool pool(std::min<int>(count, static_cast<int>(std::max(1u, std::thread::hardware_concurrency()))));
  std::vector<std::exception_ptr> failures(static_cast<std::size_t>(count));
  pool.parallelFor(static_cast<std::size_t>(count), 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      try {
        body(static_cast<int>(k));
      } catch (...) {
        failures[k] = std::current_exception();
      }
    }
  });
  for (const std::exception_ptr& failure : failures)
    if (failure) std::rethrow_exception(failure);
}

}  // namespace pak::metrics_internal
