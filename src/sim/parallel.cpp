#include "sim/parallel.hpp"

#include <cassert>
#include <cstdint>

namespace pak {

ThreadPool::ThreadPool(int threads) {
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  shares_ = std::vector<Share>(static_cast<std::size_t>(threads));
  for (int i = 1; i < threads; ++i) workers_.emplace_back([this, i] { workerLoop(i); });
}

ThreadPool::~ThreadPool() {
  stopping_.store(true, std::memory_order_release);
  epoch_.fetch_add(1, std::memory_order_acq_rel);
  epoch_.notify_all();
  for (auto& w : workers_) w.join();
}

namespace {
constexpr std::uint64_t pack(std::uint64_t next, std::uint64_t end) { return next << 32 | end; }
}  // namespace

void ThreadPool::drainChunks(int share) {
  // Takes the chunks of one share, from its front (its owner) or its back (a helper).
  auto drain = [&](std::atomic<std::uint64_t>& range, bool fromFront) {
    for (std::uint64_t r = range.load(std::memory_order_relaxed);;) {
      const std::uint64_t next = r >> 32, end = r & 0xffffffffu;
      if (next >= end) return;
      const std::uint64_t chunk = fromFront ? next : end - 1;
      if (range.compare_exchange_weak(r, fromFront ? pack(next + 1, end) : pack(next, end - 1),
                                      std::memory_order_relaxed)) {
        const std::size_t begin = static_cast<std::size_t>(chunk) * grain_;
        kernel_(context_, begin, std::min(count_, begin + grain_));
        r = range.load(std::memory_order_relaxed);
      }
    }
  };
  const std::size_t threads = shares_.size(), own = static_cast<std::size_t>(share);
  drain(shares_[own].range, true);
  for (std::size_t k = 1; k < threads; ++k) drain(shares_[(own + k) % threads].range, false);
}

void ThreadPool::run(std::size_t n, std::size_t grain, Kernel kernel, void* context) {
  kernel_ = kernel;
  context_ = context;
  count_ = n;
  grain_ = std::max<std::size_t>(1, grain);
  const std::size_t chunks = (n + grain_ - 1) / grain_, threads = shares_.size();
  assert(chunks < (std::uint64_t{1} << 32));
  for (std::size_t t = 0; t < threads; ++t)
    shares_[t].range.store(pack(chunks * t / threads, chunks * (t + 1) / threads), std::memory_order_relaxed);
  busyWorkers_.store(static_cast<int>(workers_.size()), std::memory_order_relaxed);
  epoch_.fetch_add(1, std::memory_order_release);
  epoch_.notify_all();
  drainChunks(0);
  // Workers finish their last chunk; spin briefly, since steps are short.
  while (busyWorkers_.load(std::memory_order_acquire) != 0) std::this_thread::yield();
}

void ThreadPool::workerLoop(int share) {
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
    drainChunks(share);
    busyWorkers_.fetch_sub(1, std::memory_order_acq_rel);
  }
}

}  // namespace pak
