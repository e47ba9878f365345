#pragma once
// One way to run work in parallel: a persistent pool and `parallelFor` over an index range.
// Dispatch allocates nothing and takes no lock (atomics plus wait/notify), so it can run
// inside the simulation step. Work items must write disjoint outputs; then results do not
// depend on the number of threads.
//
// The chunks are split into one share per thread, in order. Each thread works through its own
// share first, then takes what is left of the others' from their ends. So a simulation's step
// after step mostly gives each thread the same items, whose data its core still holds, and the
// load still balances (AnimationPak's steps ran about 5 % faster on two threads than with one
// shared queue; docs/animationpak.md, seventeenth round).
#include <atomic>
#include <cstddef>
#include <cstdint>
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
  void workerLoop(int share);
  void drainChunks(int share);

  // One thread's share of the current job's chunks, [next, end) packed in one word: its owner
  // takes from the front, a thread that has run out of its own from the back, so each share
  // stays one run of items.
  struct alignas(64) Share {
    std::atomic<std::uint64_t> range{0};
  };

  std::vector<std::thread> workers_;
  // Current job; published by bumping `epoch_`.
  Kernel kernel_ = nullptr;
  void* context_ = nullptr;
  std::size_t count_ = 0;
  std::size_t grain_ = 1;
  std::vector<Share> shares_;  // one per thread, the caller's first
  std::atomic<int> busyWorkers_{0};
  std::atomic<std::uint64_t> epoch_{0};
  std::atomic<bool> stopping_{false};
};

}  // namespace pak
