#pragma once
// A run's wall-clock budget (--time-limit): the stop tests ask whether it is spent. A run that
// stops on it depends on the machine's speed, unlike every other stop.
#include <chrono>

namespace pak {

class Deadline {
 public:
  using Clock = std::chrono::steady_clock;
  // `seconds` ≤ 0: no limit.
  Deadline(Clock::time_point start, double seconds) : start_(start), seconds_(seconds) {}
  bool passed() const {
    return seconds_ > 0.0 && std::chrono::duration<double>(Clock::now() - start_).count() >= seconds_;
  }

 private:
  Clock::time_point start_;
  double seconds_;
};

}  // namespace pak
