#pragma once
// An estimate of the time left in a run that ends when one of a few measures reaches zero
// (slices still growing, the widest gap above the closeness, say) or at an iteration cap: each
// measure's recent rate of fall and the recent seconds per iteration, over a window of
// progress reports.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <deque>
#include <string>

namespace pak::cli {

class RunEta {
 public:
  static constexpr int kMeasures = 3;
  using Measures = std::array<double, kMeasures>;  // each ≥ 0, the run's end near 0; ∞: not known yet

  explicit RunEta(int iterationCap, int window = 6) : cap_(iterationCap), window_(window) {}

  // "about 40 s left", "at most 90 s left" (only the cap bounds it yet), or "" (too early).
  std::string record(int iteration, double seconds, const Measures& left) {
    samples_.push_back({iteration, seconds, left});
    if (static_cast<int>(samples_.size()) > window_) samples_.pop_front();
    const Sample& a = samples_.front();
    const Sample& b = samples_.back();
    if (b.iteration <= a.iteration || b.seconds <= a.seconds) return "";
    const double perIteration = (b.seconds - a.seconds) / (b.iteration - a.iteration);
    const double toCap = std::max(0, cap_ - iteration) * perIteration;
    double estimate = toCap;
    bool extrapolated = false;
    for (int k = 0; k < kMeasures; ++k) {
      if (!std::isfinite(a.left[k]) || !std::isfinite(b.left[k])) continue;
      const double fall = (a.left[k] - b.left[k]) / (b.iteration - a.iteration);
      if (!(fall > 0.0)) continue;
      estimate = std::min(estimate, std::max(0.0, b.left[k]) / fall * perIteration);
      extrapolated = true;
    }
    return (extrapolated ? "about " : "at most ") + clock(estimate) + " left";
  }

 private:
  static std::string clock(double s) {
    char text[24];
    if (s < 90.0) std::snprintf(text, sizeof text, "%.0f s", std::ceil(s));
    else std::snprintf(text, sizeof text, "%.0f min", std::ceil(s / 60.0));
    return text;
  }
  struct Sample { int iteration; double seconds; Measures left; };
  int cap_, window_;
  std::deque<Sample> samples_;
};

}  // namespace pak::cli
