#pragma once
// One way to run work in parallel: a persistent pool and `parallelFor` over an index range.
// Dispatch allocates nothing and takes no lock (atomics plus wait/notify), so it can run
// inside the simulation step. Work items must write disjoint outputs; then results do not
// depend on the number of threads.
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace pak {

class ThreadPool {
 public:
  // threads <= 0: one per hardware thread. The calling thread counts as one.
  explicit ThreadPool(int threads = 0);
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  int threadCount() const { return static_cast<int>(workers_.size()) + 1; }

  // Calls body(begin, end) on contiguous chunks covering [0, n); returns when all are done.
  template <class Body>
  void parallelFor(std::size_t n, std::size_t grain, Body&& body) {
    if (n == 0) return;
    if (workers_.empty() || n <= grain) {
      body(std::size_t{0}, n);
      return;
    }
    using B = std::remove_reference_t<Body>;
    run(n, grain, [](void* ctx, std::size_t b, std::size_t e) { (*static_cast<B*>(ctx))(b, e); },
        const_cast<void*>(static_cast<const void*>(&body)));
  }

 private:
  using Kernel = void (*)(void*, std::size_t, std::size_t);
  void run(std::size_t n, std::size_t grain, Kernel kernel, void* context);
  void workerLoop();
  void drainChunks();

  std::vector<std::thread> workers_;
  // Current job; published by bumping `epoch_`.
  Kernel kernel_ = nullptr;
  void* context_ = nullptr;
  std::size_t count_ = 0;
  std::size_t grain_ = 1;
  std::atomic<std::size_t> nextChunk_{0};
  std::atomic<int> busyWorkers_{0};
  std::atomic<std::uint64_t> epoch_{0};
  std::atomic<bool> stopping_{false};
};

}  // namespace pak
