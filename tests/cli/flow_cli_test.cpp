// `pak flow` as a user runs it on the bundled FLOWPAK examples: valid packings, the report's
// figures, snapshots, debug layers, determinism and one-line errors.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "run_pak.hpp"

using namespace pak::testing;

namespace {

// Small settings so the sanitizer build stays quick.
const std::string kQuick = " --iterations 2 --field-resolution 96 --blob-resolution 256 --shift-neighbours 40 -q";

TEST(CliFlow, KoiIsPackedWithoutOverlapsAndReported) {
  ScratchFolder dir("cli-flow-koi");
  PakRun run = runPak("flow examples/flow/koi.svg -e examples/flow/elements" + kQuick + " -o " +
                      shellQuoted(dir.file("koi.svg")) + " --report " + shellQuoted(dir.file("koi.json")) +
                      " --snapshots " + shellQuoted(dir.file("snaps")) + " --debug-layers");
  ASSERT_EQ(run.exitCode, 0) << run.err;
  auto report = nlohmann::json::parse(readWholeFile(dir.file("koi.json")));
  // Ornament by default (issue 16): about --count 100 elements, at the density reported.
  EXPECT_GE(report["element-count"].get<int>(), 80);
  EXPECT_LE(report["element-count"].get<int>(), 150);
  EXPECT_NEAR(report["density"]["gap"].get<double>(), 21.3, 0.5);
  EXPECT_GT(report["density"]["max-length"].get<double>(), report["density"]["min-length"].get<double>());
  EXPECT_GT(report["density"]["spacing"].get<double>(), 0.0);
  EXPECT_EQ(report["overlap-count"], 0);
  EXPECT_EQ(report["elements-outside"], 0);
  EXPECT_EQ(report["self-intersecting-outlines"], 0) << report["problems"];
  EXPECT_EQ(report["iterations"], 2);
  auto areas = report["element-area-per-iteration"];
  ASSERT_EQ(areas.size(), 3u);
  EXPECT_GE(areas[2].get<double>(), areas[0].get<double>());
  EXPECT_GT(report["fill-ratio-art"].get<double>(), 0.2);
  // One snapshot after placement and one per iteration.
  for (const char* name : {"iteration-000.svg", "iteration-001.svg", "iteration-002.svg"})
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "snaps" / name)) << name;
  std::string svg = readWholeFile(dir.file("koi.svg"));
  for (const char* layer : {"id=\"container\"", "id=\"elements\"", "id=\"field\"", "id=\"streamlines\"", "id=\"blobs\""})
    EXPECT_NE(svg.find(layer), std::string::npos) << layer;
  // Colours of the library are kept.
  EXPECT_NE(svg.find("#c8553d"), std::string::npos);
}

TEST(CliFlow, MedallionKeepsItsFixedSunAndFixedSpinesAndIsDeterministic) {
  ScratchFolder dir("cli-flow-medallion");
  std::string common = "flow examples/flow/medallion.svg -e examples/flow/elements" + kQuick + " --gap 80 --seed 3";
  PakRun a = runPak(common + " -o " + shellQuoted(dir.file("a.svg")) + " --report " + shellQuoted(dir.file("a.json")));
  PakRun b = runPak(common + " -o " + shellQuoted(dir.file("b.svg")));
  PakRun polygons = runPak(common + " --polyline -o " + shellQuoted(dir.file("c.svg")) + " --report " +
                           shellQuoted(dir.file("c.json")));
  ASSERT_EQ(polygons.exitCode, 0) << polygons.err;
  ASSERT_EQ(a.exitCode, 0) << a.err;
  ASSERT_EQ(b.exitCode, 0) << b.err;
  EXPECT_EQ(readWholeFile(dir.file("a.svg")), readWholeFile(dir.file("b.svg")));
  // Curves by default, polygons with --polyline; the curves take fewer points and keep within
  // their tolerance of the polygons (0.4 canonical units).
  EXPECT_NE(readWholeFile(dir.file("a.svg")).find(" C"), std::string::npos);
  EXPECT_EQ(readWholeFile(dir.file("c.svg")).find(" C"), std::string::npos);
  auto report = nlohmann::json::parse(readWholeFile(dir.file("a.json")));
  auto polygonReport = nlohmann::json::parse(readWholeFile(dir.file("c.json")));
  EXPECT_EQ(report["output-outlines"], "cubic Béziers");
  EXPECT_EQ(polygonReport["output-outlines"], "polygons");
  EXPECT_LT(report["output-points"].get<int>(), polygonReport["output-points"].get<int>());
  EXPECT_GT(report["output-largest-curve-deviation"].get<double>(), 0.0);
  EXPECT_LE(report["output-largest-curve-deviation"].get<double>(), 0.4 * 1.05);
  EXPECT_EQ(polygonReport["output-largest-curve-deviation"], 0.0);
  EXPECT_EQ(report["overlap-count"], 0);  // the fixed sun counts as an element here
  EXPECT_EQ(report["elements-outside"], 0);
  EXPECT_GE(report["element-count"].get<int>(), 8);
  std::string svg = readWholeFile(dir.file("a.svg"));
  EXPECT_NE(svg.find("id=\"fixed\""), std::string::npos);
  EXPECT_NE(svg.find("#f2b632"), std::string::npos);  // the sun's colour
}

TEST(CliFlow, EachContainerMayNameItsOwnDensityAndElements) {
  ScratchFolder dir("cli-flow-regions");
  // Two equal squares with guides; the left asks for streamlines twice as dense and for the
  // leaf only.
  std::string scene = dir.write(
      "scene.svg",
      R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 420 200"><g id="container">)"
      R"(<rect x="0" y="0" width="200" height="200" data-gap="30" data-elements="leaf.svg"/>)"
      R"(<rect x="220" y="0" width="200" height="200" data-gap="60"/></g>)"
      R"(<g id="guides"><path d="M 10 100 L 190 100" fill="none" stroke="red"/>)"
      R"(<path d="M 230 100 L 410 100" fill="none" stroke="red"/></g></svg>)");
  std::filesystem::copy_file(std::filesystem::path(PAK_SOURCE_DIR) / "examples/flow/elements/leaf.svg",
                             dir.path() / "leaf.svg");
  PakRun run = runPak("flow " + shellQuoted(scene) + " -e examples/flow/elements/teardrop.svg" + kQuick +
                      " --min-length 40 -o " + shellQuoted(dir.file("o.svg")) + " --report " + shellQuoted(dir.file("r.json")));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  auto report = nlohmann::json::parse(readWholeFile(dir.file("r.json")));
  auto counts = report["elements-per-container"];
  ASSERT_EQ(counts.size(), 2u);
  EXPECT_GT(counts[0].get<int>(), counts[1].get<int>());
  EXPECT_EQ(report["overlap-count"], 0);
  std::string svg = readWholeFile(dir.file("o.svg"));
  EXPECT_NE(svg.find("data-source=\"leaf.svg\""), std::string::npos);
  EXPECT_NE(svg.find("data-source=\"teardrop.svg\""), std::string::npos);
  // A bad density is one error line.
  std::string bad = dir.write("bad.svg", R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">)"
                                         R"(<g id="container"><rect width="100" height="100" data-gap="dense"/></g>)"
                                         R"(<g id="guides"><path d="M 0 50 L 100 50"/></g></svg>)");
  PakRun failed = runPak("flow " + shellQuoted(bad) + " -e examples/flow/elements -o " + shellQuoted(dir.file("b.svg")));
  EXPECT_EQ(failed.exitCode, 2);
  ASSERT_EQ(failed.errLines().size(), 1u) << failed.err;
  EXPECT_NE(failed.err.find("data-gap"), std::string::npos);
}

// The koi across its horizontal axis: y=240 and the same line through two points give the
// same file, and every element has its twin.
TEST(CliFlow, MirrorTakesAHorizontalLineOrTwoPoints) {
  ScratchFolder dir("cli-flow-mirror");
  const std::string base = "flow examples/flow/koi.svg -e examples/flow/elements" + kQuick;
  PakRun horizontal = runPak(base + " --mirror y=240 -o " + shellQuoted(dir.file("y.svg")) + " --report " +
                             shellQuoted(dir.file("y.json")));
  ASSERT_EQ(horizontal.exitCode, 0) << horizontal.err;
  PakRun points = runPak(base + " --mirror 60,240,740,240 -o " + shellQuoted(dir.file("p.svg")));
  ASSERT_EQ(points.exitCode, 0) << points.err;
  EXPECT_EQ(readWholeFile(dir.file("y.svg")), readWholeFile(dir.file("p.svg")));
  auto report = nlohmann::json::parse(readWholeFile(dir.file("y.json")));
  EXPECT_GE(report["element-count"].get<int>(), 4);
  EXPECT_EQ(report["element-count"].get<int>() % 2, 0);
  EXPECT_EQ(report["overlap-count"], 0) << report["problems"];
  EXPECT_EQ(report["elements-outside"], 0);
}

// The owl (fixed eyes and beak, mirrored across x = 300): clean, symmetric, no fold.
TEST(CliFlow, TheMirroredOwlIsCleanAndSymmetric) {
  ScratchFolder dir("cli-flow-owl");
  PakRun run = runPak("flow examples/flow/owl.svg -e examples/flow/elements --mirror x=300" + kQuick + " -o " +
                      shellQuoted(dir.file("owl.svg")) + " --report " + shellQuoted(dir.file("owl.json")));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  auto report = nlohmann::json::parse(readWholeFile(dir.file("owl.json")));
  EXPECT_GE(report["element-count"].get<int>(), 10);
  EXPECT_EQ(report["element-count"].get<int>() % 2, 0);
  EXPECT_EQ(report["overlap-count"], 0) << report["problems"];  // the eyes and beak count as an element
  EXPECT_EQ(report["elements-outside"], 0);
  EXPECT_EQ(report["self-intersecting-outlines"], 0);
  EXPECT_NE(readWholeFile(dir.file("owl.svg")).find("#2b2118"), std::string::npos);  // the pupils, copied
}

TEST(CliFlow, BadInputIsOneErrorLineAndExitTwo) {
  ScratchFolder dir("cli-flow-bad");
  std::string out = shellQuoted(dir.file("o.svg"));
  std::string noGuides = dir.write(
      "scene.svg", R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100"><g id="container">)"
                   R"(<rect width="100" height="100"/></g></svg>)");
  std::string badConfig = dir.write("c.json", R"({"iterations": "many"})");
  for (const std::string& args :
       {"flow " + shellQuoted(noGuides) + " -e examples/flow/elements -o " + out,
        "flow examples/flow/koi.svg -e examples/flow/elements -o " + out + " --mirror z=3",
        "flow examples/flow/koi.svg -e examples/flow/elements -o " + out + " --mirror x=10",
        "flow examples/flow/koi.svg -e examples/flow/elements -o " + out + " --mirror 1,2,1,2",
        "flow examples/flow/koi.svg -e examples/flow/elements -o " + out + " --gap -4",
        "flow examples/flow/koi.svg -e examples/flow/elements -o " + out + " --min-length 500 --max-length 100",
        "flow examples/flow/koi.svg -e examples/flow/elements -o " + out + " --config " + shellQuoted(badConfig),
        "flow examples/flow/koi.svg -e examples/flow/elements -o " + out + " --snapshots " +
            shellQuoted(dir.file("s")) + " --every 0",
        "flow examples/flow/koi.svg -e examples/flow/elements -o " + out + " --gap 2furlong",
        "flow examples/flow/koi.svg -e examples/flow/elements -o " + out + " --spacing mm",
        "flow examples/flow/koi.svg -e examples/flow/elements -o " + out + " --config " +
            shellQuoted(dir.write("units.json", R"({"gap": "3 parsecs"})")),
        "flow examples/flow/koi.svg -e no-such-folder -o " + out}) {
    PakRun run = runPak(args);
    EXPECT_EQ(run.exitCode, 2) << args << "\n" << run.err;
    ASSERT_EQ(run.errLines().size(), 1u) << args << "\n" << run.err;
    EXPECT_EQ(run.errLines()[0].rfind("pak: error: ", 0), 0u) << run.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("o.svg"))) << args;
  }
}

// Lengths with units (issue 17, item 5): 3 % of l_canvas is 30 canonical units, and a
// document 200 mm wide over an 800-unit viewBox has 4 units to the millimetre; the koi's
// l_canvas is 680 units. A length with a unit gives the run its canonical equivalent gives.
TEST(CliFlow, LengthsTakeUnitsAndGiveTheRunTheirCanonicalValueGives) {
  ScratchFolder dir("cli-flow-units");
  std::string koi = readWholeFile(std::filesystem::path(PAK_SOURCE_DIR) / "examples/flow/koi.svg");
  const std::string size = R"(width="800" height="480")";
  ASSERT_NE(koi.find(size), std::string::npos);
  koi.replace(koi.find(size), size.size(), R"(width="200mm" height="120mm")");
  const std::string koiMm = dir.write("koi-mm.svg", koi);
  const std::string common = " -e examples/flow/elements" + kQuick + " --count 30";
  auto run = [&](const std::string& scene, const std::string& lengths, const std::string& name) {
    PakRun r = runPak("flow " + shellQuoted(scene) + common + lengths + " -o " + shellQuoted(dir.file(name + ".svg")) +
                      " --report " + shellQuoted(dir.file(name + ".json")));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return nlohmann::json::parse(readWholeFile(dir.file(name + ".json")));
  };
  const auto units = run(koiMm, " --gap 3% --spacing 0.5mm", "units");
  EXPECT_EQ(units["lengths-given"], (nlohmann::json{{"gap", "3%"}, {"spacing", "0.5mm"}}));
  EXPECT_DOUBLE_EQ(units["parameters"]["gap"].get<double>(), 30.0);
  const double spacing = units["parameters"]["spacing"].get<double>();
  EXPECT_NEAR(spacing, 0.5 * 4.0 * 1000.0 / 680.0, 1e-9);
  char exact[32];  // the same double back
  std::snprintf(exact, sizeof exact, "%.17g", spacing);
  const auto plain = run("examples/flow/koi.svg", " --gap 30 --spacing " + std::string(exact), "plain");
  EXPECT_EQ(plain["lengths-given"], nlohmann::json::object());
  EXPECT_EQ(units["element-count"], plain["element-count"]);
  EXPECT_DOUBLE_EQ(units["fill-ratio-art"].get<double>(), plain["fill-ratio-art"].get<double>());
  // The same from a --config file.
  const std::string config = dir.write("c.json", R"({"gap": "3%", "spacing": "0.5mm"})");
  const auto configured = run(koiMm, " --config " + shellQuoted(config), "configured");
  EXPECT_EQ(configured["lengths-given"], units["lengths-given"]);
  EXPECT_EQ(readWholeFile(dir.file("configured.svg")), readWholeFile(dir.file("units.svg")));
}

}  // namespace
