#include "sim/simulation_loop.hpp"

#include <gtest/gtest.h>

#include <vector>

using namespace pak;

namespace {

// A stand-in simulation whose value rises by `rate` per step until `stallAt`, then stays.
struct Ramp {
  int iteration_ = 0;
  double value = 0.0, rate = 1.0;
  int stallAt = 1000;
  int iteration() const { return iteration_; }
  void step() {
    ++iteration_;
    if (iteration_ <= stallAt) value += rate;
  }
};

enum class Stop { Target, Stalled };

}  // namespace

TEST(SimulationLoop, StopsAtTheFirstTestThatFires) {
  Ramp ramp;
  StallWindow window(4);
  std::vector<int> seen;
  auto reason = runUntilStopped<Stop>(
      ramp, 100, window, [&] { return ramp.value; }, [&](int it) { seen.push_back(it); },
      [&](const StallWindow&) -> std::optional<Stop> {
        if (ramp.value >= 3.0) return Stop::Target;
        return std::nullopt;
      });
  EXPECT_EQ(reason, Stop::Target);
  EXPECT_EQ(ramp.iteration(), 3);
  // Callbacks ran after every step but the one the run stopped on: a checkpoint taken there
  // would be resumed a step past the stop.
  EXPECT_EQ(seen, (std::vector<int>{1, 2}));
  EXPECT_EQ(window.recorded(), 3);
}

TEST(SimulationLoop, StallWindowEndsARunThatStopsGrowing) {
  Ramp ramp;
  ramp.stallAt = 10;
  StallWindow window(4);
  auto reason = runUntilStopped<Stop>(
      ramp, 100, window, [&] { return ramp.value; }, [](int) {},
      [&](const StallWindow& w) -> std::optional<Stop> {
        if (w.full() && w.rms() < 0.5) return Stop::Stalled;
        return std::nullopt;
      });
  EXPECT_EQ(reason, Stop::Stalled);
  // Steps of 1 until iteration 10, then 0: RMS over 4 steps drops below 0.5 once at most one
  // of them is 1 (sqrt(1/4) = 0.5 is not below), i.e. at iteration 14.
  EXPECT_EQ(ramp.iteration(), 14);
}

TEST(SimulationLoop, ReturnsNothingAtTheIterationCap) {
  Ramp ramp;
  StallWindow window(2);
  auto reason = runUntilStopped<Stop>(
      ramp, 25, window, [&] { return ramp.value; }, [](int) {}, [](const StallWindow&) { return std::optional<Stop>{}; });
  EXPECT_FALSE(reason.has_value());
  EXPECT_EQ(ramp.iteration(), 25);
}
