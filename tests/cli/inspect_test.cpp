// `pak inspect`: what Pak sees in the bundled example, as text and as JSON.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "cli/run_pak.hpp"

namespace fs = std::filesystem;
using nlohmann::json;
using pak::testing::PakRun;
using pak::testing::runPak;
using pak::testing::shellQuoted;

namespace {

constexpr double kPi = 3.14159265358979323846;

json inspectJson(const std::string& arguments) {
  PakRun run = runPak("inspect --json " + arguments);
  EXPECT_EQ(run.exitCode, 0) << run.err;
  EXPECT_TRUE(run.err.empty()) << run.err;
  return json::parse(run.out);  // throws (and fails the test) if the JSON is broken
}

TEST(CliInspect, SceneTextReportsTheContainerWithOneHole) {
  PakRun run = runPak("inspect examples/scene.svg");
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_TRUE(run.err.empty()) << run.err;
  EXPECT_EQ(run.out.rfind("examples/scene.svg\n", 0), 0u) << run.out;
  EXPECT_NE(run.out.find("layers: container"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("containers: 1, total area "), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("1 hole,"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("warnings: none"), std::string::npos) << run.out;
}

TEST(CliInspect, SceneJsonHasTheContainerAreaHoleAndBounds) {
  json report = inspectJson("examples/scene.svg");
  ASSERT_EQ(report["files"].size(), 1u);
  const json& file = report["files"][0];
  EXPECT_EQ(file["file"], "examples/scene.svg");
  EXPECT_EQ(file["width"], 1000);
  EXPECT_EQ(file["height"], 700);
  EXPECT_EQ(file["viewBox"], json::array({0, 0, 1000, 700}));
  EXPECT_EQ(file["layers"], json::array({"container"}));
  EXPECT_TRUE(file["elements"].empty());
  EXPECT_TRUE(file["warnings"].empty());
  const json& scene = file["scene"];
  ASSERT_TRUE(scene.is_object());
  ASSERT_EQ(scene["containers"].size(), 1u);
  const json& container = scene["containers"][0];
  EXPECT_EQ(container["holes"], 1);
  // The fish spans x 48..968 (nose to tail tips) and y 66..600 (dorsal fin tip to lower tail tip).
  EXPECT_NEAR(container["bounds"]["min"][0].get<double>(), 48, 0.5);
  EXPECT_NEAR(container["bounds"]["max"][0].get<double>(), 968, 0.5);
  EXPECT_NEAR(container["bounds"]["min"][1].get<double>(), 66, 0.5);
  EXPECT_NEAR(container["bounds"]["max"][1].get<double>(), 600, 0.5);
  // Area: the outline minus the eye (a circle of radius 44), well inside the bounding box.
  double area = container["area"].get<double>();
  EXPECT_NEAR(scene["containerArea"].get<double>(), area, 1e-6 * area);
  EXPECT_GT(area, 0.5 * 920 * 534);
  EXPECT_LT(area, 0.9 * 920 * 534);
  EXPECT_NEAR(area, 265746, 0.005 * 265746);  // measured once; flattening may move it a little
  ASSERT_EQ(scene["containerShapes"].size(), 1u);
  const json& shape = scene["containerShapes"][0];
  EXPECT_EQ(shape["id"], "fish");
  EXPECT_EQ(shape["fillRule"], "evenodd");
  EXPECT_EQ(shape["fill"]["hex"], "#dcebf5");
  EXPECT_EQ(shape["holes"], 1);
  EXPECT_NEAR(shape["filledArea"].get<double>(), area, 1e-3 * area);
  EXPECT_TRUE(scene["fixed"].empty());
  EXPECT_TRUE(scene["guides"].empty());
  EXPECT_TRUE(scene["spines"].empty());
}

TEST(CliInspect, ElementJsonListsPathsColoursAndHoles) {
  json report = inspectJson("examples/elements/cat.svg");
  const json& file = report["files"][0];
  ASSERT_EQ(file["elements"].size(), 1u);
  const json& cat = file["elements"][0];
  EXPECT_EQ(cat["name"], "cat");
  ASSERT_EQ(cat["paths"].size(), 4u);
  const json& head = cat["paths"][0];
  EXPECT_EQ(head["id"], "head");
  EXPECT_EQ(head["fill"]["hex"], "#5b5b66");
  EXPECT_EQ(head["holes"], 2);  // the eyes
  // Each eye is an ellipse with radii 11 and 14.
  double eyes = 2 * kPi * 11 * 14;
  double headWithoutEyes = head["filledArea"].get<double>();
  EXPECT_GT(headWithoutEyes, eyes);
  const json& whiskers = cat["paths"][3];
  EXPECT_TRUE(whiskers["fill"].is_null());
  EXPECT_EQ(whiskers["stroke"]["hex"], "#2a2a30");
  EXPECT_EQ(whiskers["closedSubpaths"], 0);
  EXPECT_GT(whiskers["paintedArea"].get<double>(), 0);
  EXPECT_GT(cat["area"].get<double>(), 0);
  EXPECT_TRUE(file["warnings"].empty());
}

TEST(CliInspect, EveryBundledElementHasColouredArt) {
  std::string arguments;
  int count = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(PAK_SOURCE_DIR) / "examples" / "elements"))
    if (entry.path().extension() == ".svg") {
      arguments += " " + shellQuoted(entry.path().string());
      ++count;
    }
  ASSERT_GE(count, 6);
  ASSERT_LE(count, 8);
  json report = inspectJson(arguments);
  ASSERT_EQ(report["files"].size(), static_cast<std::size_t>(count));
  for (const json& file : report["files"]) {
    SCOPED_TRACE(file["file"].get<std::string>());
    ASSERT_EQ(file["elements"].size(), 1u);
    const json& element = file["elements"][0];
    std::set<std::string> colours;
    for (const json& path : element["paths"]) {
      if (!path["fill"].is_null()) colours.insert(path["fill"]["hex"]);
      if (!path["stroke"].is_null()) colours.insert(path["stroke"]["hex"]);
    }
    EXPECT_GE(colours.size(), 2u);
    EXPECT_GE(element["paths"].size(), 2u);
    EXPECT_GT(element["area"].get<double>(), 100);  // drawn on a 200-unit canvas
    EXPECT_TRUE(file["warnings"].empty()) << file["warnings"].dump();
  }
}

TEST(CliInspect, SeveralFilesInOneRun) {
  PakRun run = runPak("inspect examples/scene.svg examples/elements/leaf.svg");
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("examples/scene.svg\n"), std::string::npos);
  EXPECT_NE(run.out.find("\nexamples/elements/leaf.svg\n"), std::string::npos);
  EXPECT_NE(run.out.find("element \"leaf\""), std::string::npos) << run.out;
}

TEST(CliInspect, OneBadFileFailsTheWholeRunWithoutPartialOutput) {
  PakRun run = runPak("inspect examples/scene.svg examples/no-such-file.svg");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_TRUE(run.out.empty()) << run.out;
  EXPECT_EQ(run.err.rfind("pak: error: examples/no-such-file.svg: ", 0), 0u) << run.err;
}

TEST(CliInspect, LoneClosedShapeIsShownAsElementAndScene) {
  fs::path heart = fs::path(PAK_SHARED_DATA_DIR) / "mdi" / "heart.svg";
  if (!fs::exists(heart)) GTEST_SKIP() << "shared data not found at " << heart;
  json file = inspectJson(shellQuoted(heart.string()))["files"][0];
  EXPECT_EQ(file["elements"].size(), 1u);
  ASSERT_TRUE(file["scene"].is_object());
  EXPECT_EQ(file["scene"]["containers"].size(), 1u);
}

TEST(CliInspect, MdiCatHasTwoEyeHoles) {
  fs::path cat = fs::path(PAK_SHARED_DATA_DIR) / "mdi" / "cat.svg";
  if (!fs::exists(cat)) GTEST_SKIP() << "shared data not found at " << cat;
  json file = inspectJson(shellQuoted(cat.string()))["files"][0];
  ASSERT_EQ(file["elements"].size(), 1u);
  EXPECT_GE(file["elements"][0]["holes"].get<int>(), 2);
}

TEST(CliInspect, HelpExplainsEveryOption) {
  PakRun run = runPak("inspect --help");
  EXPECT_EQ(run.exitCode, 0);
  EXPECT_NE(run.out.find("--json"), std::string::npos);
  EXPECT_NE(run.out.find("default"), std::string::npos);
}

// Each effect Pak does not draw is named in the report (tests/svg/unsupported-effects.svg has
// one of each).
TEST(CliInspect, NamesEveryUndrawnEffect) {
  PakRun run = runPak("inspect tests/svg/unsupported-effects.svg");
  ASSERT_EQ(run.exitCode, 0) << run.err;
  for (const char* name : {"mask=", "filter=", "mix-blend-mode=", "marker-end=",
                           "<text> is not supported", "<image> is not supported"})
    EXPECT_NE(run.out.find(name), std::string::npos) << name << "\n" << run.out;
  EXPECT_EQ(run.out.find("warnings: none"), std::string::npos) << run.out;
}

// Every <use> copy is drawn (tests/svg/use-clones.svg: a field, 3 stripes from one rect,
// 2 studs from a symbol through a group of uses), with nothing skipped.
TEST(CliInspect, UseClonesAreDrawn) {
  json report = inspectJson("tests/svg/use-clones.svg");
  const json& file = report["files"][0];
  EXPECT_EQ(file["shapes"], 6);
  EXPECT_TRUE(file["warnings"].empty()) << file["warnings"];
}

// clip-path is applied: tests/svg/clipped-square.svg, a 100×100 square seen through a 50×50
// window, reads as area 2500 as a container and as an element.
TEST(CliInspect, ClipPathIsApplied) {
  json report = inspectJson("tests/svg/clipped-square.svg");
  const json& file = report["files"][0];
  ASSERT_TRUE(file["scene"].is_object());
  EXPECT_NEAR(file["scene"]["containerArea"].get<double>(), 2500.0, 1e-6);
  ASSERT_EQ(file["elements"].size(), 1u);
  EXPECT_NEAR(file["elements"][0]["area"].get<double>(), 2500.0, 1e-6);
  EXPECT_TRUE(file["warnings"].empty()) << file["warnings"];
}

}  // namespace
