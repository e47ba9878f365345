// `pak animate` as a user runs it on the bundled stars example, kept small: every output
// written and consistent with the others, determinism across thread counts, checkpoint and
// resume, and one-line errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <nlohmann/json.hpp>

#include "cli/png_pixels.hpp"
#include "io/gif_decoder.hpp"
#include "run_pak.hpp"

using namespace pak::testing;

namespace {

std::vector<double> numbersIn(const std::string& text) {
  std::vector<double> numbers;
  static const std::regex number(R"(-?[0-9]+(\.[0-9]+)?(e-?[0-9]+)?)");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), number); it != std::sregex_iterator(); ++it)
    numbers.push_back(std::stod(it->str()));
  return numbers;
}

// The `d` of the index-th <path> of an SVG file.
std::string pathData(const std::string& svg, std::size_t index) {
  std::size_t at = 0;
  for (std::size_t k = 0; k <= index; ++k) at = svg.find("<path", at + 1);
  const std::size_t begin = svg.find(" d=\"", at) + 4;
  return svg.substr(begin, svg.find('"', begin) - begin);
}

const std::string kStars =
    "animate -c examples/animate/stars/disc.svg -a examples/animate/stars/stars.json --slices 6 --frames 8 "
    "--width 120 --sheet-frames 3 --svg-keyframes 4 -q";

TEST(CliAnimate, WritesGifAnimatedSvgFramesAndSheetThatAgree) {
  ScratchFolder dir("cli-animate-outputs");
  // --polyline: the SVG frames as polygons, the points the animated SVG interpolates.
  PakRun run = runPak(kStars + " --max-iterations 400 --png-frames --svg-frames --polyline --png " + shellQuoted(dir.file("first.png")) +
                      " -o " + shellQuoted(dir.file("out")) +
                      " --report " + shellQuoted(dir.file("r.json")));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const auto report = nlohmann::json::parse(readWholeFile(dir.file("r.json")));
  EXPECT_EQ(report["elements"], 20);
  EXPECT_EQ(report["slices"], 6);
  EXPECT_EQ(report["settle-iterations"], 100);  // the default, after the stop
  EXPECT_LE(report["iterations"].get<int>(), 400 + 100);
  EXPECT_GT(report["vertices"].get<int>(), 20 * 6 * 8);
  EXPECT_GT(report["art-fill-mean-over-frames"].get<double>(), 0.2);
  EXPECT_EQ(report["frames-with-element-outside"], 0);

  const std::filesystem::path out = dir.path() / "out";
  const Gif gif = decodeGif((out / "animation.gif").string());
  ASSERT_EQ(gif.frames.size(), 8u);
  EXPECT_EQ(gif.loopCount, 0);
  for (int f : {0, 3, 7}) {
    char name[32];
    std::snprintf(name, sizeof name, "frame-%04d.png", f);
    const PngPixels png = readPngPixels((out / "frames" / name).string());
    ASSERT_EQ(png.width, gif.width);
    ASSERT_EQ(png.height, gif.height);
    // The GIF's palette is shared by all frames, so compare colours loosely; most pixels agree.
    int agree = 0, total = 0;
    for (int y = 0; y < png.height; y += 7)
      for (int x = 0; x < png.width; x += 7, ++total) {
        const Rgba p = png.at(x, y);
        const GifPixel g = gif.at(f, x, y);
        agree += (std::abs(p.r - g.r) + std::abs(p.g - g.g) + std::abs(p.b - g.b) < 60) ? 1 : 0;
      }
    EXPECT_GT(agree, total * 9 / 10) << "frame " << f;
    std::snprintf(name, sizeof name, "frame-%04d.svg", f);
    EXPECT_TRUE(std::filesystem::exists(out / "svg-frames" / name)) << name;
  }
  const std::string animated = readWholeFile((out / "animation.svg").string());
  // One path per shape whose `d` runs through the keyframes: keyframe i (t = i/4) is frame 2i.
  const std::size_t animate = animated.find("<animate attributeName=\"d\"");
  ASSERT_NE(animate, std::string::npos);
  std::size_t pathIndex = 0;
  for (std::size_t at = animated.find("<path"); at < animate; at = animated.find("<path", at + 1)) ++pathIndex;
  --pathIndex;
  const std::size_t valuesAt = animated.find("values=\"", animate) + 8;
  std::string values = animated.substr(valuesAt, animated.find('"', valuesAt) - valuesAt);
  std::vector<std::string> keyframes;
  for (std::size_t from = 0, to; (to = values.find(';', from)) != std::string::npos || from < values.size(); from = to + 1) {
    if (to == std::string::npos) to = values.size();
    keyframes.push_back(values.substr(from, to - from));
  }
  ASSERT_EQ(keyframes.size(), 5u);  // four keyframes and the first again, closing the loop
  for (int i = 0; i < 4; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "frame-%04d.svg", 2 * i);
    const std::vector<double> frame = numbersIn(pathData(readWholeFile((out / "svg-frames" / name).string()), pathIndex));
    const std::vector<double> key = numbersIn(keyframes[i]);
    ASSERT_EQ(frame.size(), key.size()) << name;
    for (std::size_t k = 0; k < key.size(); ++k) ASSERT_NEAR(frame[k], key[k], 0.02) << name;
  }
  EXPECT_NE(animated.find("repeatCount=\"indefinite\""), std::string::npos);
  EXPECT_NE(animated.find("#fbc531"), std::string::npos) << "a star's colour is kept";
  const PngPixels first = readPngPixels(dir.file("first.png")), frame0 = readPngPixels((out / "frames" / "frame-0000.png").string());
  ASSERT_EQ(first.width, frame0.width);
  ASSERT_EQ(first.height, frame0.height);
  EXPECT_EQ(first.width, 120);
  for (int y = 0; y < first.height; y += 11)
    for (int x = 0; x < first.width; x += 11) ASSERT_TRUE(near(first.at(x, y), frame0.at(x, y).r, frame0.at(x, y).g, frame0.at(x, y).b, 0));
  const PngPixels sheet = readPngPixels((out / "contact-sheet.png").string());
  EXPECT_EQ(sheet.width, 3 * 120);
}

TEST(CliAnimate, SameFramesWithOneOrTwoThreadsAndAfterResuming) {
  ScratchFolder dir("cli-animate-determinism");
  const std::string common = kStars + " --no-gif --svg-frames --seed 4";
  PakRun one = runPak(common + " --max-iterations 60 --threads 1 -o " + shellQuoted(dir.file("one")));
  PakRun two = runPak(common + " --max-iterations 60 --threads 2 -o " + shellQuoted(dir.file("two")));
  PakRun half = runPak(common + " --max-iterations 30 --checkpoint " + shellQuoted(dir.file("ck.bin")) +
                       " --every 30 -o " + shellQuoted(dir.file("half")));
  ASSERT_EQ(one.exitCode, 0) << one.err;
  ASSERT_EQ(two.exitCode, 0) << two.err;
  ASSERT_EQ(half.exitCode, 0) << half.err;
  PakRun resumed = runPak(common + " --max-iterations 60 --resume " + shellQuoted(dir.file("ck.bin")) + " -o " +
                          shellQuoted(dir.file("resumed")));
  ASSERT_EQ(resumed.exitCode, 0) << resumed.err;
  for (const char* frame : {"frame-0000.svg", "frame-0005.svg"}) {
    const std::string a = readWholeFile((dir.path() / "one" / "svg-frames" / frame).string());
    EXPECT_EQ(a, readWholeFile((dir.path() / "two" / "svg-frames" / frame).string())) << frame;
    EXPECT_EQ(a, readWholeFile((dir.path() / "resumed" / "svg-frames" / frame).string())) << frame;
    EXPECT_NE(a, readWholeFile((dir.path() / "half" / "svg-frames" / frame).string())) << frame;
  }
  // A checkpoint does not fit other options.
  PakRun other = runPak(common + " --gap 0.1 --resume " + shellQuoted(dir.file("ck.bin")) + " -o " + shellQuoted(dir.file("x")));
  EXPECT_EQ(other.exitCode, 2);
  EXPECT_NE(other.err.find("checkpoint"), std::string::npos) << other.err;
}

TEST(CliAnimate, TheVideoTargetAndThePreviewTimeAreCheckedBeforeTheRun) {
  ScratchFolder dir("cli-animate-early-checks");
  // The output folder is made before the simulation starts: these fail before either.
  for (const std::string& extra : {std::string(" --video ") + shellQuoted(dir.file("v.avi")),
                                   " --png-at 1.5 --png " + shellQuoted(dir.file("p.png")),
                                   std::string(" --png-at 0.5")}) {
    PakRun run = runPak(kStars + extra + " -o " + shellQuoted(dir.file("out")));
    EXPECT_EQ(run.exitCode, 2) << extra << "\n" << run.err;
    EXPECT_EQ(run.err.rfind("pak: error: ", 0), 0u) << run.err;
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "out")) << extra;
  }
  EXPECT_NE(runPak(kStars + " --video " + shellQuoted(dir.file("v.avi")) + " -o " + shellQuoted(dir.file("out"))).err.find(
                "unknown video format"),
            std::string::npos);
}

TEST(CliAnimate, ThePreviewIsTheFrameAtPngAt) {
  ScratchFolder dir("cli-animate-png-at");
  const std::string common = kStars + " --max-iterations 200 --png-frames -o " + shellQuoted(dir.file("out"));
  ASSERT_EQ(runPak(common + " --png " + shellQuoted(dir.file("half.png")) + " --png-at 0.5").exitCode, 0);
  // A loop's 8 frames are at t = k / 8: frame 4 is t = 0.5, frame 0 is not.
  const PngPixels half = readPngPixels(dir.file("half.png"));
  const PngPixels frame4 = readPngPixels((dir.path() / "out" / "frames" / "frame-0004.png").string());
  const PngPixels frame0 = readPngPixels((dir.path() / "out" / "frames" / "frame-0000.png").string());
  ASSERT_EQ(half.width, frame4.width);
  ASSERT_EQ(half.height, frame4.height);
  int sameAs4 = 0, sameAs0 = 0, total = 0;
  for (int y = 0; y < half.height; y += 3)
    for (int x = 0; x < half.width; x += 3, ++total) {
      const Rgba p = half.at(x, y), a = frame4.at(x, y), b = frame0.at(x, y);
      sameAs4 += (p.r == a.r && p.g == a.g && p.b == a.b) ? 1 : 0;
      sameAs0 += (p.r == b.r && p.g == b.g && p.b == b.b) ? 1 : 0;
    }
  EXPECT_EQ(sameAs4, total);
  EXPECT_LT(sameAs0, total * 95 / 100);
}

TEST(CliAnimate, TheFixedMoonIsInEveryFrameAndTheStarsKeepClearOfIt) {
  ScratchFolder dir("cli-animate-fixed");
  PakRun run = runPak("animate -c examples/animate/stars/disc-moon.svg -a examples/animate/stars/stars.json --slices 6 "
                      "--frames 8 --width 120 --sheet-frames 3 --svg-keyframes 4 -q --max-iterations 400 --svg-frames -o " +
                      shellQuoted(dir.file("out")) + " --report " + shellQuoted(dir.file("r.json")));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const auto report = nlohmann::json::parse(readWholeFile(dir.file("r.json")));
  EXPECT_EQ(report["frames-with-overlaps"], 0);  // the moon counts as one more element
  EXPECT_EQ(report["frames-with-element-outside"], 0);
  for (const char* name : {"frame-0000.svg", "frame-0005.svg"})
    EXPECT_NE(readWholeFile((dir.path() / "out" / "svg-frames" / name).string()).find("#f3efd2"), std::string::npos)
        << name << " draws the moon";
  // SVG frames are written as curves (the animated SVG, which interpolates its paths, not).
  EXPECT_NE(readWholeFile((dir.path() / "out" / "svg-frames" / "frame-0000.svg").string()).find(" C"), std::string::npos);
}

TEST(CliAnimate, TheSwallowFliesThroughTheCloudAndOutAndFramesTile) {
  ScratchFolder dir("cli-animate-travelling");
  // 9 slices put the 8 frames on slices: the swallow crosses 80 units between two of them,
  // more than a frame between them follows cleanly after 300 iterations (the example has 50).
  PakRun run = runPak("animate -c examples/animate/birds/cloud.svg -a examples/animate/birds/flock.json --slices 9 "
                      "--frames 8 --width 120 --sheet-frames 3 --svg-keyframes 4 -q --max-iterations 300 --svg-frames -o " +
                      shellQuoted(dir.file("out")) + " --report " + shellQuoted(dir.file("r.json")));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const auto report = nlohmann::json::parse(readWholeFile(dir.file("r.json")));
  EXPECT_EQ(report["frames-with-overlaps"], 0);
  EXPECT_EQ(report["frames-with-element-outside"], 0);  // the swallow outside the cloud is not "outside"
  // The swallow is guided: its smallest drawn scale is reported on its own (its copies count as
  // the swallow), and no element was drawn smaller.
  const double guided = report["guided-smallest-separation-scale"], any = report["smallest-separation-scale"];
  EXPECT_GT(guided, 0.0);
  EXPECT_LE(guided, 1.0);
  EXPECT_GE(guided, any);
  // At t = 0 the swallow sits on the canvas's left edge: it is drawn there, one canvas width
  // further on (leaving the frame on the right, where the next tile begins) and one back.
  const std::string first = readWholeFile((dir.path() / "out" / "svg-frames" / "frame-0000.svg").string());
  std::size_t swallows = 0;
  for (std::size_t at = first.find("#2c4a86"); at != std::string::npos; at = first.find("#2c4a86", at + 1)) ++swallows;
  EXPECT_EQ(swallows, 3u);
}

TEST(CliAnimate, PenguinsTurnIntoGiraffesInACleanPacking) {
  ScratchFolder dir("cli-animate-penguins");
  PakRun run = runPak("animate -c examples/animate/penguins/square.svg -a examples/animate/penguins/turn.json --slices 6 "
                      "--frames 8 --width 120 --sheet-frames 3 --svg-keyframes 4 -q --max-iterations 300 -o " +
                      shellQuoted(dir.file("out")) + " --report " + shellQuoted(dir.file("r.json")));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const auto report = nlohmann::json::parse(readWholeFile(dir.file("r.json")));
  EXPECT_EQ(report["elements"], 25);
  EXPECT_EQ(report["frames-with-overlaps"], 0);
  EXPECT_EQ(report["frames-with-element-outside"], 0);
  EXPECT_EQ(report["parameters"]["k-torsion"], 10.0);  // what holds each slice at its scripted turn
  EXPECT_EQ(report["guided-smallest-separation-scale"], 1.0);  // none is guided
}

TEST(CliAnimate, TheMirroredManeIsSymmetricAndCheckedOverBothHalves) {
  ScratchFolder dir("cli-animate-mirror");
  PakRun run = runPak("animate -c examples/animate/lion/mane.svg -a examples/animate/lion/mane.json --mirror x=250 "
                      "--slices 6 --frames 8 --width 120 --sheet-frames 3 --svg-keyframes 4 -q --max-iterations 300 "
                      "--svg-frames --polyline -o " + shellQuoted(dir.file("out")) + " --report " + shellQuoted(dir.file("r.json")));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const auto report = nlohmann::json::parse(readWholeFile(dir.file("r.json")));
  EXPECT_EQ(report["elements"], 16);  // simulated: the left half
  EXPECT_EQ(report["parameters"]["mirror"], "x=250");
  EXPECT_EQ(report["frames-with-overlaps"], 0);  // both halves, the face and the twins across the line
  EXPECT_EQ(report["frames-with-element-outside"], 0);
  // Each frame draws 32 strands, in mirrored pairs: each strand's x coordinates are 500 − its
  // twin's, read in reverse.
  const std::string frame = readWholeFile((dir.path() / "out" / "svg-frames" / "frame-0003.svg").string());
  std::vector<std::string> strands;  // the `d` of each <path> painted in the strand's colour
  for (std::size_t at = frame.find("<path"); at != std::string::npos; at = frame.find("<path", at + 1)) {
    const std::string tag = frame.substr(at, frame.find('>', at) - at);
    if (tag.find("fill=\"#ee8a26\"") == std::string::npos) continue;
    const std::size_t d = tag.find(" d=\"") + 4;
    strands.push_back(tag.substr(d, tag.find('"', d) - d));
  }
  ASSERT_EQ(strands.size(), 32u);
  for (std::size_t e = 0; e < 16; ++e) {
    const std::vector<double> left = numbersIn(strands[e]), right = numbersIn(strands[16 + e]);
    ASSERT_EQ(left.size(), right.size()) << e;
    ASSERT_EQ(left.size() % 2, 0u);
    const std::size_t points = left.size() / 2;
    for (std::size_t i = 0; i < points; ++i) {
      EXPECT_NEAR(right[2 * (points - 1 - i)], 500.0 - left[2 * i], 0.02) << e;
      EXPECT_NEAR(right[2 * (points - 1 - i) + 1], left[2 * i + 1], 0.02) << e;
    }
  }
  PakRun bad = runPak("animate -c examples/animate/lion/mane.svg -a examples/animate/lion/mane.json --mirror y=3 -o " +
                      shellQuoted(dir.file("bad")));
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_EQ(bad.err.rfind("pak: error: --mirror: ", 0), 0u) << bad.err;
}

TEST(CliAnimate, BadInputIsOneLineAndExitCodeTwo) {
  ScratchFolder dir("cli-animate-errors");
  const std::string bad = dir.file("bad.json");
  std::ofstream(bad) << "{\"elements\": [{\"svg\": \"nowhere.svg\", \"count\": 0}]}";
  for (const std::string& args :
       {std::string("animate -c examples/animate/stars/disc.svg -a missing.json -o ") + shellQuoted(dir.file("o")),
        "animate -c examples/animate/stars/disc.svg -a " + shellQuoted(bad) + " -o " + shellQuoted(dir.file("o")),
        kStars + " --slices 1 -o " + shellQuoted(dir.file("o")),
        kStars + " --resume " + shellQuoted(bad) + " -o " + shellQuoted(dir.file("o"))}) {
    PakRun run = runPak(args);
    EXPECT_EQ(run.exitCode, 2) << args << "\n" << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_EQ(run.err.rfind("pak: error: ", 0), 0u) << run.err;
  }
}

}  // namespace
