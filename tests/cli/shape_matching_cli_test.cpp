// `pak pack --shape-matching` (thesis 4.7) from the command line: the report's corners, the
// docked elements, the matching time, and one-line errors for bad docking options.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "run_pak.hpp"

using namespace pak::testing;

namespace {
// A five-pointed star, 200 units wide.
const char* kStar = R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 200 200">
<path d="M100,5 L123,73 195,73 137,116 159,185 100,143 41,185 63,116 5,73 77,73 Z"/></svg>)";
}  // namespace

TEST(CliShapeMatching, ReportsCornersDockedElementsAndTiming) {
  ScratchFolder dir("cli-shape-matching");
  std::string star = dir.write("star.svg", kStar);
  PakRun run = runPak("pack -c " + shellQuoted(star) + " -e examples/elements --count 8 --gap 20 --max-iterations 200 -q "
                      "--shape-matching --docking-strength 30 -o " + shellQuoted(dir.file("o.svg")) + " --report " +
                      shellQuoted(dir.file("r.json")));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  auto report = nlohmann::json::parse(readWholeFile(dir.file("r.json")));
  EXPECT_EQ(report["parameters"]["shape-matching"], true);
  EXPECT_EQ(report["parameters"]["docking-strength"], 30.0);
  EXPECT_EQ(report["salient-corners"].size(), 5u);
  EXPECT_EQ(report["shape-matching"]["corners"], 5);
  EXPECT_EQ(report["shape-matching"]["docked-elements"], 5);
  EXPECT_LT(report["shape-matching"]["matching-seconds"].get<double>(), 1.0);
  // Without the flag the corners are still reported (for comparisons) but nothing is docked.
  run = runPak("pack -c " + shellQuoted(star) + " -e examples/elements --count 8 --gap 20 --max-iterations 20 -q -o " +
               shellQuoted(dir.file("p.svg")) + " --report " + shellQuoted(dir.file("s.json")));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  report = nlohmann::json::parse(readWholeFile(dir.file("s.json")));
  EXPECT_EQ(report["salient-corners"].size(), 5u);
  EXPECT_FALSE(report.contains("shape-matching"));
}

TEST(CliShapeMatching, BadDockingStrengthIsOneErrorLine) {
  ScratchFolder dir("cli-shape-matching-bad");
  std::string bad = dir.write("bad.json", R"({"shape-matching": 1})");
  for (const std::string& args :
       {"pack -c examples/scene.svg -e examples/elements --shape-matching --docking-strength -1 -o " + shellQuoted(dir.file("o.svg")),
        "pack -c examples/scene.svg -e examples/elements --config " + shellQuoted(bad) + " -o " + shellQuoted(dir.file("o.svg"))}) {
    PakRun run = runPak(args);
    EXPECT_EQ(run.exitCode, 2) << args;
    ASSERT_EQ(run.errLines().size(), 1u) << run.err;
    EXPECT_EQ(run.errLines()[0].rfind("pak: error: ", 0), 0u) << run.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("o.svg")));
  }
}
