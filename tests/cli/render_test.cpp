// `pak render`: PNG and SVG output of inputs, holes drawn as holes, options, and failures
// that leave nothing behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "cli/png_pixels.hpp"
#include "cli/run_pak.hpp"

namespace fs = std::filesystem;
using pak::testing::near;
using pak::testing::PakRun;
using pak::testing::readPngPixels;
using pak::testing::runPak;
using pak::testing::ScratchFolder;
using pak::testing::shellQuoted;

namespace {

const std::string kScene = "examples/scene.svg";

TEST(CliRender, SceneToPngShowsTheEyeAsAHole) {
  ScratchFolder folder("render-scene");
  std::string out = folder.file("scene.png");
  PakRun run = runPak("render " + kScene + " -o " + shellQuoted(out) + " --width 500");
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_TRUE(run.err.empty()) << run.err;
  auto image = readPngPixels(out);
  ASSERT_EQ(image.width, 500);
  ASSERT_EQ(image.height, 350);  // the scene is 1000 x 700
  // The fish's eye is centred at (218, 318) in the file: half that in pixels.
  EXPECT_TRUE(near(image.at(109, 159), 255, 255, 255)) << "eye is not a hole";
  EXPECT_TRUE(near(image.at(250, 180), 0xdc, 0xeb, 0xf5)) << "body is not the container's fill";
  EXPECT_TRUE(near(image.at(2, 2), 255, 255, 255));
  EXPECT_EQ(std::distance(fs::directory_iterator(folder.path()), fs::directory_iterator()), 1);
}

TEST(CliRender, TransparentAndColouredBackgrounds) {
  ScratchFolder folder("render-background");
  std::string clear = folder.file("clear.png"), red = folder.file("red.png");
  ASSERT_EQ(runPak("render " + kScene + " -o " + shellQuoted(clear) + " --width 200 --background none").exitCode, 0);
  ASSERT_EQ(runPak("render " + kScene + " -o " + shellQuoted(red) + " --width 200 --background '#f00'").exitCode, 0);
  EXPECT_EQ(readPngPixels(clear).at(1, 1).a, 0);
  EXPECT_TRUE(near(readPngPixels(red).at(1, 1), 255, 0, 0));
}

TEST(CliRender, EveryBundledElementRenders) {
  ScratchFolder folder("render-elements");
  int count = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(PAK_SOURCE_DIR) / "examples" / "elements")) {
    if (entry.path().extension() != ".svg") continue;
    std::string out = folder.file(entry.path().stem().string() + ".png");
    PakRun run = runPak("render " + shellQuoted(entry.path().string()) + " -o " + shellQuoted(out) + " --width 120");
    EXPECT_EQ(run.exitCode, 0) << entry.path() << ": " << run.err;
    EXPECT_GT(readPngPixels(out).width, 0) << entry.path();
    ++count;
  }
  EXPECT_GE(count, 6);
}

TEST(CliRender, SvgOutputReadsBackAsTheSameScene) {
  ScratchFolder folder("render-svg");
  std::string out = folder.file("scene.svg");
  PakRun render = runPak("render " + kScene + " -o " + shellQuoted(out));
  ASSERT_EQ(render.exitCode, 0) << render.err;
  PakRun original = runPak("inspect --json " + kScene);
  PakRun copy = runPak("inspect --json " + shellQuoted(out));
  ASSERT_EQ(original.exitCode, 0) << original.err;
  ASSERT_EQ(copy.exitCode, 0) << copy.err;
  auto a = nlohmann::json::parse(original.out)["files"][0]["scene"];
  auto b = nlohmann::json::parse(copy.out)["files"][0]["scene"];
  ASSERT_FALSE(b.is_null()) << "the rendered SVG lost its container layer";
  ASSERT_EQ(b["containers"].size(), 1u);
  EXPECT_EQ(b["containers"][0]["holes"], 1);
  double expected = a["containerArea"].get<double>();
  EXPECT_NEAR(b["containerArea"].get<double>(), expected, expected * 1e-3);
}

TEST(CliRender, SvgOutputWidthOption) {
  ScratchFolder folder("render-svg-width");
  std::string out = folder.file("small.svg");
  ASSERT_EQ(runPak("render " + kScene + " -o " + shellQuoted(out) + " --width 500").exitCode, 0);
  std::string text = pak::testing::readWholeFile(out);
  EXPECT_NE(text.find("width=\"500\""), std::string::npos);
  EXPECT_NE(text.find("height=\"350\""), std::string::npos);
  EXPECT_NE(text.find("viewBox=\"0 0 1000 700\""), std::string::npos);
}

TEST(CliRender, MdiCatEyesAreHoles) {
  fs::path cat = fs::path(PAK_SHARED_DATA_DIR) / "mdi" / "cat.svg";
  if (!fs::exists(cat)) GTEST_SKIP() << "shared data not found at " << cat << " (only on the project's machines)";
  ScratchFolder folder("render-cat");
  std::string out = folder.file("cat.png");
  PakRun run = runPak("render " + shellQuoted(cat.string()) + " -o " + shellQuoted(out) + " --width 240");
  ASSERT_EQ(run.exitCode, 0) << run.err;
  auto image = readPngPixels(out);
  ASSERT_EQ(image.width, 240);
  ASSERT_EQ(image.height, 240);
  // The icon is 24 units wide: its eyes are unit circles at (9, 12) and (15, 12).
  EXPECT_TRUE(near(image.at(90, 120), 255, 255, 255)) << "left eye is filled";
  EXPECT_TRUE(near(image.at(150, 120), 255, 255, 255)) << "right eye is filled";
  EXPECT_TRUE(near(image.at(120, 100), 0, 0, 0)) << "the face between the eyes is not black";
}

TEST(CliRender, LegacyPathFileRenders) {
  fs::path heart = fs::path(PAK_SHARED_DATA_DIR) / "repulsionpak" / "containers" / "heart.path";
  if (!fs::exists(heart)) GTEST_SKIP() << "shared data not found at " << heart;
  ScratchFolder folder("render-path");
  std::string out = folder.file("heart.png");
  PakRun run = runPak("render " + shellQuoted(heart.string()) + " -o " + shellQuoted(out) + " --width 300");
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_EQ(readPngPixels(out).width, 300);
}

TEST(CliRender, MissingOutputFolderFailsAndLeavesNothing) {
  ScratchFolder folder("render-missing");
  std::string out = folder.file("no/such/folder/scene.png");
  PakRun run = runPak("render " + kScene + " -o " + shellQuoted(out));
  EXPECT_EQ(run.exitCode, 2);
  ASSERT_EQ(run.errLines().size(), 1u) << run.err;
  EXPECT_EQ(run.err.rfind("pak: error: " + out + ": ", 0), 0u) << run.err;
  EXPECT_TRUE(fs::is_empty(folder.path()));
}

TEST(CliRender, UnknownOutputFormatFails) {
  ScratchFolder folder("render-format");
  PakRun run = runPak("render " + kScene + " -o " + shellQuoted(folder.file("scene.jpg")));
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.err.find(".png or .svg"), std::string::npos) << run.err;
  EXPECT_TRUE(fs::is_empty(folder.path()));
}

TEST(CliRender, BadOptionsFail) {
  ScratchFolder folder("render-options");
  std::string out = shellQuoted(folder.file("scene.png"));
  for (const char* options : {"--background chartreuse-ish", "--width 0", "--width 100000", "--width ten"}) {
    PakRun run = runPak("render " + kScene + " -o " + out + " " + options);
    EXPECT_EQ(run.exitCode, 2) << options;
    EXPECT_EQ(run.errLines().size(), 1u) << options << ": " << run.err;
    EXPECT_EQ(run.err.rfind("pak: error: ", 0), 0u) << run.err;
  }
  EXPECT_TRUE(fs::is_empty(folder.path()));
}

TEST(CliRender, HelpExplainsEveryOption) {
  PakRun run = runPak("render --help");
  EXPECT_EQ(run.exitCode, 0);
  for (const char* word : {"--output", "--width", "--background", "default: 1000", "none", ".png", ".svg"})
    EXPECT_NE(run.out.find(word), std::string::npos) << word;
}

}  // namespace
