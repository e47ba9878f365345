#include "sim/parallel.hpp"

#include <cstdint>

namespace pak {

ThreadPool::ThreadPool(int threads) {
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  for (int i = 1; i < threads; ++i) workers_.emplace_back([this] { workerLoop(); });
}

ThreadPool::~ThreadPool() {
  stopping_.store(true, std::memory_order_release);
  epoch_.fetch_add(1, std::memory_order_acq_rel);
  epoch_.notify_all();
  for (auto& w : workers_) w.join();
}

void ThreadPool::drainChunks() {
  const std::size_t chunks = (count_ + grain_ - 1) / grain_;
  for (;;) {
    std::size_t c = nextChunk_.fetch_add(1, std::memory_order_relaxed);
    if (c >= chunks) return;
    std::size_t begin = c * grain_;
    std::size_t end = std::min(count_, begin + grain_);
    kernel_(context_, begin, end);
  }
}

void ThreadPool::run(std::size_t n, std::size_t grain, Kernel kernel, void* context) {
  kernel_ = kernel;
  context_ = context;
  count_ = n;
  grain_ = std::max<std::size_t>(1, grain);
  nextChunk_.store(0, std::memory_order_relaxed);
  busyWorkers_.store(static_cast<int>(workers_.size()), std::memory_order_relaxed);
  epoch_.fetch_add(1, std::memory_order_release);
  epoch_.notify_all();
  drainChunks();
  // Workers finish their last chunk; spin briefly, since steps are short.
  while (busyWorkers_.load(std::memory_order_acquire) != 0) std::this_thread::yield();
}

void ThreadPool::workerLoop() {
  // Epoch 0 is the state before any job; starting from it (not from a load) means a job
  // published before this thread started is not missed.
  std::uint64_t seen = 0;
  for (;;) {
    // Spin a little before sleeping: the next step usually follows within microseconds.
    std::uint64_t now = seen;
    for (int spin = 0; spin < 2000 && (now = epoch_.load(std::memory_order_acquire)) == seen; ++spin)
      std::this_thread::yield();
    if (now == seen) {
      epoch_.wait(seen, std::memory_order_acquire);
      now = epoch_.load(std::memory_order_acquire);
    }
    seen = now;
    if (stopping_.load(std::memory_order_acquire)) return;
    drainChunks();
    busyWorkers_.fetch_sub(1, std::memory_order_acq_rel);
  }
}

}  // namespace pak
