// `pak metrics` as a user runs it: pack a small example, then measure it.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "cli/png_pixels.hpp"
#include "cli/run_pak.hpp"

using namespace pak::testing;
using nlohmann::json;

namespace {

// Small and coarse: the binary runs under sanitizers in the test build.
const std::string kFast = " --radii 20 --grid 200 --bins 10";

class CliMetrics : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    folder_ = new ScratchFolder("cli-metrics");
    PakRun run = runPak("pack -c examples/scene.svg -e examples/elements --count 6 --gap 20 --max-iterations 300 -q -o " +
                        shellQuoted(folder_->file("packing.svg")) + " --report " +
                        shellQuoted(folder_->file("report.json")));
    ASSERT_EQ(run.exitCode, 0) << run.err;
  }
  static void TearDownTestSuite() {
    delete folder_;
    folder_ = nullptr;
  }
  static std::string file(const std::string& name) { return folder_->file(name); }
  static ScratchFolder* folder_;
};
ScratchFolder* CliMetrics::folder_ = nullptr;

TEST_F(CliMetrics, TableJsonCsvAndPlot) {
  PakRun run = runPak("metrics " + shellQuoted(file("packing.svg")) + kFast + " --report " +
                      shellQuoted(file("report.json")) + " --json " + shellQuoted(file("m.json")) + " --csv " +
                      shellQuoted(file("m.csv")) + " --plot " + shellQuoted(file("plot.png")));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_TRUE(run.err.empty()) << run.err;
  EXPECT_NE(run.out.find("Q(d_gap/2)"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("packing.svg"), std::string::npos) << run.out;

  json report = json::parse(readWholeFile(file("report.json")));
  json metrics = json::parse(readWholeFile(file("m.json")));
  ASSERT_EQ(metrics["packings"].size(), 1u);
  const json& m = metrics["packings"][0];
  EXPECT_EQ(m["elements"], 6);
  EXPECT_NEAR(m["d_gap"].get<double>(), 20.0 / report["canonical-scale"].get<double>(), 1e-9);
  EXPECT_FALSE(m["d_gap-estimated"].get<bool>());
  EXPECT_NEAR(m["positive-ratio"].get<double>() + m["negative-ratio"].get<double>(), 1.0, 1e-9);
  for (const char* curve : {"Q", "H", "O"}) {
    EXPECT_EQ(m["curves"][curve]["r"].size(), m["curves"][curve]["value"].size()) << curve;
    EXPECT_GE(m["curves"][curve]["r"].size(), 2u) << curve;
  }
  EXPECT_NEAR(m["curves"]["Q"]["value"][0].get<double>(), m["negative-ratio"].get<double>(), 1e-6);
  EXPECT_EQ(readWholeFile(file("m.csv")).rfind("file,curve,r,value\n", 0), 0u);
  EXPECT_EQ(readWholeFile(file("plot.png")).rfind("\x89PNG", 0), 0u);
}

TEST_F(CliMetrics, CalibrateSvgPlotAndVisualization) {
  PakRun run = runPak("metrics " + shellQuoted(file("packing.svg")) + " " + shellQuoted(file("packing.svg")) + kFast +
                      " --gap 15 --calibrate --plot " + shellQuoted(file("plot.svg")) + " --visualize 5 --visualize-out " +
                      shellQuoted(file("offset.png")));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("offset"), std::string::npos) << run.out;
  EXPECT_NE(readWholeFile(file("plot.svg")).find("<svg"), std::string::npos);
  EXPECT_EQ(readWholeFile(file("offset-1.png")).rfind("\x89PNG", 0), 0u);
  EXPECT_EQ(readWholeFile(file("offset-2.png")).rfind("\x89PNG", 0), 0u);
}

TEST_F(CliMetrics, DistanceMapShadesFreeSpaceByDistance) {
  // A 100 × 100 square container with one 40 × 40 square element in the middle.
  const std::string path = folder_->write(
      "one.svg",
      "<svg xmlns='http://www.w3.org/2000/svg' viewBox='0 0 100 100'><g id='container'><rect width='100' "
      "height='100'/></g><g id='elements'><g><rect x='30' y='30' width='40' height='40' fill='red'/></g></g></svg>");
  PakRun run = runPak("metrics " + shellQuoted(path) + kFast + " --gap 10 --distance-map " + shellQuoted(file("dm.png")));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const PngPixels image = readPngPixels(file("dm.png"));
  ASSERT_EQ(image.width, 200);
  ASSERT_EQ(image.height, 200);
  auto brightness = [&](int x, int y) { const Rgba p = image.at(x, y); return p.r + p.g + p.b; };
  const Rgba element = image.at(100, 100);
  EXPECT_EQ(element.r, element.g);  // grey
  EXPECT_EQ(element.g, element.b);
  // Free space gets lighter away from the walls and the element: the point midway between the
  // element and the wall (distance 15) is lighter than one next to the element (distance ~1).
  EXPECT_GT(brightness(30, 100), brightness(57, 100));
  EXPECT_GT(brightness(30, 100), brightness(2, 100));
  PakRun bad = runPak("metrics " + shellQuoted(path) + kFast + " --distance-map " + shellQuoted(file("dm.jpg")));
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_EQ(bad.errLines().size(), 1u) << bad.err;
}

TEST_F(CliMetrics, BadPackingsFailWithOneErrorLine) {
  const std::string head = "<svg xmlns='http://www.w3.org/2000/svg' viewBox='0 0 100 100'>";
  const std::string cases[][2] = {
      {"no-container.svg", head + "<path d='M0 0 L50 50' stroke='black'/></svg>"},
      {"no-elements.svg", head + "<g id='container'><rect width='100' height='100'/></g></svg>"},
      {"outside.svg", head + "<g id='container'><rect width='50' height='50'/></g>"
                             "<g id='elements'><g><rect x='70' y='70' width='5' height='5'/></g></g></svg>"},
  };
  for (const auto& [name, svg] : cases) {
    std::string path = folder_->write(name, svg);
    PakRun run = runPak("metrics " + shellQuoted(path) + kFast + " --json " + shellQuoted(file("bad.json")));
    EXPECT_EQ(run.exitCode, 2) << name;
    ASSERT_EQ(run.errLines().size(), 1u) << name << ": " << run.err;
    EXPECT_EQ(run.errLines()[0].rfind("pak: error: ", 0), 0u) << run.err;
    EXPECT_FALSE(std::filesystem::exists(file("bad.json"))) << name;
  }
  PakRun badPlot = runPak("metrics " + shellQuoted(file("packing.svg")) + " --plot " + shellQuoted(file("plot.pdf")));
  EXPECT_EQ(badPlot.exitCode, 2);
  EXPECT_NE(badPlot.err.find("use .png or .svg"), std::string::npos) << badPlot.err;
}

}  // namespace
