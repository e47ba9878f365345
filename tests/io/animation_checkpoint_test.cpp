// Checkpoints round-trip bit for bit and refuse files that are not theirs.
#include "pak/io/animation_checkpoint.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "pak/error.hpp"
#include "pak/io/text_file.hpp"

namespace pak {
namespace {

std::string scratch(const char* name) { return (std::filesystem::temp_directory_path() / name).string(); }

AnimationState sampleState() {
  AnimationState s;
  s.iteration = 1234;
  s.positions = {{1.0, 2.0, 0.0}, {0.1 + 0.2, -5e-300, 1000.0}};
  s.velocities = {{0.5, -0.25, 1e-3}, {0.0, 0.0, -0.0}};
  s.growth = {0.1, 0.7};
  s.previousGrowth = {0.1, 0.699};
  s.neighbourOrigin = {{0.9, 2.1, 0.0}, {0.25, 1e-9, 999.5}};
  s.recentMeanGrowth = {0.3, 0.31, 0.32};
  s.recorded = 17;
  return s;
}

TEST(AnimationCheckpoint, RoundTripsExactly) {
  const std::string path = scratch("pak-checkpoint-roundtrip.bin");
  const AnimationState s = sampleState();
  writeAnimationCheckpoint(s, 42, path);
  const AnimationState r = readAnimationCheckpoint(path, 42);
  EXPECT_EQ(r.iteration, s.iteration);
  EXPECT_EQ(r.positions, s.positions);
  EXPECT_EQ(r.velocities, s.velocities);
  EXPECT_EQ(r.growth, s.growth);
  EXPECT_EQ(r.previousGrowth, s.previousGrowth);
  EXPECT_EQ(r.neighbourOrigin, s.neighbourOrigin);
  EXPECT_EQ(r.recentMeanGrowth, s.recentMeanGrowth);
  EXPECT_EQ(r.recorded, s.recorded);
  std::filesystem::remove(path);
}

TEST(AnimationCheckpoint, RefusesOtherRunsAndDamagedFiles) {
  const std::string path = scratch("pak-checkpoint-bad.bin");
  writeAnimationCheckpoint(sampleState(), 42, path);
  EXPECT_THROW(readAnimationCheckpoint(path, 43), InputError);  // another run's
  const std::string bytes = readTextFile(path);
  std::ofstream(path, std::ios::binary) << bytes.substr(0, bytes.size() - 5);
  EXPECT_THROW(readAnimationCheckpoint(path, 42), InputError);  // truncated
  std::ofstream(path, std::ios::binary) << "not a checkpoint at all";
  EXPECT_THROW(readAnimationCheckpoint(path, 42), InputError);
  std::filesystem::remove(path);
  EXPECT_THROW(readAnimationCheckpoint(path, 42), InputError);  // missing
}

TEST(AnimationCheckpoint, FingerprintsDifferForDifferentBytes) {
  EXPECT_NE(fingerprintBytes("a"), fingerprintBytes("b"));
  EXPECT_EQ(fingerprintBytes("abc"), fingerprintBytes("c", fingerprintBytes("ab")));
}

}  // namespace
}  // namespace pak
