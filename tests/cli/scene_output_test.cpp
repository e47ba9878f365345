// What a packing's output keeps of its scene (tests/svg/poster-scene.svg): the page size in
// the scene's own units, and the layers no method uses, copied as written in their places.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <regex>
#include <string>

#include "png_pixels.hpp"
#include "pak/io/svg_reader.hpp"
#include "run_pak.hpp"

using namespace pak::testing;

namespace {

const std::string kScene = "tests/svg/poster-scene.svg";

std::string sceneText() { return readWholeFile(std::filesystem::path(PAK_SOURCE_DIR) / kScene); }

// The scene's layer whose start tag has `id="<id>"`, as written: from its <g to its </g>.
std::string layerSource(const std::string& id) {
  const std::string text = sceneText();
  const std::size_t begin = text.rfind("<g", text.find("id=\"" + id + "\""));
  return text.substr(begin, text.find("</g>", begin) + 4 - begin);
}

// Every id="…" of an SVG with how often it occurs.
std::map<std::string, int> idCounts(const std::string& svg) {
  std::map<std::string, int> counts;
  const std::regex id(R"~(\sid="([^"]*)")~");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), id); it != std::sregex_iterator(); ++it) ++counts[(*it)[1]];
  return counts;
}

void expectUniqueIds(const std::string& svg) {
  for (const auto& [id, count] : idCounts(svg)) EXPECT_EQ(count, 1) << "id \"" << id << "\"";
}

// The output is the page the artist drew, with the layers around the packing in the order
// drawn: the background under the container, the title and the hidden notes over the elements.
void expectSceneAround(const std::string& svg) {
  EXPECT_NE(svg.find(R"~(width="210mm" height="210mm" viewBox="0 0 210 210")~"), std::string::npos) << svg.substr(0, 400);
  const std::size_t background = svg.find(layerSource("layer1"));
  const std::size_t title = svg.find(layerSource("layer3"));
  const std::size_t notes = svg.find(layerSource("layer4"));
  const std::size_t container = svg.find("<g id=\"container\"");
  const std::size_t elements = svg.find("<g id=\"elements\"");
  ASSERT_NE(background, std::string::npos) << svg;
  ASSERT_NE(title, std::string::npos) << svg;
  ASSERT_NE(notes, std::string::npos) << svg;
  ASSERT_NE(container, std::string::npos);
  ASSERT_NE(elements, std::string::npos);
  EXPECT_LT(background, container);
  EXPECT_LT(elements, title);
  EXPECT_LT(title, notes);
  EXPECT_EQ(svg.find("M 40 112 H 170"), std::string::npos);  // the guides are Pak's, not copied
  // What the copies reference, once: the gradient and the one holding its stops, the symbol,
  // and the disc the shadow clones (Pak's container path gives way to its id); not the rest.
  for (const char* definition : {"<linearGradient id=\"skyFill\"", "<linearGradient id=\"sky\"", "<symbol id=\"sparkle\"",
                                 "<circle id=\"disc\""})
    EXPECT_NE(svg.find(definition), std::string::npos) << definition;
  EXPECT_EQ(svg.find("unused"), std::string::npos);
  EXPECT_NE(svg.find("xmlns:sodipodi=\"http://sodipodi.sourceforge.net/DTD/sodipodi-0.dtd\""), std::string::npos);
  expectUniqueIds(svg);
  // It reads back: the copied layers are layers again.
  pak::SvgDocument back = pak::readSvgString(svg, "out.svg");
  for (const char* layer : {"background", "title", "notes", "container", "elements"})
    EXPECT_NE(std::find(back.layers.begin(), back.layers.end(), layer), back.layers.end()) << layer;
}

}  // namespace

TEST(CliSceneOutput, PackKeepsThePageSizeAndTheOtherLayersInTheirPlaces) {
  ScratchFolder dir("cli-scene-pack");
  PakRun run = runPak("pack -c " + kScene + " -e examples/elements --count 5 --max-iterations 50 --progress-every 1000 -o " +
                      shellQuoted(dir.file("out.svg")) + " --png " + shellQuoted(dir.file("out.png")));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  // The copied layers are not read, so their text and gradient give no warning.
  for (const std::string& line : run.errLines()) EXPECT_EQ(line.find("pak: warning:"), std::string::npos) << line;
  expectSceneAround(readWholeFile(dir.file("out.svg")));
  // The preview draws the background too: its gradient's mean colour in the page's corner.
  PngPixels png = readPngPixels(dir.file("out.png"));
  ASSERT_GT(png.width, 0);
  const Rgba corner = png.at(2, 2);
  EXPECT_NEAR(corner.r, 253, 3);
  EXPECT_NEAR(corner.g, 227, 3);
  EXPECT_NEAR(corner.b, 138, 3);
}

TEST(CliSceneOutput, FlowKeepsThePageSizeAndTheOtherLayersInTheirPlaces) {
  ScratchFolder dir("cli-scene-flow");
  PakRun run = runPak("flow " + kScene + " -e examples/flow/elements --count 8 --iterations 0 -q -o " +
                      shellQuoted(dir.file("flow.svg")));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  expectSceneAround(readWholeFile(dir.file("flow.svg")));
}

// A layer with another name holds the containers (--container-layer): it is not copied, and
// the `container` layer, Pak's name, is not either.
TEST(CliSceneOutput, TheContainerLayerIsNeverCopied) {
  ScratchFolder dir("cli-scene-layer");
  std::string scene = sceneText();
  scene.replace(scene.find("inkscape:label=\"Title\""), 22, "inkscape:label=\"Frame\"");
  const std::string shapes = R"~(<g id="shapes"><rect x="40" y="40" width="130" height="130" fill="#ccc"/></g>)~";
  scene.replace(scene.find("</svg>"), 0, shapes);
  const std::string file = dir.write("scene.svg", scene);
  PakRun run = runPak("pack -c " + shellQuoted(file) + " --container-layer shapes -e examples/elements --count 3 "
                      "--max-iterations 20 -q -o " + shellQuoted(dir.file("out.svg")));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const std::string svg = readWholeFile(dir.file("out.svg"));
  EXPECT_NE(svg.find("inkscape:label=\"Frame\""), std::string::npos);
  EXPECT_EQ(svg.find("<g id=\"shapes\">"), std::string::npos);      // drawn by Pak as its container
  EXPECT_EQ(svg.find("id=\"layer2\""), std::string::npos);          // the `container` layer
  EXPECT_LT(svg.find("inkscape:label=\"Frame\""), svg.find("<g id=\"container\""));  // drawn before `shapes`
  expectUniqueIds(svg);
}

// A .path scene has no units and no layers: the output is sized in numbers, as before.
TEST(CliSceneOutput, PathScenesKeepTheirNumericSize) {
  ScratchFolder dir("cli-scene-path");
  const std::string scene = dir.write("square.path",
                                      "1\nforeground_color_rgb 0 0,0,0\nbackground_color_rgb 0 230,230,230\n"
                                      "0 1 0 0 0 400 0 400 300 0 300\n");
  PakRun run = runPak("pack -c " + shellQuoted(scene) + " -e examples/elements --count 3 --max-iterations 20 -q -o " +
                      shellQuoted(dir.file("out.svg")));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const std::string svg = readWholeFile(dir.file("out.svg"));
  std::smatch size;
  ASSERT_TRUE(std::regex_search(svg, size, std::regex(R"~(<svg [^>]*width="([^"]*)" height="([^"]*)")~")))
      << svg.substr(0, 300);
  EXPECT_TRUE(std::regex_match(size.str(1), std::regex("[0-9.]+"))) << size.str(1);
  EXPECT_TRUE(std::regex_match(size.str(2), std::regex("[0-9.]+"))) << size.str(2);
  expectUniqueIds(svg);
}
