// Golden results: the exact outcome (a hash of every output coordinate, and the iteration
// count) of four small runs. Any change to the numbers a packer produces fails here, so it is
// seen in review. To accept a deliberate change, rewrite the expected file with:
//   PAK_UPDATE_GOLDEN=1 build/test/pak_tests --gtest_filter='Golden.*'
// and commit tests/golden/expected.txt with the change that moved the numbers.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "pak/io/animation_script_reader.hpp"
#include "pak/io/scene_loader.hpp"
#include "pak/pak.hpp"
#include "pak/repulsion/tiling.hpp"

using namespace pak;

namespace {

const std::string kExamples = std::string(PAK_SOURCE_DIR) + "/examples";
const std::string kExpectedFile = std::string(PAK_SOURCE_DIR) + "/tests/golden/expected.txt";

// FNV-1a over the bit patterns of the values.
struct Hash {
  std::uint64_t value = 0xcbf29ce484222325ull;
  void add(std::uint64_t bits) {
    for (int k = 0; k < 8; ++k) {
      value ^= (bits >> (8 * k)) & 0xff;
      value *= 0x100000001b3ull;
    }
  }
  void add(double d) { add(std::bit_cast<std::uint64_t>(d)); }
  void add(Vec2 p) { add(p.x), add(p.y); }
};

struct Golden {
  std::uint64_t hash = 0;
  int iterations = 0;
  friend bool operator==(const Golden&, const Golden&) = default;
};

Golden goldenOf(const Packing& packing) {
  Hash h;
  for (const PlacedElement& e : packing.elements) {
    h.add(e.growth);
    for (Vec2 p : e.meshVertices) h.add(p);
    for (const Shape& s : e.art) {
      h.add(s.strokeWidth);
      for (const Subpath& sub : s.subpaths)
        for (Vec2 p : sub.points) h.add(p);
    }
  }
  return {h.value, packing.iterations};
}

Golden goldenOf(const AnimatedPacking& animation) {
  Hash h;
  for (const AnimatedElement& e : animation.elements) {
    for (double t : e.sliceTimes) h.add(t);
    for (double g : e.sliceGrowth) h.add(g);
    for (const auto& slice : e.slices)
      for (Vec2 p : slice) h.add(p);
  }
  return {h.value, animation.iterations};
}

std::map<std::string, Golden> readExpected() {
  std::map<std::string, Golden> expected;
  std::ifstream in(kExpectedFile);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string name, hash;
    Golden g;
    fields >> name >> hash >> g.iterations;
    g.hash = std::stoull(hash, nullptr, 16);
    expected[name] = g;
  }
  return expected;
}

void writeExpected(const std::map<std::string, Golden>& results) {
  std::ofstream out(kExpectedFile);
  out << "# name  hash  iterations (written by PAK_UPDATE_GOLDEN=1; see golden_results_test.cpp)\n";
  for (const auto& [name, g] : results) {
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(g.hash));
    out << name << ' ' << hex << ' ' << g.iterations << '\n';
  }
}

// Compares with the expected file, or records the result when PAK_UPDATE_GOLDEN is set.
void check(const std::string& name, const Golden& actual) {
  if (std::getenv("PAK_UPDATE_GOLDEN")) {
    std::map<std::string, Golden> all = readExpected();
    all[name] = actual;
    writeExpected(all);
    return;
  }
  const std::map<std::string, Golden> expected = readExpected();
  auto it = expected.find(name);
  ASSERT_NE(it, expected.end()) << name << " is not in " << kExpectedFile << "; record it with PAK_UPDATE_GOLDEN=1";
  EXPECT_EQ(actual.iterations, it->second.iterations) << name;
  EXPECT_EQ(actual.hash, it->second.hash) << name << ": the packing's numbers changed";
}

RepulsionOptions shortRun() {
  RepulsionOptions o;
  o.count = 10;
  o.stop.maxIterations = 300;
  o.run.seed = 5;
  o.run.threads = 2;
  return o;
}

}  // namespace

TEST(Golden, ExampleFish) {
  const Scene scene = loadScene(kExamples + "/scene.svg").scene;
  const Library library = loadLibrary({kExamples + "/elements"});
  check("example-fish", goldenOf(packRepulsion(scene, library, shortRun())));
}

TEST(Golden, Tile) {
  RepulsionOptions options = shortRun();
  options.tiling.size = {1000.0, 1000.0};
  const Library library = loadLibrary({kExamples + "/elements"});
  check("tile", goldenOf(packRepulsion(tileScene(options.tiling.size), library, options)));
}

TEST(Golden, SecondaryPass) {
  const Scene scene = loadScene(kExamples + "/scene.svg").scene;
  const Library library = loadLibrary({kExamples + "/elements"});
  const Library secondary = loadLibrary({kExamples + "/elements/star.svg"});
  RepulsionOptions options = shortRun();
  options.stop.targetFill = 0.5;
  check("secondary-pass", goldenOf(packRepulsion(scene, library, secondary, options)));
}

TEST(Golden, ShortSpacetimeRun) {
  const std::string dir = kExamples + "/animate/stars";
  const AnimationScript script = readAnimationScript(dir + "/stars.json");
  const Scene scene = loadScene(dir + "/disc.svg").scene;
  Library library;
  for (const AnimatedElementSpec& spec : script.elements) library.push_back(loadLibrary({spec.svg}).front());
  AnimationOptions options;
  options.slices = 8;
  options.stop.maxIterations = 60;
  options.run.seed = 2;
  options.run.threads = 2;
  check("spacetime", goldenOf(packAnimation(scene, library, script, options)));
}
