#pragma once
// Growth (thesis 4.5.1 and 5.5.3): after every step, the scale factor g of an element
// (RepulsionPak) or of a slice (AnimationPak) grows by k_g Δt while it has room, never past
// the cap where there is one. What "room" means is the simulator's: no vertex inside another
// element, none too far outside the container, and for slices a smooth profile in t.
#include <algorithm>
#include <cassert>
#include <limits>

namespace pak {

class GrowthRule {
 public:
  static constexpr double kNoCap = std::numeric_limits<double>::infinity();

  GrowthRule(double growthRate, double timeStep, double cap = kNoCap)
      : increment_(growthRate * timeStep), cap_(cap) {
    assert(growthRate >= 0.0 && timeStep > 0.0 && cap > 0.0);
  }

  // g after one more step of growth.
  double grown(double g) const { return std::min(cap_, g + increment_); }
  // g after one step of shrinking, never below a tenth of what it was.
  double shrunk(double g) const { return std::max(0.9 * g, g - increment_); }
  // g after this step: grown if there is room, else unchanged.
  double next(double g, bool room) const { return room ? grown(g) : g; }
  // Whether growth could still change g (it is below the cap).
  bool belowCap(double g) const { return g < cap_; }

 private:
  double increment_, cap_;
};

}  // namespace pak
