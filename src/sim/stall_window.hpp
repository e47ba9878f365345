#pragma once
// The memory of a stall rule (thesis 4.5.2, eq. 4.7): the values A of the last w + 1
// iterations, in a ring indexed by iteration number. RepulsionPak stops when the RMS of the
// steps A_i − A_(i−1) over the window falls below ε; AnimationPak when the rise of the slices'
// mean growth over the window does. The ring and its count are the rule's whole state, so a
// checkpoint that saves them (values, recorded) resumes to the same stop.
#include <cassert>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace pak {

class StallWindow {
 public:
  // window w ≥ 1 iterations: w + 1 values.
  explicit StallWindow(int window) : window_(window), values_(static_cast<std::size_t>(window) + 1, 0.0) {
    assert(window >= 1);
  }

  // The value of iteration `iteration`, the one after the last recorded.
  void record(int iteration, double value) {
    assert(iteration >= 0);
    values_[slot(iteration)] = value;
    latest_ = iteration;
    ++recorded_;
  }

  // Whether w + 1 values have been recorded: the window is complete.
  bool full() const { return recorded_ > window_; }

  // Eq. 4.7 over the window ending at the latest iteration: sqrt(1/w Σ (A_i − A_(i−1))²).
  double rms() const {
    assert(full());
    const int first = latest_ - window_;
    double sum = 0.0;
    for (int i = 1; i <= window_; ++i) {
      const double d = values_[slot(first + i)] - values_[slot(first + i - 1)];
      sum += d * d;
    }
    return std::sqrt(sum / window_);
  }

  // A_w − A_0: how much the value rose over the window.
  double rise() const {
    assert(full());
    return values_[slot(latest_)] - values_[slot(latest_ - window_)];
  }

  // The state: the ring (slot = iteration mod (w + 1)) and how many values it has seen.
  const std::vector<double>& values() const { return values_; }
  int recorded() const { return recorded_; }
  // Back to a saved state whose latest value is that of `latestIteration`.
  void restore(std::vector<double> values, int recorded, int latestIteration) {
    assert(values.size() == values_.size() && recorded >= 0 && latestIteration >= 0);
    values_ = std::move(values);
    recorded_ = recorded;
    latest_ = latestIteration;
  }

 private:
  std::size_t slot(int iteration) const {
    assert(iteration >= 0);
    return static_cast<std::size_t>(iteration % (window_ + 1));
  }

  int window_;
  std::vector<double> values_;
  int recorded_ = 0;
  int latest_ = 0;
};

}  // namespace pak
