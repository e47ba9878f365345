// `pak pack --secondary`, fixed elements and `--rigid` / `--preset` as a user runs them.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "pak/scene_loader.hpp"
#include "run_pak.hpp"

using namespace pak::testing;

namespace {

const std::string kQuick = "pack -c examples/fixed-scene.svg -e examples/elements/cat.svg examples/elements/fish.svg "
                           "--count 8 --gap 16 --target-fill 0.45 --max-iterations 700 --quiet";

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

std::string fixedLayer(const std::string& svg) {
  std::size_t begin = svg.find("<g id=\"fixed\"");
  if (begin == std::string::npos) return {};
  return svg.substr(begin, svg.find("</g>", begin) - begin);
}

}  // namespace

TEST(CliPackSecondary, SecondPassFillsPocketsAroundUntouchedFixedElements) {
  ScratchFolder dir("cli-pack-secondary");
  PakRun run = runPak(kQuick + " --secondary examples/elements/star.svg -o " + shellQuoted(dir.file("out.svg")) +
                      " --report " + shellQuoted(dir.file("r.json")));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  auto report = nlohmann::json::parse(readWholeFile(dir.file("r.json")));
  ASSERT_EQ(report["passes"].size(), 2u);
  const auto& primary = report["passes"][0];
  const auto& secondary = report["passes"][1];
  EXPECT_EQ(primary["pass"], "primary");
  EXPECT_EQ(secondary["pass"], "secondary");
  EXPECT_GT(secondary["elements"].get<int>(), 0);
  EXPECT_EQ(report["secondary-count"], secondary["elements"]);
  EXPECT_EQ(report["iterations"].get<int>(), primary["iterations"].get<int>() + secondary["iterations"].get<int>());
  EXPECT_GT(secondary["fill-ratio-art"].get<double>(), primary["fill-ratio-art"].get<double>());
  EXPECT_GT(secondary["fill-ratio-skin"].get<double>(), primary["fill-ratio-skin"].get<double>());
  EXPECT_NEAR(report["fill-ratio-art"].get<double>(), secondary["fill-ratio-art"].get<double>(), 1e-9);
  EXPECT_EQ(report["overlap-count"], 0);  // fixed elements included as one more element
  EXPECT_EQ(report["elements-outside"], 0);
  EXPECT_EQ(report["fixed-count"], 3);
  EXPECT_GT(report["fixed-area-ratio"].get<double>(), 0.01);

  std::string svg = readWholeFile(dir.file("out.svg"));
  EXPECT_EQ(count(svg, "class=\"element secondary\""), secondary["elements"].get<int>());
  EXPECT_EQ(count(svg, "class=\"element\""), 8);

  // The fixed layer: the same bytes whatever was packed, and read back it is the input's
  // geometry and paint.
  PakRun other = runPak("pack -c examples/fixed-scene.svg -e examples/elements/leaf.svg --count 3 --max-iterations 50 "
                        "--seed 9 -q -o " + shellQuoted(dir.file("other.svg")));
  ASSERT_EQ(other.exitCode, 0) << other.err;
  EXPECT_FALSE(fixedLayer(svg).empty());
  EXPECT_EQ(fixedLayer(svg), fixedLayer(readWholeFile(dir.file("other.svg"))));
  pak::Scene input = pak::loadScene(std::string(PAK_SOURCE_DIR) + "/examples/fixed-scene.svg");
  pak::Scene output = pak::loadScene(dir.file("out.svg"));
  ASSERT_EQ(output.fixed.size(), input.fixed.size());
  for (std::size_t i = 0; i < input.fixed.size(); ++i) {
    EXPECT_EQ(output.fixed[i].fill, input.fixed[i].fill) << i;
    EXPECT_EQ(output.fixed[i].stroke, input.fixed[i].stroke) << i;
    EXPECT_DOUBLE_EQ(output.fixed[i].strokeWidth, input.fixed[i].strokeWidth) << i;
    ASSERT_EQ(output.fixed[i].subpaths.size(), input.fixed[i].subpaths.size()) << i;
    for (std::size_t k = 0; k < input.fixed[i].subpaths.size(); ++k) {
      const auto& a = output.fixed[i].subpaths[k].points;
      const auto& b = input.fixed[i].subpaths[k].points;
      ASSERT_EQ(a.size(), b.size());
      for (std::size_t p = 0; p < a.size(); ++p) EXPECT_LE(pak::distance(a[p], b[p]), 0.5e-3 * std::sqrt(2.0) + 1e-9) << i << " " << p;
    }
  }
}

TEST(CliPackSecondary, RigidIsStiffAndOverlapFreeAndFlagsWinOverPresets) {
  ScratchFolder dir("cli-pack-rigid");
  const std::string base = "pack -c examples/scene.svg -e examples/elements --count 8 --gap 16 --target-fill 0.45 "
                           "--seed 2 --quiet -o " + shellQuoted(dir.file("out.svg"));
  PakRun run = runPak(base + " --max-iterations 3000 --rigid --report " + shellQuoted(dir.file("rigid.json")));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  auto rigid = nlohmann::json::parse(readWholeFile(dir.file("rigid.json")));
  EXPECT_EQ(rigid["preset"], "rigid");
  EXPECT_EQ(rigid["parameters"]["k-edge"], 1000.0);
  EXPECT_LT(rigid["max-edge-strain"].get<double>(), 0.1);
  EXPECT_LT(rigid["mean-edge-strain"].get<double>(), 0.01);
  EXPECT_EQ(rigid["overlap-count"], 0);
  EXPECT_EQ(rigid["elements-outside"], 0);

  run = runPak(base + " --preset rigid --k-edge 500 --max-iterations 10 --report " + shellQuoted(dir.file("r2.json")));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  auto mixed = nlohmann::json::parse(readWholeFile(dir.file("r2.json")));
  EXPECT_EQ(mixed["parameters"]["k-edge"], 500.0);
  EXPECT_EQ(mixed["parameters"]["max-iterations"], 10);
  EXPECT_EQ(mixed["parameters"]["time-step"], rigid["parameters"]["time-step"]);

  for (const std::string bad : {" --preset wobbly", " --rigid --preset soft", " --secondary no/such/folder"}) {
    PakRun failed = runPak(base + bad);
    EXPECT_EQ(failed.exitCode, 2) << bad;
    ASSERT_EQ(failed.errLines().size(), 1u) << failed.err;
    EXPECT_EQ(failed.errLines()[0].rfind("pak: error: ", 0), 0u) << failed.err;
  }
}
