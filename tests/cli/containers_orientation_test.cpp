// `pak pack` with several containers, per-container libraries, --container-layer and
// --orientation, as a user runs it.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "run_pak.hpp"

using namespace pak::testing;

TEST(CliContainers, RoomsAndASecondRunInsideTheFirstRunsElements) {
  ScratchFolder dir("cli-containers");
  PakRun first = runPak("pack -c examples/rooms.svg -e examples/elements/cat.svg --count 6 --gap 16 "
                        "--max-iterations 400 -q -o " + shellQuoted(dir.file("rooms.svg")) + " --report " +
                        shellQuoted(dir.file("rooms.json")));
  ASSERT_EQ(first.exitCode, 0) << first.err;
  auto report = nlohmann::json::parse(readWholeFile(dir.file("rooms.json")));
  EXPECT_EQ(report["elements-per-container"].size(), 3u);
  EXPECT_EQ(report["overlap-count"], 0);
  EXPECT_EQ(report["elements-outside"], 0);
  EXPECT_EQ(report["parameters"]["container-layer"], "container");

  // Every element of the first run is a container of the second.
  PakRun second = runPak("pack -c " + shellQuoted(dir.file("rooms.svg")) +
                         " --container-layer elements -e examples/elements/moon.svg --count 12 --gap 16 "
                         "--max-iterations 300 -q -o " + shellQuoted(dir.file("inside.svg")) + " --report " +
                         shellQuoted(dir.file("inside.json")));
  ASSERT_EQ(second.exitCode, 0) << second.err;
  auto inside = nlohmann::json::parse(readWholeFile(dir.file("inside.json")));
  EXPECT_EQ(inside["elements-per-container"].size(), report["element-count"]);
  EXPECT_EQ(inside["elements-outside"], 0);
  EXPECT_EQ(inside["overlap-count"], 0);
}

TEST(CliContainers, OrientationOptionsAreReported) {
  ScratchFolder dir("cli-orientation");
  PakRun run = runPak("pack -c examples/band.svg -e examples/elements/bird.svg --count 4 --max-iterations 50 -q "
                      "--orientation-field y:10:20 -o " + shellQuoted(dir.file("o.svg")) + " --report " +
                      shellQuoted(dir.file("r.json")));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  auto report = nlohmann::json::parse(readWholeFile(dir.file("r.json")));
  EXPECT_EQ(report["parameters"]["orientation"], "field");  // a field alone asks for it
  EXPECT_EQ(report["parameters"]["orientation-field"], "y:10:20");
}

TEST(CliContainers, BadValuesAreOneErrorLineAndExitTwo) {
  ScratchFolder dir("cli-containers-bad");
  std::string out = shellQuoted(dir.file("o.svg"));
  std::string missingLibrary = dir.write(
      "scene.svg", R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100"><g id="container">)"
                   R"(<rect width="100" height="100" data-elements="no-such.svg"/></g></svg>)");
  std::string badConfig = dir.write("c.json", R"({"orientation": 3})");
  for (const std::string& args :
       {"pack -c examples/band.svg -e examples/elements -o " + out + " --orientation sideways",
        "pack -c examples/band.svg -e examples/elements -o " + out + " --orientation field --orientation-field z:0:9",
        "pack -c examples/band.svg -e examples/elements -o " + out + " --orientation-field x:0",
        "pack -c examples/band.svg -e examples/elements -o " + out + " --container-layer nosuchlayer",
        "pack -c examples/band.svg -e examples/elements -o " + out + " --container-layer elements",
        "pack -c examples/band.svg -e examples/elements -o " + out + " --config " + shellQuoted(badConfig),
        "pack -c " + shellQuoted(missingLibrary) + " -e examples/elements -o " + out}) {
    PakRun run = runPak(args);
    EXPECT_EQ(run.exitCode, 2) << args;
    ASSERT_EQ(run.errLines().size(), 1u) << args << "\n" << run.err;
    EXPECT_EQ(run.err.rfind("pak: error: ", 0), 0u) << run.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("o.svg"))) << args;
  }
}
