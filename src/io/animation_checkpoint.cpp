#include "pak/io/animation_checkpoint.hpp"

#include <cassert>

#include <cmath>
#include <cstring>

#include "pak/error.hpp"
#include "pak/io/atomic_file.hpp"
#include "pak/io/text_file.hpp"

namespace pak {

namespace {

constexpr char kMagic[8] = {'P', 'A', 'K', 'A', 'N', 'I', 'M', '4'};

template <class T>
void put(std::string& out, const T& value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

class Reader {
 public:
  Reader(const std::string& bytes, const std::string& path) : bytes_(bytes), path_(path) {}
  template <class T>
  T get() {
    T value;
    if (offset_ + sizeof value > bytes_.size()) throw InputError(path_, "checkpoint is truncated");
    std::memcpy(&value, bytes_.data() + offset_, sizeof value);
    offset_ += sizeof value;
    return value;
  }
  bool atEnd() const { return offset_ == bytes_.size(); }

 private:
  const std::string& bytes_;
  const std::string& path_;
  std::size_t offset_ = 0;
};

}  // namespace

std::uint64_t fingerprintBytes(const std::string& bytes, std::uint64_t seed) {
  std::uint64_t h = seed;
  for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
  return h;
}

void writeAnimationCheckpoint(const AnimationState& state, std::uint64_t fingerprint, const std::string& path) {
  assert(state.previousGrowth.size() == state.growth.size() && state.neighbourOrigin.size() == state.positions.size());
  std::string out(kMagic, sizeof kMagic);
  put(out, fingerprint);
  put(out, static_cast<std::int64_t>(state.iteration));
  put(out, static_cast<std::uint64_t>(state.positions.size()));
  put(out, static_cast<std::uint64_t>(state.growth.size()));
  for (const Vec3& p : state.positions) put(out, p.x), put(out, p.y), put(out, p.t);
  for (const Vec3& v : state.velocities) put(out, v.x), put(out, v.y), put(out, v.t);
  for (const Vec3& p : state.neighbourOrigin) put(out, p.x), put(out, p.y), put(out, p.t);
  for (double g : state.growth) put(out, g);
  for (double g : state.previousGrowth) put(out, g);
  put(out, static_cast<std::uint64_t>(state.recentMeanGrowth.size()));
  for (double g : state.recentMeanGrowth) put(out, g);
  put(out, static_cast<std::int64_t>(state.recorded));
  writeFileAtomically(path, out);
}

AnimationState readAnimationCheckpoint(const std::string& path, std::uint64_t fingerprint) {
  const std::string bytes = readTextFile(path);
  if (bytes.size() < sizeof kMagic || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
    throw InputError(path, "not a pak animate checkpoint");
  Reader in(bytes, path);
  for (std::size_t k = 0; k < sizeof kMagic; ++k) in.get<char>();
  if (in.get<std::uint64_t>() != fingerprint)
    throw InputError(path, "checkpoint was made for other inputs or options; run again without --resume");
  AnimationState state;
  const std::int64_t iteration = in.get<std::int64_t>();
  const std::uint64_t vertices = in.get<std::uint64_t>(), slices = in.get<std::uint64_t>();
  if (iteration < 0 || vertices > (bytes.size() / 72) || slices > bytes.size() / 8)
    throw InputError(path, "checkpoint header is damaged");
  state.iteration = static_cast<int>(iteration);
  auto vec = [&] {
    Vec3 p;
    p.x = in.get<double>(), p.y = in.get<double>(), p.t = in.get<double>();
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.t)) throw InputError(path, "checkpoint holds a non-finite number");
    return p;
  };
  state.positions.reserve(vertices);
  for (std::uint64_t k = 0; k < vertices; ++k) state.positions.push_back(vec());
  state.velocities.reserve(vertices);
  for (std::uint64_t k = 0; k < vertices; ++k) state.velocities.push_back(vec());
  state.neighbourOrigin.reserve(vertices);
  for (std::uint64_t k = 0; k < vertices; ++k) state.neighbourOrigin.push_back(vec());
  state.growth.reserve(slices);
  for (std::uint64_t k = 0; k < slices; ++k) state.growth.push_back(in.get<double>());
  state.previousGrowth.reserve(slices);
  for (std::uint64_t k = 0; k < slices; ++k) state.previousGrowth.push_back(in.get<double>());
  const std::uint64_t window = in.get<std::uint64_t>();
  if (window > bytes.size() / 8) throw InputError(path, "checkpoint is damaged");
  for (std::uint64_t k = 0; k < window; ++k) state.recentMeanGrowth.push_back(in.get<double>());
  const std::int64_t recorded = in.get<std::int64_t>();
  if (recorded < 0) throw InputError(path, "checkpoint is damaged");
  state.recorded = static_cast<int>(recorded);
  if (!in.atEnd()) throw InputError(path, "checkpoint has trailing bytes");
  return state;
}

}  // namespace pak
