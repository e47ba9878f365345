// `pak pack` as a user runs it: output layout, report, snapshots, config errors.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <regex>

#include "run_pak.hpp"

using namespace pak::testing;

namespace {
const std::string kQuick = "pack -c examples/scene.svg -e examples/elements --count 6 --gap 20 --max-iterations 300 --quiet";

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}
}  // namespace

TEST(CliPack, WritesTheOutputLayoutAndAReport) {
  ScratchFolder dir("cli-pack");
  PakRun run = runPak(kQuick + " -o " + shellQuoted(dir.file("out.svg")) + " --png " + shellQuoted(dir.file("out.png")) +
                      " --report " + shellQuoted(dir.file("report.json")) + " --snapshots " +
                      shellQuoted(dir.file("snaps")) + " --every 100");
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_TRUE(run.err.empty()) << run.err;  // --quiet
  std::string svg = readWholeFile(dir.file("out.svg"));
  EXPECT_EQ(count(svg, "<g id=\"container\""), 1);
  EXPECT_EQ(count(svg, "<g id=\"elements\""), 1);
  EXPECT_EQ(count(svg, "class=\"element\""), 6);
  EXPECT_EQ(count(svg, "data-source=\""), 6);
  EXPECT_EQ(count(svg, "id=\"skins\""), 0);  // debug layers only on request
  EXPECT_TRUE(std::filesystem::file_size(dir.file("out.png")) > 1000);
  auto report = nlohmann::json::parse(readWholeFile(dir.file("report.json")));
  EXPECT_EQ(report["element-count"], 6);
  // 300 iterations of growth, then the clean-up's (counted in the total).
  EXPECT_EQ(report["iterations"], 300 + report["passes"][0]["settle-iterations"].get<int>());
  EXPECT_EQ(report["stop-reason"], "iteration-cap");
  EXPECT_EQ(report["parameters"]["gap"], 20.0);
  EXPECT_EQ(report["parameters"]["seed"], 1);
  EXPECT_EQ(report["overlap-count"], 0);
  for (const char* key : {"wall-seconds", "fill-ratio-art", "fill-ratio-skin", "vertex-count", "overlap-area"})
    EXPECT_TRUE(report.contains(key)) << key;
  for (const char* snap : {"snapshot-000100.svg", "snapshot-000200.svg", "snapshot-000300.svg"})
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "snaps" / snap)) << snap;
}

TEST(CliPack, ReportHasTheEvennessPakMetricsMeasuresOnTheOutput) {
  ScratchFolder dir("cli-pack-evenness");
  PakRun run = runPak(kQuick + " -o " + shellQuoted(dir.file("out.svg")) + " --report " + shellQuoted(dir.file("r.json")));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  PakRun metrics = runPak("metrics " + shellQuoted(dir.file("out.svg")) + " --json " + shellQuoted(dir.file("m.json")));
  ASSERT_EQ(metrics.exitCode, 0) << metrics.err;
  auto report = nlohmann::json::parse(readWholeFile(dir.file("r.json")));
  auto measured = nlohmann::json::parse(readWholeFile(dir.file("m.json")))["packings"][0]["evenness"];
  ASSERT_TRUE(report.contains("evenness"));
  // The output SVG rounds coordinates and the medial axis moves with them by a cell here and
  // there, so the two agree closely, not to the bit.
  EXPECT_NEAR(report["evenness"]["negative-ratio"].get<double>(), measured["negative-ratio"].get<double>(), 1e-3);
  for (const char* key : {"P1", "P2", "P3"})
    EXPECT_NEAR(report["evenness"][key].get<double>(), measured[key].get<double>(), 0.03) << key;
  EXPECT_GT(report["evenness"]["P2"].get<double>(), 0.0);  // 300 iterations leave pockets
  // This short run stops mid-growth with element 3 folded; each fold is named in the problems.
  int folds = 0;
  for (const auto& problem : report["problems"]) folds += count(problem.get<std::string>(), "crosses itself");
  EXPECT_EQ(report["self-intersecting-outlines"], folds);
  EXPECT_GT(report["primary-area-cv"].get<double>(), 0.0);
  EXPECT_LT(report["primary-area-cv"].get<double>(), 1.0);
}

// A length with a unit (issue 17, item 5): 2 % of the container's bounding square is 20
// canonical units; the report gives both.
TEST(CliPack, LengthsTakeUnits) {
  ScratchFolder dir("cli-pack-units");
  PakRun run = runPak("pack -c examples/scene.svg -e examples/elements --count 6 --gap 2% --max-iterations 10 --quiet -o " +
                      shellQuoted(dir.file("out.svg")) + " --report " + shellQuoted(dir.file("r.json")));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  auto report = nlohmann::json::parse(readWholeFile(dir.file("r.json")));
  EXPECT_DOUBLE_EQ(report["parameters"]["gap"].get<double>(), 20.0);
  EXPECT_EQ(report["lengths-given"], (nlohmann::json{{"gap", "2%"}}));
  PakRun bad = runPak("pack -c examples/scene.svg -e examples/elements --cell-size 3parsec -o " + shellQuoted(dir.file("b.svg")));
  EXPECT_EQ(bad.exitCode, 2);
  ASSERT_EQ(bad.errLines().size(), 1u) << bad.err;
  EXPECT_EQ(bad.errLines()[0].rfind("pak: error: --cell-size: ", 0), 0u) << bad.err;
}

TEST(CliPack, PetalsDrawnOverlappingAreNotCountedAsFolds) {
  // examples/elements/flower.svg draws its petals as one ring that crosses itself; after one
  // step nothing has deformed, so nothing is folded.
  ScratchFolder dir("cli-pack-drawn-crossing");
  PakRun run = runPak("pack -c examples/scene.svg -e examples/elements/flower.svg --count 4 --max-iterations 1 -q -o " +
                      shellQuoted(dir.file("out.svg")) + " --report " + shellQuoted(dir.file("r.json")));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  auto report = nlohmann::json::parse(readWholeFile(dir.file("r.json")));
  EXPECT_EQ(report["self-intersecting-outlines"], 0) << report["problems"];
}

TEST(CliPack, DebugLayersAddSkinsAndMeshes) {
  ScratchFolder dir("cli-pack-debug");
  PakRun run = runPak("pack -c examples/scene.svg -e examples/elements --count 6 --gap 20 --max-iterations 10 --quiet "
                      "--debug-layers -o " + shellQuoted(dir.file("out.svg")));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  std::string svg = readWholeFile(dir.file("out.svg"));
  EXPECT_EQ(count(svg, "<g id=\"skins\""), 1);
  EXPECT_EQ(count(svg, "<g id=\"meshes\""), 1);
}

TEST(CliPack, ConfigFileSetsOptionsAndFlagsWin) {
  ScratchFolder dir("cli-pack-config");
  std::string config = dir.write("c.json", R"({"gap": 15, "count": 4, "max-iterations": 20})");
  PakRun run = runPak("pack -c examples/scene.svg -e examples/elements -q --config " + shellQuoted(config) +
                      " --count 3 -o " + shellQuoted(dir.file("o.svg")) + " --report " + shellQuoted(dir.file("r.json")));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  auto report = nlohmann::json::parse(readWholeFile(dir.file("r.json")));
  EXPECT_EQ(report["parameters"]["gap"], 15.0);
  EXPECT_EQ(report["element-count"], 3);
}

TEST(CliPack, ConfigFileMayNameThePresetAndTheTile) {
  ScratchFolder dir("cli-pack-config-preset");
  // The file's preset sets the strengths the file does not give; the file's own value wins.
  std::string config = dir.write("c.json", R"({"preset": "rigid", "k-edge": 700, "tile": "300,200", "count": 3,
                                             "max-iterations": 10})");
  PakRun run = runPak("pack -e examples/elements/star.svg -q --config " + shellQuoted(config) + " -o " +
                      shellQuoted(dir.file("o.svg")) + " --report " + shellQuoted(dir.file("r.json")));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  auto report = nlohmann::json::parse(readWholeFile(dir.file("r.json")));
  EXPECT_EQ(report["preset"], "rigid");
  EXPECT_EQ(report["parameters"]["k-edge"], 700.0);
  EXPECT_EQ(report["parameters"]["time-step"], 0.04);  // from the rigid preset
  ASSERT_TRUE(report.contains("tile"));
  EXPECT_EQ(report["tile"][0], 300.0);
  EXPECT_EQ(report["tile"][1], 200.0);
}

TEST(CliPack, BadOptionsAreOneClearErrorLine) {
  ScratchFolder dir("cli-pack-bad");
  std::string out = shellQuoted(dir.file("o.svg"));
  std::string unknown = dir.write("u.json", R"({"gapp": 1})");
  std::string notJson = dir.write("n.json", "{gap:");
  for (const std::string& args :
       {"pack -c examples/scene.svg -e examples/elements -o " + out + " --gap -3",
        "pack -c examples/scene.svg -e examples/elements -o " + out + " --config " + shellQuoted(unknown),
        "pack -c examples/scene.svg -e examples/elements -o " + out + " --config " + shellQuoted(notJson),
        "pack -c examples/scene.svg -e " + shellQuoted(dir.file("none")) + " -o " + out}) {
    PakRun run = runPak(args);
    EXPECT_EQ(run.exitCode, 2) << args;
    ASSERT_EQ(run.errLines().size(), 1u) << args << "\n" << run.err;
    EXPECT_EQ(run.errLines()[0].rfind("pak: error: ", 0), 0u) << run.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("o.svg"))) << args;
  }
}

TEST(CliPack, TileWritesAClippedSeamlessTileAndAPreview) {
  ScratchFolder dir("cli-pack-tile");
  PakRun run = runPak("pack --tile 400,300 -e examples/elements --count 6 --gap 16 --max-iterations 600 --quiet -o " +
                      shellQuoted(dir.file("tile.svg")) + " --tile-preview " + shellQuoted(dir.file("preview.png")) +
                      " --tile-preview-repeat 2 --report " + shellQuoted(dir.file("report.json")));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  std::string svg = readWholeFile(dir.file("tile.svg"));
  EXPECT_NE(svg.find("viewBox=\"0 0 400 300\""), std::string::npos);
  EXPECT_EQ(count(svg, "<clipPath"), 1);
  EXPECT_EQ(count(svg, "clip-path=\"url(#pak-clip-1)\""), 1);
  EXPECT_EQ(count(svg, "class=\"element\""), 6);
  EXPECT_TRUE(std::filesystem::file_size(dir.file("preview.png")) > 1000);
  auto report = nlohmann::json::parse(readWholeFile(dir.file("report.json")));
  EXPECT_EQ(report["tile"], nlohmann::json::array({400.0, 300.0}));
  EXPECT_EQ(report["overlap-count"], 0);      // checked on the torus, seams included
  EXPECT_EQ(report["elements-outside"], 0);   // clones clipped to the tile
}

TEST(CliPack, TileOptionErrors) {
  ScratchFolder dir("cli-pack-tile-errors");
  std::string out = " -o " + shellQuoted(dir.file("x.svg"));
  for (const std::string& args : {std::string("pack --tile 400 -e examples/elements"),
                                  std::string("pack --tile 400,-3 -e examples/elements"),
                                  std::string("pack --tile 400,300 -c examples/scene.svg -e examples/elements"),
                                  std::string("pack -e examples/elements"),
                                  std::string("pack -c examples/scene.svg -e examples/elements --tile-preview p.png")}) {
    PakRun run = runPak(args + out);
    EXPECT_EQ(run.exitCode, 2) << args;
    ASSERT_EQ(run.errLines().size(), 1u) << args << ": " << run.err;
    EXPECT_EQ(run.errLines()[0].rfind("pak: error: ", 0), 0u) << run.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("x.svg")));
  }
}

// What the readers skip in an element file is said by the packing commands too, not only by
// `pak inspect`; --quiet silences it.
TEST(CliPack, WarnsAboutSkippedShapesInElementFiles) {
  ScratchFolder dir("cli-pack-warnings");
  const std::string element = dir.write(
      "labelled.svg", R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">)"
                      R"(<circle cx="50" cy="50" r="40" fill="#c33"/><text x="10" y="90">label</text></svg>)");
  const std::string pack = "pack -c examples/scene.svg -e " + shellQuoted(element) +
                           " --count 3 --max-iterations 5 --progress-every 1000 -o " + shellQuoted(dir.file("out.svg"));
  PakRun run = runPak(pack);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_EQ(count(run.err, "pak: warning: " + element), 1) << run.err;
  EXPECT_NE(run.err.find("<text> is not supported"), std::string::npos) << run.err;
  PakRun quiet = runPak(pack + " --quiet");
  ASSERT_EQ(quiet.exitCode, 0) << quiet.err;
  EXPECT_TRUE(quiet.err.empty()) << quiet.err;

  PakRun flow = runPak("flow examples/flow/koi.svg -e examples/flow/elements " + shellQuoted(element) +
                       " --iterations 0 -o " + shellQuoted(dir.file("flow.svg")));
  ASSERT_EQ(flow.exitCode, 0) << flow.err;
  EXPECT_EQ(count(flow.err, "pak: warning: " + element), 1) << flow.err;
}

// The named warnings of tests/svg/unsupported-effects.svg reach `pak pack` users too.
TEST(CliPack, WarnsAboutEveryUndrawnEffect) {
  ScratchFolder dir("cli-pack-effects");
  PakRun run = runPak("pack -c examples/scene.svg -e tests/svg/unsupported-effects.svg --count 3 --max-iterations 5 "
                      "--progress-every 1000 -o " + shellQuoted(dir.file("out.svg")));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  for (const char* name : {"mask=", "filter=", "mix-blend-mode=", "marker-end=",
                           "<text> is not supported", "<image> is not supported"})
    EXPECT_NE(run.err.find(name), std::string::npos) << name << "\n" << run.err;
  for (const std::string& line : run.errLines()) {
    if (line.find("tests/svg/unsupported-effects.svg") != std::string::npos) {
      EXPECT_EQ(line.rfind("pak: warning: ", 0), 0u) << line;
    }
  }
}

// A dashed stroke keeps its dashes, scaled with the element like its width
// (tests/svg/dashed-badge.svg: width 2, dashes 6 3, offset 1).
TEST(CliPack, DashedStrokesKeepTheirDashesScaledWithTheElement) {
  ScratchFolder dir("cli-pack-dashes");
  PakRun run = runPak("pack -c examples/scene.svg -e tests/svg/dashed-badge.svg --count 4 --max-iterations 50 -q -o " +
                      shellQuoted(dir.file("out.svg")));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_EQ(run.err.find("dasharray"), std::string::npos) << run.err;  // read, not warned about
  const std::string svg = readWholeFile(dir.file("out.svg"));
  const std::regex dashed(R"~(stroke-width="([0-9.]+)" stroke-dasharray="([0-9.]+) ([0-9.]+)" stroke-dashoffset="([0-9.]+)")~");
  int rings = 0;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), dashed); it != std::sregex_iterator(); ++it, ++rings) {
    const double width = std::stod((*it)[1]);
    EXPECT_NE(width, 2.0);  // placed smaller or larger than drawn
    EXPECT_NEAR(std::stod((*it)[2]) / width, 3.0, 0.01) << it->str();
    EXPECT_NEAR(std::stod((*it)[3]) / width, 1.5, 0.01) << it->str();
    EXPECT_NEAR(std::stod((*it)[4]) / width, 0.5, 0.01) << it->str();
  }
  EXPECT_EQ(rings, 4);
}

// Editable curves by default (issue 17): cubic Béziers fitted within 0.085 canonical units of
// the deformed outlines, fewer points than the polygons, which --polyline writes as before.
TEST(CliPack, OutlinesAreCurvesByDefaultAndPolygonsOnRequest) {
  ScratchFolder dir("cli-pack-curves");
  PakRun curves = runPak(kQuick + " -o " + shellQuoted(dir.file("c.svg")) + " --report " + shellQuoted(dir.file("c.json")));
  PakRun polygons = runPak(kQuick + " --polyline -o " + shellQuoted(dir.file("p.svg")) + " --report " +
                           shellQuoted(dir.file("p.json")));
  ASSERT_EQ(curves.exitCode, 0) << curves.err;
  ASSERT_EQ(polygons.exitCode, 0) << polygons.err;
  const std::string curveSvg = readWholeFile(dir.file("c.svg")), polygonSvg = readWholeFile(dir.file("p.svg"));
  EXPECT_GT(count(curveSvg, " C"), 6);
  EXPECT_EQ(count(polygonSvg, " C"), 0);
  auto c = nlohmann::json::parse(readWholeFile(dir.file("c.json")));
  auto p = nlohmann::json::parse(readWholeFile(dir.file("p.json")));
  EXPECT_EQ(c["output-outlines"], "cubic Béziers");
  EXPECT_EQ(p["output-outlines"], "polygons");
  EXPECT_LT(c["output-points"].get<int>(), p["output-points"].get<int>() * 3 / 4);
  EXPECT_GT(c["output-largest-curve-deviation"].get<double>(), 0.0);
  EXPECT_LE(c["output-largest-curve-deviation"].get<double>(), 0.1);
  EXPECT_EQ(p["output-largest-curve-deviation"], 0.0);
  // The same packing either way: only the way its outlines are written differs.
  EXPECT_EQ(c["fill-ratio-art"], p["fill-ratio-art"]);
  EXPECT_EQ(count(curveSvg, "data-source=\""), count(polygonSvg, "data-source=\""));
}

// Issue 17's target: the curves hold at most 3 × the points the art was drawn with, within 0.1
// canonical units. The smoothed art needs far fewer than the thesis's linear map, whose kinks
// at every mesh edge the curves must follow.
TEST(CliPack, CurvesHoldAtMostThreeTimesTheDrawnPoints) {
  ScratchFolder dir("cli-pack-drawn-points");
  const std::string common = "pack -c examples/scene.svg -e examples/elements --count 12 --max-iterations 600 --quiet";
  PakRun smooth = runPak(common + " -o " + shellQuoted(dir.file("s.svg")) + " --report " + shellQuoted(dir.file("s.json")));
  PakRun linear = runPak(common + " --linear-art -o " + shellQuoted(dir.file("l.svg")) + " --report " +
                         shellQuoted(dir.file("l.json")));
  ASSERT_EQ(smooth.exitCode, 0) << smooth.err;
  ASSERT_EQ(linear.exitCode, 0) << linear.err;
  auto s = nlohmann::json::parse(readWholeFile(dir.file("s.json")));
  auto l = nlohmann::json::parse(readWholeFile(dir.file("l.json")));
  EXPECT_GT(s["drawn-points"].get<int>(), 12 * 20);  // every element drew some
  EXPECT_EQ(s["drawn-points"], l["drawn-points"]);
  EXPECT_LE(s["output-points-per-drawn-point"].get<double>(), 3.0);
  EXPECT_LT(s["output-points-per-drawn-point"].get<double>(), 0.8 * l["output-points-per-drawn-point"].get<double>());
  EXPECT_LE(s["output-largest-curve-deviation"].get<double>(), 0.1);
  EXPECT_LE(l["output-largest-curve-deviation"].get<double>(), 0.1);
  EXPECT_EQ(s["overlap-count"], 0);
}
