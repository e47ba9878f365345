#pragma once
// Checkpoints of an AnimationPak run (`pak animate --checkpoint`, `--resume`): the simulation
// state in a small binary file, written atomically, so a long run survives an interruption
// and resumes to a bit-identical result. `fingerprint` identifies the inputs and options the
// state belongs to; reading refuses a checkpoint made for others.
#include <cstdint>
#include <string>

#include "pak/animation/animation.hpp"

namespace pak {

void writeAnimationCheckpoint(const AnimationState& state, std::uint64_t fingerprint, const std::string& path);
// Throws InputError if the file is missing, damaged, or has another fingerprint.
AnimationState readAnimationCheckpoint(const std::string& path, std::uint64_t fingerprint);

// FNV-1a over some bytes, chained: what callers build fingerprints with.
std::uint64_t fingerprintBytes(const std::string& bytes, std::uint64_t seed = 14695981039346656037ull);

}  // namespace pak
