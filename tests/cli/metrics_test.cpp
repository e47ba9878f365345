// `pak metrics` as a user runs it: pack a small example, then measure it.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
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
  // The evenness measure, on the --grid grid.
  EXPECT_NE(run.out.find("P2 (D>2h)"), std::string::npos) << run.out;
  const json& e = m["evenness"];
  EXPECT_EQ(e["resolution"], 200);
  EXPECT_GT(e["h"].get<double>(), 0.0);
  EXPECT_GE(e["P1"].get<double>(), e["P2"].get<double>());
  EXPECT_GE(e["P2"].get<double>(), e["P3"].get<double>());
  EXPECT_GE(e["largest-radius-over-h"].get<double>(), 1.0);
  EXPECT_NEAR(e["negative-ratio"].get<double>(), m["negative-ratio"].get<double>(), 0.05);
  const std::string csv = readWholeFile(file("m.csv"));
  EXPECT_EQ(csv.rfind("file,curve,r,value\n", 0), 0u);
  EXPECT_NE(csv.find(",P,2,"), std::string::npos);
  EXPECT_NE(csv.find(",evenness-h,,"), std::string::npos);
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

// A 100 × 100 container with four 40 × 40 squares: channels of width 10 between them and
// 5 to the walls (h = 2.5); a round hole of radius 15 in one square is a pocket (D up to 15 >
// 3h), a 1.5 × 1.5 eye in another is filled (under 4e-4 of the square), and a fixed square
// in the middle channel crossing is positive space.
std::string fourSquares(double scale) {
  std::ostringstream svg;
  auto rect = [&](double x, double y, double w, double h) {
    svg << "<rect x='" << x * scale << "' y='" << y * scale << "' width='" << w * scale << "' height='" << h * scale
        << "'/>";
  };
  auto square = [&](double x, double y, double w) {  // a closed path, for holes
    svg << " M" << x * scale << " " << y * scale << " h" << w * scale << " v" << w * scale << " h" << -w * scale << " Z";
  };
  auto circle = [&](double cx, double cy, double r) {  // two half-circle arcs
    const double x0 = (cx - r) * scale, x1 = (cx + r) * scale, y = cy * scale, radius = r * scale;
    svg << " M" << x0 << " " << y << " A" << radius << " " << radius << " 0 1 0 " << x1 << " " << y << " A" << radius
        << " " << radius << " 0 1 0 " << x0 << " " << y << " Z";
  };
  svg << "<svg xmlns='http://www.w3.org/2000/svg' viewBox='0 0 " << 100 * scale << " " << 100 * scale << "'>";
  svg << "<g id='container'>";
  rect(0, 0, 100, 100);
  svg << "</g><g id='fixed'>";
  rect(47, 47, 6, 6);
  svg << "</g><g id='elements'><g><path fill-rule='evenodd' d='";
  square(5, 5, 40);
  circle(25, 25, 15);
  svg << "'/></g><g><path fill-rule='evenodd' d='";
  square(55, 5, 40);
  square(70, 20, 1.5);
  svg << "'/></g><g>";
  rect(5, 55, 40, 40);
  svg << "</g><g>";
  rect(55, 55, 40, 40);
  svg << "</g></g></svg>";
  return svg.str();
}

TEST_F(CliMetrics, EvennessMapAndScaleInvariance) {
  const std::string small = folder_->write("four.svg", fourSquares(1.0));
  const std::string large = folder_->write("four-large.svg", fourSquares(2.5));
  PakRun run = runPak("metrics " + shellQuoted(small) + " " + shellQuoted(large) + kFast + " --gap 5 --json " +
                      shellQuoted(file("four.json")) + " --evenness-map " + shellQuoted(file("even.png")));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const json all = json::parse(readWholeFile(file("four.json")));
  const json& a = all["packings"][0]["evenness"];
  const json& b = all["packings"][1]["evenness"];
  EXPECT_NEAR(a["h"].get<double>(), 2.5, 0.25);  // half a cell of the 200-cell grid
  EXPECT_GT(a["P3"].get<double>(), 0.0);
  // The fixed square is positive space here and invisible to the chapter-6 ratios.
  const double art = 4 * 40 * 40 - 3.14159 * 15 * 15;  // the eye aside
  EXPECT_NEAR(all["packings"][0]["negative-ratio"].get<double>(), 1.0 - (art - 1.5 * 1.5) / 1e4, 1e-4);
  EXPECT_NEAR(a["negative-ratio"].get<double>(), 1.0 - (art + 6 * 6) / 1e4, 5e-3);
  // Scaling the whole file by 2.5 scales the lengths and nothing else.
  EXPECT_NEAR(b["h"].get<double>(), 2.5 * a["h"].get<double>(), 1e-6);
  for (const char* ratio : {"negative-ratio", "P1", "P2", "P3", "largest-radius-over-h", "width-spread"})
    EXPECT_NEAR(b[ratio].get<double>(), a[ratio].get<double>(), 1e-4) << ratio;

  const PngPixels image = readPngPixels(file("even-1.png"));
  ASSERT_EQ(image.width, 200);
  ASSERT_EQ(image.height, 200);
  EXPECT_TRUE(near(image.at(50, 44), 214, 33, 26)) << "near the pocket centre, D > 3h: red";
  EXPECT_TRUE(near(image.at(50, 32), 250, 158, 38)) << "D = 6.25 in the pocket, 2h < D < 3h: orange";
  EXPECT_TRUE(near(image.at(141, 41), 128, 128, 128)) << "the filled eye: dark grey";
  EXPECT_TRUE(near(image.at(150, 150), 184, 184, 184)) << "an element: light grey";
  EXPECT_TRUE(near(image.at(100, 100), 184, 184, 184)) << "the fixed square: light grey";
  // The wall channel's midline, y = 2.5, is white in column 50 (x = 25).
  bool axis = false;
  for (int y = 3; y <= 6; ++y) axis = axis || near(image.at(50, y), 255, 255, 255);
  EXPECT_TRUE(axis);
  EXPECT_EQ(readPngPixels(file("even-2.png")).width, 200);
  PakRun bad = runPak("metrics " + shellQuoted(small) + kFast + " --evenness-map " + shellQuoted(file("even.jpg")));
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

// The options have one table: a --config file gives them as the flags do, the flags win, and
// a wrong key or type is one error line naming the file.
TEST_F(CliMetrics, ConfigGivesTheSameOptionsAsFlags) {
  const std::string config = folder_->write("metrics-config.json", R"({"radii": 20, "grid": 200, "bins": 10, "gap": 5})");
  PakRun flags = runPak("metrics " + shellQuoted(file("packing.svg")) + kFast + " --gap 5 --json " +
                        shellQuoted(file("flags.json")));
  ASSERT_EQ(flags.exitCode, 0) << flags.err;
  PakRun configured = runPak("metrics " + shellQuoted(file("packing.svg")) + " --config " + shellQuoted(config) +
                             " --json " + shellQuoted(file("config.json")));
  ASSERT_EQ(configured.exitCode, 0) << configured.err;
  EXPECT_EQ(readWholeFile(file("flags.json")), readWholeFile(file("config.json")));
  // A flag wins over the file, and a given gap over the report's.
  PakRun both = runPak("metrics " + shellQuoted(file("packing.svg")) + " --config " + shellQuoted(config) +
                       " --gap 7 --report " + shellQuoted(file("report.json")) + " --json " + shellQuoted(file("both.json")));
  ASSERT_EQ(both.exitCode, 0) << both.err;
  EXPECT_EQ(json::parse(readWholeFile(file("both.json")))["packings"][0]["d_gap"].get<double>(), 7.0);

  const std::string bad = folder_->write("metrics-bad.json", R"({"grid": "fine"})");
  PakRun run = runPak("metrics " + shellQuoted(file("packing.svg")) + " --config " + shellQuoted(bad));
  EXPECT_EQ(run.exitCode, 2);
  ASSERT_EQ(run.errLines().size(), 1u) << run.err;
  EXPECT_NE(run.err.find("\"grid\" must be an integer"), std::string::npos) << run.err;
}

}  // namespace
