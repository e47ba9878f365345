// Animation outputs: a red square moving across three frames, written as PNG frames, SVG
// frames, an animated SVG, a GIF, a video and a contact sheet, then read back: files, sizes,
// the colour under the square in every frame, and errors that leave no file behind.
#include "pak/io/animation_output.hpp"

#include <gtest/gtest.h>
#include <rapidxml_ns/rapidxml_ns.hpp>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli/png_pixels.hpp"
#include "io/color_palette.hpp"
#include "io/gif_decoder.hpp"
#include "pak/error.hpp"
#include "pak/io/png_renderer.hpp"
#include "pak/io/svg_reader.hpp"

namespace fs = std::filesystem;
using pak::testing::near;
using pak::testing::readPngPixels;

namespace {

const pak::Color kRed{220, 30, 30, 1.0}, kGreen{30, 160, 60, 1.0}, kBlue{40, 70, 200, 1.0};

pak::Subpath rectangle(double x0, double y0, double x1, double y1) {
  return {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, true};
}

// A 100 x 50 view box: a grey container outline and one element, a 20 x 20 square at x.
pak::Drawing squareFrame(double x, pak::Color colour = kRed) {
  pak::Drawing drawing;
  drawing.viewBox = {{0, 0}, {100, 50}};
  pak::DrawingGroup container;
  container.id = "container";
  container.shapes.push_back(pak::strokedLines({rectangle(1, 1, 99, 49)}, {120, 120, 120, 1.0}, 1.0));
  pak::DrawingGroup elements;
  elements.id = "elements";
  pak::DrawingGroup element;
  element.cssClass = "element";
  pak::DrawnShape square;
  square.subpaths = {rectangle(x, 15, x + 20, 35)};
  square.fill = colour;
  element.shapes.push_back(square);
  elements.children.push_back(element);
  drawing.groups = {container, elements};
  return drawing;
}

// The square at x = 10, 40, 70: at width 200 its centre is at pixel (2 x + 20, 50).
std::vector<pak::Drawing> movingSquare() { return {squareFrame(10), squareFrame(40), squareFrame(70)}; }
int centreX(double x) { return static_cast<int>(2 * x + 20); }

pak::AnimationOutputOptions smallOptions() {
  pak::AnimationOutputOptions options;
  options.width = 200;
  options.duration = 3.0;
  return options;
}

std::string readText(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

class AnimationOutputTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    folder_ = fs::temp_directory_path() / ("pak-animation-" + std::string(info->name()) + "-" + std::to_string(::getpid()));
    fs::remove_all(folder_);
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }
  std::string file(const std::string& name) const { return (folder_ / name).string(); }
  std::vector<std::string> entries(const fs::path& folder) const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
  fs::path folder_;
};

// --- raster helper ---

TEST_F(AnimationOutputTest, RenderToImageMatchesThePngFile) {
  pak::Drawing drawing = squareFrame(40);
  pak::PngOptions png{.width = 200};
  pak::RgbaImage image = pak::renderToImage(drawing, png);
  ASSERT_EQ(image.width, 200);
  ASSERT_EQ(image.height, 100);
  ASSERT_EQ(image.rgba.size(), 200u * 100u * 4u);
  auto at = [&](int x, int y) { return &image.rgba[(static_cast<std::size_t>(y) * image.width + x) * 4]; };
  EXPECT_EQ(at(100, 50)[0], kRed.r);
  EXPECT_EQ(at(100, 50)[1], kRed.g);
  EXPECT_EQ(at(100, 50)[2], kRed.b);
  EXPECT_EQ(at(100, 50)[3], 255);
  EXPECT_EQ(at(30, 20)[0], 255);  // background

  pak::writePngFile(drawing, file("square.png"), png);
  pak::testing::PngPixels written = readPngPixels(file("square.png"));
  ASSERT_EQ(written.width, image.width);
  ASSERT_EQ(written.height, image.height);
  for (int y = 0; y < image.height; y += 7)
    for (int x = 0; x < image.width; x += 7) {
      const std::uint8_t* p = at(x, y);
      EXPECT_TRUE(near(written.at(x, y), p[0], p[1], p[2], 1)) << x << "," << y;
    }
}

TEST_F(AnimationOutputTest, RenderToImageWithAFixedHeightCentresTheDrawing) {
  pak::PngOptions png{.width = 200, .background = std::nullopt, .height = 200};
  pak::RgbaImage image = pak::renderToImage(squareFrame(40), png);
  ASSERT_EQ(image.width, 200);
  ASSERT_EQ(image.height, 200);
  // The 2:1 drawing sits in the middle band (y 50 to 150); above it is transparent.
  EXPECT_EQ(image.rgba[(static_cast<std::size_t>(20) * 200 + 100) * 4 + 3], 0);
  const std::uint8_t* centre = &image.rgba[(static_cast<std::size_t>(100) * 200 + 100) * 4];
  EXPECT_EQ(centre[0], kRed.r);
  EXPECT_EQ(centre[3], 255);
}

// --- frame sequences ---

TEST_F(AnimationOutputTest, PngFramesShowTheSquareMoving) {
  std::vector<pak::Drawing> frames = movingSquare();
  std::string folder = file("frames/png");  // created, parents too
  pak::writePngFrames(frames, folder, smallOptions());
  EXPECT_EQ(entries(folder), (std::vector<std::string>{"frame-0000.png", "frame-0001.png", "frame-0002.png"}));
  const double xs[] = {10, 40, 70};
  for (int i = 0; i < 3; ++i) {
    auto image = readPngPixels(folder + "/frame-000" + std::to_string(i) + ".png");
    ASSERT_EQ(image.width, 200);
    ASSERT_EQ(image.height, 100);
    for (int j = 0; j < 3; ++j) {
      auto pixel = image.at(centreX(xs[j]), 50);
      if (i == j)
        EXPECT_TRUE(near(pixel, kRed.r, kRed.g, kRed.b)) << "frame " << i;
      else
        EXPECT_TRUE(near(pixel, 255, 255, 255)) << "frame " << i << " at square " << j;
    }
  }
}

TEST_F(AnimationOutputTest, PngFramesAllTakeTheFirstFramesSize) {
  std::vector<pak::Drawing> frames = movingSquare();
  frames[1].viewBox = {{0, 0}, {100, 100}};  // a square box: fitted into 200 x 100
  pak::writePngFrames(frames, file("frames"), smallOptions());
  for (const std::string& name : entries(file("frames"))) {
    auto image = readPngPixels(file("frames/" + name));
    EXPECT_EQ(image.width, 200) << name;
    EXPECT_EQ(image.height, 100) << name;
  }
}

TEST_F(AnimationOutputTest, SvgFramesAreReadableSvg) {
  std::vector<pak::Drawing> frames = movingSquare();
  pak::writeSvgFrames(frames, file("svg"), smallOptions());
  EXPECT_EQ(entries(file("svg")), (std::vector<std::string>{"frame-0000.svg", "frame-0001.svg", "frame-0002.svg"}));
  pak::SvgDocument document = pak::readSvgFile(file("svg/frame-0002.svg"));
  ASSERT_EQ(document.shapes.size(), 2u);
  EXPECT_EQ(document.shapes[1].fill, kRed);
  EXPECT_NEAR(bounds(document.shapes[1]).min.x, 70.0, 1e-6);
}

TEST_F(AnimationOutputTest, FramesIntoAFileFail) {
  std::ofstream(file("taken")) << "x";
  EXPECT_THROW(pak::writePngFrames(movingSquare(), file("taken"), smallOptions()), pak::InputError);
  EXPECT_THROW(pak::writeSvgFrames({}, file("empty"), smallOptions()), pak::InputError);
}

// --- animated SVG ---

struct SvgAnimate {
  std::string attribute, values, keyTimes, calcMode, repeatCount, fill, parent, parentClass;
};

// Parses the file as XML (throws on malformed markup) and lists its <animate> elements and ids.
std::vector<SvgAnimate> animatesOf(const std::string& text, std::vector<std::string>* ids = nullptr) {
  std::vector<char> buffer(text.begin(), text.end());
  buffer.push_back('\0');
  rapidxml_ns::xml_document<> document;
  document.parse<0>(buffer.data());
  std::vector<SvgAnimate> found;
  auto attribute = [](rapidxml_ns::xml_node<>* node, const char* name) {
    auto* a = node->first_attribute(name);
    return a ? std::string(a->value(), a->value_size()) : std::string();
  };
  auto visit = [&](rapidxml_ns::xml_node<>* node, auto& self) -> void {
    for (auto* child = node->first_node(); child; child = child->next_sibling()) {
      if (child->type() != rapidxml_ns::node_element) continue;
      std::string name(child->local_name(), child->local_name_size());
      if (ids && !attribute(child, "id").empty()) ids->push_back(attribute(child, "id"));
      if (name == "animate")
        found.push_back({attribute(child, "attributeName"), attribute(child, "values"), attribute(child, "keyTimes"),
                         attribute(child, "calcMode"), attribute(child, "repeatCount"), attribute(child, "fill"),
                         std::string(node->local_name(), node->local_name_size()), attribute(node, "class")});
      self(child, self);
    }
  };
  visit(&document, visit);
  return found;
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream stream(text);
  for (std::string part; std::getline(stream, part, separator);) parts.push_back(part);
  return parts;
}

TEST_F(AnimationOutputTest, AnimatedSvgMorphsEachShapeThroughTheFrames) {
  pak::writeAnimatedSvg(movingSquare(), file("moving.svg"), smallOptions());
  std::string text = readText(file("moving.svg"));
  std::vector<SvgAnimate> animates = animatesOf(text);
  // Only the square moves; the container outline is still and has no <animate>.
  ASSERT_EQ(animates.size(), 1u);
  const SvgAnimate& a = animates[0];
  EXPECT_EQ(a.attribute, "d");
  EXPECT_EQ(a.parent, "path");
  EXPECT_EQ(a.calcMode, "linear");
  EXPECT_EQ(a.repeatCount, "indefinite");
  std::vector<std::string> values = split(a.values, ';');
  ASSERT_EQ(values.size(), 4u);  // three frames, then the first again to loop smoothly
  EXPECT_EQ(values.front(), values.back());
  EXPECT_EQ(values[0].rfind("M10,15 L30,15", 0), 0u) << values[0];
  EXPECT_EQ(values[2].rfind("M70,15 L90,15", 0), 0u) << values[2];
  EXPECT_EQ(split(a.keyTimes, ';'), (std::vector<std::string>{"0", "0.333333", "0.666667", "1"}));
  EXPECT_NE(text.find("dur=\"3s\""), std::string::npos);
  // It looks like Pak's static output: the same layers and classes.
  EXPECT_NE(text.find("id=\"container\""), std::string::npos);
  EXPECT_NE(text.find("id=\"elements\""), std::string::npos);
  EXPECT_NE(text.find("class=\"element\""), std::string::npos);
  // Pak's own reader sees the first frame.
  pak::SvgDocument document = pak::readSvgString(text, "moving.svg");
  ASSERT_EQ(document.shapes.size(), 2u);
  EXPECT_NEAR(bounds(document.shapes[1]).min.x, 10.0, 1e-6);
}

TEST_F(AnimationOutputTest, AnimatedSvgThatPlaysOnceFreezesOnTheLastFrame) {
  pak::AnimationOutputOptions options = smallOptions();
  options.loop = false;
  pak::writeAnimatedSvg(movingSquare(), file("once.svg"), options);
  std::vector<SvgAnimate> animates = animatesOf(readText(file("once.svg")));
  ASSERT_EQ(animates.size(), 1u);
  EXPECT_EQ(split(animates[0].values, ';').size(), 3u);
  EXPECT_EQ(split(animates[0].keyTimes, ';'), (std::vector<std::string>{"0", "0.5", "1"}));
  EXPECT_EQ(animates[0].repeatCount, "");
  EXPECT_EQ(animates[0].fill, "freeze");
}

TEST_F(AnimationOutputTest, AnimatedSvgCoordinatesFollowTheViewBoxSize) {
  std::vector<pak::Drawing> frames = movingSquare();
  for (pak::Drawing& frame : frames) {  // the same picture in a unit box
    frame.viewBox = {{0, 0}, {1, 0.5}};
    for (pak::DrawingGroup* group : {&frame.groups[0], &frame.groups[1].children[0]})
      for (pak::DrawnShape& shape : group->shapes)
        for (pak::Subpath& subpath : shape.subpaths)
          for (pak::Vec2& p : subpath.points) p = p * (1.0 / 100.0) + pak::Vec2{0.0012345, 0.0};
  }
  pak::writeAnimatedSvg(frames, file("unit.svg"), smallOptions());
  std::vector<SvgAnimate> animates = animatesOf(readText(file("unit.svg")));
  ASSERT_EQ(animates.size(), 1u);
  // 4 decimals for a box of size 1: 0.1012345 is written 0.1012.
  EXPECT_EQ(split(animates[0].values, ';')[0].rfind("M0.1012,0.15", 0), 0u) << animates[0].values;
}

TEST_F(AnimationOutputTest, AnimatedSvgShowsFramesInTurnWhenTheirStructureDiffers) {
  std::vector<pak::Drawing> frames = movingSquare();
  frames[1].groups[1].children.push_back(frames[1].groups[1].children[0]);  // a second element
  frames[1].groups[1].children[1].shapes[0].fill = kBlue;
  frames[2].groups[1].children[0].shapes[0].fill = kGreen;  // other paint
  pak::writeAnimatedSvg(frames, file("flip.svg"), smallOptions());
  std::string text = readText(file("flip.svg"));
  std::vector<std::string> ids;
  std::vector<SvgAnimate> animates = animatesOf(text, &ids);
  ASSERT_EQ(animates.size(), 3u);
  EXPECT_EQ(animates[0].values, "visible;hidden");
  EXPECT_EQ(animates[0].keyTimes, "0;0.333333");
  EXPECT_EQ(animates[1].values, "hidden;visible;hidden");
  EXPECT_EQ(animates[1].keyTimes, "0;0.333333;0.666667");
  EXPECT_EQ(animates[2].values, "hidden;visible");
  EXPECT_EQ(animates[2].keyTimes, "0;0.666667");
  for (const SvgAnimate& a : animates) {
    EXPECT_EQ(a.attribute, "visibility");
    EXPECT_EQ(a.calcMode, "discrete");
    EXPECT_EQ(a.parentClass, "frame");
  }
  // Every id once: the later frames' layers get a suffix.
  std::set<std::string> unique(ids.begin(), ids.end());
  EXPECT_EQ(unique.size(), ids.size());
  EXPECT_TRUE(unique.count("container") && unique.count("container-f1") && unique.count("elements-f2"));
  EXPECT_NE(text.find("class=\"element\""), std::string::npos);
  // Without SMIL (Inkscape) the first frame shows: only the later frames start hidden.
  EXPECT_NE(text.find("inkscape:label=\"frame-0000\">"), std::string::npos);
  EXPECT_NE(text.find("inkscape:label=\"frame-0001\" visibility=\"hidden\">"), std::string::npos);
  EXPECT_NE(text.find("inkscape:label=\"frame-0002\" visibility=\"hidden\">"), std::string::npos);
}

// A scene's copied layers are the same in every frame: written once, outside the frames, the
// background under them and the title over them, so their ids stay unique.
TEST_F(AnimationOutputTest, AnimatedSvgWritesTheScenesCopiedLayersOnce) {
  std::vector<pak::Drawing> frames = movingSquare();
  frames[1].groups[1].children.push_back(frames[1].groups[1].children[0]);  // a flip book
  auto copied = [](const std::string& content) {
    pak::DrawingGroup group;
    group.markup = pak::RawMarkup{content, {}, {}};
    group.markupReplacesGroup = true;
    return group;
  };
  const std::string background = R"~(<g id="paper"><rect width="100" height="50" fill="#ffe"/></g>)~";
  const std::string title = R"~(<g id="title"><rect id="rule" width="100" height="2"/></g>)~";
  for (pak::Drawing& frame : frames) {
    frame.groups.insert(frame.groups.begin(), copied(background));
    frame.groups.push_back(copied(title));
  }
  pak::writeAnimatedSvg(frames, file("layers.svg"), smallOptions());
  const std::string text = readText(file("layers.svg"));
  std::vector<std::string> ids;
  animatesOf(text, &ids);
  std::set<std::string> unique(ids.begin(), ids.end());
  EXPECT_EQ(unique.size(), ids.size()) << text;
  const std::size_t paper = text.find(background), rule = text.find(title);
  ASSERT_NE(paper, std::string::npos);
  ASSERT_NE(rule, std::string::npos);
  EXPECT_EQ(text.find(background, paper + 1), std::string::npos);
  EXPECT_EQ(text.find(title, rule + 1), std::string::npos);
  EXPECT_LT(paper, text.find("id=\"frame-0000\""));
  EXPECT_GT(rule, text.find("id=\"frame-0002\""));
}

TEST_F(AnimationOutputTest, AnimatedSvgOfOneFrameIsStatic) {
  pak::writeAnimatedSvg({squareFrame(10)}, file("one.svg"), smallOptions());
  EXPECT_TRUE(animatesOf(readText(file("one.svg"))).empty());
}

// --- GIF ---

TEST_F(AnimationOutputTest, GifHasEveryFrameWithItsColours) {
  std::vector<pak::Drawing> frames = {squareFrame(10, kRed), squareFrame(40, kGreen), squareFrame(70, kBlue)};
  pak::writeGif(frames, file("squares.gif"), smallOptions());
  pak::testing::Gif gif = pak::testing::decodeGif(file("squares.gif"));
  EXPECT_EQ(gif.width, 200);
  EXPECT_EQ(gif.height, 100);
  ASSERT_EQ(gif.frames.size(), 3u);
  ASSERT_TRUE(gif.loopCount.has_value());
  EXPECT_EQ(*gif.loopCount, 0);  // forever
  for (const pak::Color& c : {kRed, kGreen, kBlue}) EXPECT_TRUE(gif.paletteHas(c.r, c.g, c.b));
  EXPECT_TRUE(gif.paletteHas(255, 255, 255));
  const pak::Color colours[] = {kRed, kGreen, kBlue};
  const double xs[] = {10, 40, 70};
  int total = 0;
  for (int i = 0; i < 3; ++i) {
    total += gif.frames[i].delay;
    EXPECT_EQ(gif.frames[i].delay, 100);  // 3 s over 3 frames
    for (int j = 0; j < 3; ++j) {
      pak::testing::GifPixel p = gif.at(i, centreX(xs[j]), 50);
      EXPECT_EQ(p.a, 255);
      if (i == j) {
        EXPECT_EQ(p.r, colours[i].r) << "frame " << i;
        EXPECT_EQ(p.g, colours[i].g) << "frame " << i;
        EXPECT_EQ(p.b, colours[i].b) << "frame " << i;
      } else {
        EXPECT_EQ(p.r + p.g + p.b, 3 * 255) << "frame " << i << " at square " << j;
      }
    }
  }
  EXPECT_EQ(total, 300);
  EXPECT_EQ(entries(folder_), std::vector<std::string>{"squares.gif"});  // no temporary left
}

TEST_F(AnimationOutputTest, GifWithoutBackgroundIsTransparentAndCanPlayOnce) {
  pak::AnimationOutputOptions options = smallOptions();
  options.background.reset();
  options.loop = false;
  options.duration = 0.05;  // shorter than GIF's shortest useful delay
  pak::writeGif(movingSquare(), file("clear.gif"), options);
  pak::testing::Gif gif = pak::testing::decodeGif(file("clear.gif"));
  ASSERT_EQ(gif.frames.size(), 3u);
  EXPECT_FALSE(gif.loopCount.has_value());
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(gif.frames[i].delay, 2);
    EXPECT_EQ(gif.at(i, 5, 50).a, 0) << "frame " << i;  // between the outline and the edge
    pak::testing::GifPixel p = gif.at(i, centreX(10 + 30 * i), 50);
    EXPECT_EQ(p.a, 255);
    EXPECT_EQ(p.r, kRed.r);
    // The previous frame's square is gone (disposal to background).
    if (i > 0) {
      EXPECT_EQ(gif.at(i, centreX(10 + 30 * (i - 1)), 50).a, 0);
    }
  }
}

TEST_F(AnimationOutputTest, GifOfManyColoursKeepsThemClose) {
  // A strip of 400 grey-to-colour bars: more colours than a GIF holds.
  pak::Drawing drawing;
  drawing.viewBox = {{0, 0}, {400, 10}};
  pak::DrawingGroup bars;
  for (int i = 0; i < 400; ++i) {
    pak::DrawnShape bar;
    bar.subpaths = {rectangle(i, 0, i + 1, 10)};
    bar.fill = pak::Color{static_cast<std::uint8_t>(i * 255 / 399), static_cast<std::uint8_t>(255 - i * 255 / 399),
                          static_cast<std::uint8_t>((i * 7) % 256), 1.0};
    bars.shapes.push_back(bar);
  }
  drawing.groups = {bars};
  pak::AnimationOutputOptions options = smallOptions();
  options.width = 400;
  pak::writeGif({drawing, drawing}, file("bars.gif"), options);
  pak::testing::Gif gif = pak::testing::decodeGif(file("bars.gif"));
  ASSERT_EQ(gif.frames.size(), 2u);
  EXPECT_LE(gif.globalPalette.size(), 256u * 3u);
  pak::RgbaImage exact = pak::renderToImage(drawing, {.width = 400});
  double error = 0.0;
  for (int x = 0; x < 400; ++x) {
    const std::uint8_t* p = &exact.rgba[(static_cast<std::size_t>(5) * 400 + x) * 4];
    pak::testing::GifPixel q = gif.at(1, x, 5);
    error = std::max({error, std::abs(p[0] - q.r) * 1.0, std::abs(p[1] - q.g) * 1.0, std::abs(p[2] - q.b) * 1.0});
  }
  EXPECT_LE(error, 24.0);
}

TEST(AnimationPalette, FewColoursAreKeptExactly) {
  pak::RgbaImage image{4, 1, {10, 20, 30, 255, 10, 20, 30, 255, 200, 100, 0, 255, 0, 0, 0, 0}};
  pak::color_palette::ColorHistogram histogram;
  histogram.add(image, pak::color_palette::Rgb{200, 100, 0});
  std::vector<pak::color_palette::Rgb> palette = pak::color_palette::medianCut(histogram, 255, {{200, 100, 0}});
  ASSERT_EQ(palette.size(), 2u);
  EXPECT_EQ(palette[0], (pak::color_palette::Rgb{200, 100, 0}));
  EXPECT_EQ(palette[1], (pak::color_palette::Rgb{10, 20, 30}));
  pak::color_palette::NearestColor nearest(palette);
  EXPECT_EQ(nearest({12, 18, 30}), 1);
  EXPECT_EQ(nearest({190, 90, 10}), 0);
}

// --- video ---

TEST_F(AnimationOutputTest, VideoNeedsAKnownExtension) {
  try {
    pak::writeVideo(movingSquare(), file("movie.avi"), smallOptions());
    FAIL() << "no error";
  } catch (const pak::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("use .mp4 or .webm"), std::string::npos) << error.what();
  }
  EXPECT_TRUE(entries(folder_).empty());
}

TEST_F(AnimationOutputTest, VideoWithoutFfmpegSaysSo) {
  if (pak::videoEncoderAvailable()) GTEST_SKIP() << "ffmpeg is installed; the missing-encoder path is not reachable";
  try {
    pak::writeVideo(movingSquare(), file("movie.mp4"), smallOptions());
    FAIL() << "no error";
  } catch (const pak::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("ffmpeg not found; install it for MP4/WebM output"), std::string::npos)
        << error.what();
  }
  EXPECT_TRUE(entries(folder_).empty());
}

TEST_F(AnimationOutputTest, VideoIsWrittenByFfmpeg) {
  if (!pak::videoEncoderAvailable()) GTEST_SKIP() << "ffmpeg is not installed";
  pak::AnimationOutputOptions options = smallOptions();
  options.width = 201;  // odd: rounded up to even for 4:2:0
  pak::writeVideo(movingSquare(), file("movie.mp4"), options);
  std::string mp4 = readText(file("movie.mp4"));
  ASSERT_GT(mp4.size(), 12u);
  EXPECT_EQ(mp4.substr(4, 4), "ftyp");
  pak::writeVideo(movingSquare(), file("movie.webm"), options);
  std::string webm = readText(file("movie.webm"));
  ASSERT_GT(webm.size(), 4u);
  EXPECT_EQ(webm.substr(0, 4), std::string("\x1a\x45\xdf\xa3"));
  EXPECT_EQ(entries(folder_), (std::vector<std::string>{"movie.mp4", "movie.webm"}));
}

// A stand-in `ffmpeg` on PATH, so the pipe, the arguments and the temporary file are tested
// where the real program is not installed. Restores PATH afterwards.
class FakeFfmpeg {
 public:
  FakeFfmpeg(const fs::path& folder, const std::string& body) : oldPath_(std::getenv("PATH") ? std::getenv("PATH") : "") {
    fs::create_directories(folder);
    const fs::path script = folder / "ffmpeg";
    std::ofstream(script) << "#!/bin/sh\n"
                             "for a in \"$@\"; do [ \"$a\" = -version ] && exit 0; done\n"
                          << body;
    fs::permissions(script, fs::perms::owner_all);
    ::setenv("PATH", (folder.string() + ":" + oldPath_).c_str(), 1);
  }
  ~FakeFfmpeg() { ::setenv("PATH", oldPath_.c_str(), 1); }

 private:
  std::string oldPath_;
};

TEST_F(AnimationOutputTest, VideoPipesRawFramesIntoFfmpeg) {
  // Records its arguments, then copies stdin (the raw frames) to its last argument.
  FakeFfmpeg fake(folder_ / "bin", "echo \"$@\" > \"$(dirname \"$0\")/arguments\"\n"
                                   "for a in \"$@\"; do last=\"$a\"; done\n"
                                   "cat > \"$last\"\n");
  ASSERT_TRUE(pak::videoEncoderAvailable());
  pak::AnimationOutputOptions options = smallOptions();
  options.width = 201;  // odd: rounded up to even for 4:2:0, the height too
  const int height = pak::renderToImage(squareFrame(10), {.width = 201}).height;
  const std::string size = "202x" + std::to_string(height + height % 2);
  pak::writeVideo(movingSquare(), file("movie.mp4"), options);
  EXPECT_EQ(fs::file_size(file("movie.mp4")), 202u * (height + height % 2) * 4u * 3u);
  std::string arguments = readText(file("bin/arguments"));
  for (const std::string& expected : {"-f rawvideo -pix_fmt rgba -s " + size + " -r 3000/3000 -i -",
                                      std::string("-c:v libx264"), std::string("-pix_fmt yuv420p"), std::string("-f mp4")})
    EXPECT_NE(arguments.find(expected), std::string::npos) << expected << " in " << arguments;
  pak::writeVideo(movingSquare(), file("movie.webm"), options);
  EXPECT_NE(readText(file("bin/arguments")).find("-c:v libvpx-vp9"), std::string::npos);
  EXPECT_EQ(entries(folder_), (std::vector<std::string>{"bin", "movie.mp4", "movie.webm"}));
}

TEST_F(AnimationOutputTest, VideoReportsFfmpegsErrorAndLeavesNoFile) {
  // Quits at once without reading: the writer gets a broken pipe, which must not kill it.
  FakeFfmpeg fake(folder_ / "bin", "echo \"Unknown encoder 'libx264'\" >&2\nexit 1\n");
  try {
    pak::writeVideo(movingSquare(), file("movie.mp4"), smallOptions());
    FAIL() << "no error";
  } catch (const pak::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("ffmpeg failed: Unknown encoder 'libx264'"), std::string::npos)
        << error.what();
  }
  EXPECT_EQ(entries(folder_), std::vector<std::string>{"bin"});
}

// --- contact sheet ---

TEST_F(AnimationOutputTest, ContactSheetPutsFramesInRows) {
  std::vector<pak::Drawing> frames = {squareFrame(10, kRed), squareFrame(40, kGreen), squareFrame(70, kBlue),
                                      squareFrame(10, kGreen), squareFrame(40, kBlue)};
  pak::writeContactSheet(frames, {}, file("plain.png"), 3, smallOptions());
  auto plain = readPngPixels(file("plain.png"));
  EXPECT_EQ(plain.width, 3 * 200);
  EXPECT_EQ(plain.height, 2 * 100);
  // Frame 4 (row 1, column 1) shows its blue square; the empty sixth cell is background.
  EXPECT_TRUE(near(plain.at(200 + centreX(40), 100 + 50), kBlue.r, kBlue.g, kBlue.b));
  EXPECT_TRUE(near(plain.at(400 + centreX(70), 50), kBlue.r, kBlue.g, kBlue.b));
  EXPECT_TRUE(near(plain.at(400 + 100, 150), 255, 255, 255));
  // A thin border at the edge of each frame.
  EXPECT_LT(plain.at(200, 50).r, 200);
  EXPECT_LT(plain.at(250, 100).r, 200);

  std::vector<std::string> captions = {"t = 0", "t = 0.2", "t = 0.4", "t = 0.6", "t = 0.8"};
  pak::writeContactSheet(frames, captions, file("captioned.png"), 5, smallOptions());
  auto captioned = readPngPixels(file("captioned.png"));
  EXPECT_EQ(captioned.width, 5 * 200);
  EXPECT_GT(captioned.height, 100);
  EXPECT_LT(captioned.height, 200);
  // Some dark caption pixels under the first frame.
  int dark = 0;
  for (int y = 100; y < captioned.height; ++y)
    for (int x = 0; x < 200; ++x) dark += captioned.at(x, y).r < 128;
  EXPECT_GT(dark, 10);
}

TEST_F(AnimationOutputTest, ContactSheetChecksItsArguments) {
  EXPECT_THROW(pak::writeContactSheet(movingSquare(), {"one"}, file("sheet.png"), 3, smallOptions()), pak::InputError);
  EXPECT_THROW(pak::writeContactSheet(movingSquare(), {}, file("sheet.png"), 0, smallOptions()), pak::InputError);
  EXPECT_TRUE(entries(folder_).empty());
}

// --- errors ---

TEST_F(AnimationOutputTest, UnwritablePathsFailAndLeaveNoFile) {
  const std::string missing = file("no-such-folder/out");
  std::vector<pak::Drawing> frames = movingSquare();
  EXPECT_THROW(pak::writeAnimatedSvg(frames, missing + ".svg", smallOptions()), pak::InputError);
  EXPECT_THROW(pak::writeGif(frames, missing + ".gif", smallOptions()), pak::InputError);
  EXPECT_THROW(pak::writeContactSheet(frames, {}, missing + ".png", 3, smallOptions()), pak::InputError);
  EXPECT_THROW(pak::writeVideo(frames, missing + ".mp4", smallOptions()), pak::InputError);
  EXPECT_TRUE(entries(folder_).empty());

  // Nothing to write, or no time to show it in.
  EXPECT_THROW(pak::writeGif({}, file("empty.gif"), smallOptions()), pak::InputError);
  pak::AnimationOutputOptions still = smallOptions();
  still.duration = 0.0;
  EXPECT_THROW(pak::writeAnimatedSvg(frames, file("still.svg"), still), pak::InputError);
  pak::AnimationOutputOptions huge = smallOptions();
  huge.width = 100000;
  EXPECT_THROW(pak::writeGif(frames, file("huge.gif"), huge), pak::InputError);
  EXPECT_TRUE(entries(folder_).empty());
}

}  // namespace
