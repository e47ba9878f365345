// `pak pack --secondary`, fixed elements and `--rigid` / `--preset` as a user runs them.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "pak/geom/verify.hpp"
#include "pak/io/packing_reader.hpp"
#include "pak/io/scene_loader.hpp"
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
  pak::Scene input = pak::loadScene(std::string(PAK_SOURCE_DIR) + "/examples/fixed-scene.svg").scene;
  pak::Scene output = pak::loadScene(dir.file("out.svg")).scene;
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

// An Inkscape scene's fixed layer comes out byte for byte (with the gradient it uses), the
// packed elements keep off it, and the output still reads back for metrics and render.
TEST(CliPackFixed, InkscapeFixedLayerIsCopiedByteForByteAndNeverOverlapped) {
  const std::string path =
      R"~(<path style="fill:#1d3557;stroke:#000000;stroke-width:1.5" d="m 100,100 c 20,0 40,20 40,40 0,20 -20,40 -40,40 z" id="path846" inkscape:label="Nose &amp; co" sodipodi:nodetypes="cscc" transform="rotate(10 120 140)" />)~";
  const std::string circle = R"~(<circle cx="300" cy="150" r="30" fill="url(#eyeGradient)" id="eye"/>)~";
  const std::string gradient =
      R"~(<radialGradient id="eyeGradient" cx="300" cy="150" r="30" gradientUnits="userSpaceOnUse"><stop offset="0" style="stop-color:#ff0000"/><stop offset="1" stop-color="#0000ff"/></radialGradient>)~";
  ScratchFolder dir("cli-pack-fixed-inkscape");
  const std::string scene = dir.write("scene.svg", R"~(<?xml version="1.0" encoding="UTF-8" standalone="no"?>
<svg xmlns="http://www.w3.org/2000/svg" xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape"
   xmlns:sodipodi="http://sodipodi.sourceforge.net/DTD/sodipodi-0.dtd" width="1000" height="700" viewBox="0 0 1000 700">
  <defs>)~" + gradient + R"~(</defs>
  <g inkscape:label="container" inkscape:groupmode="layer" id="layer1"><rect x="50" y="50" width="900" height="600" fill="#eeeeff"/></g>
  <g transform="translate(10,20)"><g inkscape:label="Fixed" inkscape:groupmode="layer" id="layer2" style="display:inline" transform="scale(2)">
      )~" + path + "\n      " + circle + R"~(
  </g></g>
</svg>
)~");
  const std::string out = dir.file("out.svg");
  PakRun run = runPak("pack -c " + shellQuoted(scene) + " -e examples/elements/cat.svg examples/elements/fish.svg "
                      "--count 6 --gap 16 --max-iterations 400 --seed 1 -q -o " + shellQuoted(out) + " --report " +
                      shellQuoted(dir.file("r.json")));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  auto report = nlohmann::json::parse(readWholeFile(dir.file("r.json")));
  EXPECT_EQ(report["fixed-count"], 2);
  EXPECT_EQ(report["overlap-count"], 0);
  EXPECT_EQ(report["elements-outside"], 0);

  const std::string svg = readWholeFile(out);
  for (const std::string& text : {path, circle, gradient}) EXPECT_NE(svg.find(text), std::string::npos) << text;
  EXPECT_NE(svg.find("xmlns:sodipodi="), std::string::npos);

  // Read back: the same fixed shapes, and no element on them (checked here, not by pak).
  pak::Scene input = pak::loadScene(scene).scene, output = pak::loadScene(out).scene;
  ASSERT_EQ(output.fixed.size(), input.fixed.size());
  std::vector<pak::Region> fixedArt;
  for (std::size_t i = 0; i < input.fixed.size(); ++i) {
    EXPECT_EQ(output.fixed[i].fill, input.fixed[i].fill) << i;
    EXPECT_NEAR(pak::area(pak::paintedRegion(output.fixed[i])), pak::area(pak::paintedRegion(input.fixed[i])), 1e-6) << i;
    fixedArt.push_back(pak::paintedRegion(input.fixed[i]));
  }
  pak::PackingGeometry packing = pak::readPacking(out);
  ASSERT_EQ(packing.elements.size(), 6u);
  std::vector<pak::Region> checked = packing.elements;
  checked.push_back(pak::unite(fixedArt));
  pak::PackingCheckOptions options;
  options.areaTolerance = 1e-6 * pak::area(packing.container);
  pak::PackingCheck check = pak::verifyPacking(checked, packing.container, options);
  EXPECT_TRUE(check.ok) << (check.problems.empty() ? "" : check.problems[0]);

  EXPECT_EQ(runPak("metrics " + shellQuoted(out) + " --radii 20 --grid 200 --bins 10").exitCode, 0);
  PakRun render = runPak("render " + shellQuoted(out) + " -o " + shellQuoted(dir.file("out.png")) + " --width 200");
  EXPECT_EQ(render.exitCode, 0) << render.err;
}

// This run used to end with the cat's art 1 unit² past the fish's wall: its skin vertices
// rested slightly outside, where the penalty boundary force balances its neighbours. A run
// whose art does not check clean gets its outside vertices projected onto the wall, and what
// still crosses it between two vertices contracted a little (cleanArt).
TEST(CliPackFixed, OutsideVerticesAreProjectedBackWhenTheArtIsNotClean) {
  ScratchFolder dir("cli-pack-fixed-project");
  PakRun run = runPak("pack -c examples/fixed-scene.svg -e examples/elements --count 8 --seed 1 -q -o " +
                      shellQuoted(dir.file("out.svg")) + " --report " + shellQuoted(dir.file("r.json")));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  auto report = nlohmann::json::parse(readWholeFile(dir.file("r.json")));
  EXPECT_EQ(report["elements-outside"], 0) << report["problems"];
  EXPECT_EQ(report["overlap-count"], 0) << report["problems"];
  // The projection and the contraction are not simulation steps: the total is growth plus the
  // clean-up. (2164 since strokes have SVG's butt caps and miter joins; 1099 with round ones.)
  EXPECT_EQ(report["iterations"].get<int>() - report["passes"][0]["settle-iterations"].get<int>(), 2164);
}
