#pragma once
// A run's wall-clock budget (--time-limit) and the caller's request to stop (Ctrl-C): the stop
// tests ask whether either has come. A run that stops on them depends on the machine's speed
// or on the user, unlike every other stop.
#include <atomic>
#include <chrono>

namespace pak {

class Deadline {
 public:
  using Clock = std::chrono::steady_clock;
  // `seconds` ≤ 0: no limit; `request` null: no request.
  Deadline(Clock::time_point start, double seconds, const std::atomic<bool>* request = nullptr)
      : start_(start), seconds_(seconds), request_(request) {}
  bool requested() const { return request_ && request_->load(std::memory_order_relaxed); }
  bool passed() const {
    return requested() || (seconds_ > 0.0 && std::chrono::duration<double>(Clock::now() - start_).count() >= seconds_);
  }

 private:
  Clock::time_point start_;
  double seconds_;
  const std::atomic<bool>* request_;
};

}  // namespace pak
