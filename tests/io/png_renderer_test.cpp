// PNG rendering: reads the written PNG back with cairo and checks pixels whose colour is
// certain (far from any anti-aliased edge).
#include "pak/io/png_renderer.hpp"

#include <cairo/cairo.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "pak/error.hpp"

namespace fs = std::filesystem;

namespace {

struct Pixel {
  int r, g, b, a;
};

struct Image {
  int width = 0, height = 0;
  std::vector<Pixel> pixels;
  Pixel at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
};

// Decodes with cairo; ARGB32 is premultiplied, so divide the alpha back out.
Image readPng(const std::string& path) {
  cairo_surface_t* surface = cairo_image_surface_create_from_png(path.c_str());
  Image image;
  if (cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(surface);
    ADD_FAILURE() << "cannot read " << path;
    return image;
  }
  image.width = cairo_image_surface_get_width(surface);
  image.height = cairo_image_surface_get_height(surface);
  int stride = cairo_image_surface_get_stride(surface);
  const unsigned char* data = cairo_image_surface_get_data(surface);
  cairo_format_t format = cairo_image_surface_get_format(surface);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      std::uint32_t word = *reinterpret_cast<const std::uint32_t*>(data + y * stride + x * 4);
      int a = format == CAIRO_FORMAT_RGB24 ? 255 : static_cast<int>(word >> 24);
      auto channel = [&](int shift) {
        int premultiplied = static_cast<int>((word >> shift) & 0xff);
        return a == 0 ? 0 : (premultiplied * 255 + a / 2) / a;
      };
      image.pixels.push_back({channel(16), channel(8), channel(0), a});
    }
  cairo_surface_destroy(surface);
  return image;
}

pak::Subpath square(double x0, double y0, double x1, double y1, bool clockwise = true) {
  pak::Subpath subpath;
  subpath.closed = true;
  if (clockwise)
    subpath.points = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  else
    subpath.points = {{x0, y0}, {x0, y1}, {x1, y1}, {x1, y0}};
  return subpath;
}

pak::Drawing drawingOf(std::vector<pak::DrawnShape> shapes, pak::Box viewBox = {{0, 0}, {100, 100}}) {
  pak::Drawing drawing;
  drawing.viewBox = viewBox;
  pak::DrawingGroup group;
  group.id = "shapes";
  group.shapes = std::move(shapes);
  drawing.groups.push_back(std::move(group));
  return drawing;
}

pak::DrawnShape filled(std::vector<pak::Subpath> subpaths, pak::Color color, pak::FillRule rule = pak::FillRule::NonZero) {
  pak::DrawnShape shape;
  shape.subpaths = std::move(subpaths);
  shape.fill = color;
  shape.fillRule = rule;
  return shape;
}

const pak::Color kRed{255, 0, 0, 1.0};
const pak::Color kBlue{0, 0, 255, 1.0};

::testing::AssertionResult isColor(Pixel p, int r, int g, int b, int a = 255, int tolerance = 2) {
  if (std::abs(p.r - r) <= tolerance && std::abs(p.g - g) <= tolerance && std::abs(p.b - b) <= tolerance &&
      std::abs(p.a - a) <= tolerance)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "pixel is (" << p.r << ", " << p.g << ", " << p.b << ", " << p.a
                                       << "), expected (" << r << ", " << g << ", " << b << ", " << a << ")";
}

class PngRendererTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    folder_ = fs::temp_directory_path() /
              ("pak-png-" + std::string(info->name()) + "-" + std::to_string(::getpid()));
    fs::remove_all(folder_);
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }
  std::string file(const std::string& name) const { return (folder_ / name).string(); }
  fs::path folder_;
};

TEST_F(PngRendererTest, RedSquareOnWhite) {
  std::string path = file("square.png");
  pak::writePngFile(drawingOf({filled({square(25, 25, 75, 75)}, kRed)}), path, {.width = 200});
  Image image = readPng(path);
  ASSERT_EQ(image.width, 200);
  ASSERT_EQ(image.height, 200);
  EXPECT_TRUE(isColor(image.at(100, 100), 255, 0, 0));
  EXPECT_TRUE(isColor(image.at(2, 2), 255, 255, 255));
  EXPECT_TRUE(isColor(image.at(197, 197), 255, 255, 255));
  // The square covers [50, 150) pixels: its border lies where the viewBox maps it.
  EXPECT_TRUE(isColor(image.at(52, 100), 255, 0, 0));
  EXPECT_TRUE(isColor(image.at(47, 100), 255, 255, 255));
}

TEST_F(PngRendererTest, HeightFollowsTheAspectRatio) {
  std::string path = file("wide.png");
  pak::Drawing drawing = drawingOf({filled({square(0, 0, 100, 50)}, kBlue)}, {{0, 0}, {200, 100}});
  pak::writePngFile(drawing, path, {.width = 300});
  Image image = readPng(path);
  EXPECT_EQ(image.width, 300);
  EXPECT_EQ(image.height, 150);
  EXPECT_TRUE(isColor(image.at(70, 35), 0, 0, 255));
  EXPECT_TRUE(isColor(image.at(230, 110), 255, 255, 255));
}

TEST_F(PngRendererTest, ViewBoxOffsetIsHonoured) {
  std::string path = file("offset.png");
  pak::Drawing drawing = drawingOf({filled({square(1000, 2000, 1050, 2100)}, kRed)}, {{1000, 2000}, {1100, 2100}});
  pak::writePngFile(drawing, path, {.width = 100});
  Image image = readPng(path);
  EXPECT_TRUE(isColor(image.at(25, 50), 255, 0, 0));
  EXPECT_TRUE(isColor(image.at(75, 50), 255, 255, 255));
}

TEST_F(PngRendererTest, TransparentBackground) {
  std::string path = file("transparent.png");
  pak::writePngFile(drawingOf({filled({square(25, 25, 75, 75)}, kRed)}), path,
                    {.width = 100, .background = std::nullopt});
  Image image = readPng(path);
  EXPECT_EQ(image.at(2, 2).a, 0);
  EXPECT_TRUE(isColor(image.at(50, 50), 255, 0, 0));
}

TEST_F(PngRendererTest, CustomBackground) {
  std::string path = file("background.png");
  pak::writePngFile(drawingOf({}), path, {.width = 50, .background = pak::Color{10, 200, 30, 1.0}});
  EXPECT_TRUE(isColor(readPng(path).at(25, 25), 10, 200, 30));
}

TEST_F(PngRendererTest, EvenOddRingHasABackgroundCentre) {
  std::string path = file("ring.png");
  // Both squares wind the same way: only the even-odd rule makes the inner one a hole.
  pak::DrawnShape ring = filled({square(10, 10, 90, 90), square(30, 30, 70, 70)}, kBlue, pak::FillRule::EvenOdd);
  pak::writePngFile(drawingOf({ring}), path, {.width = 100});
  Image image = readPng(path);
  EXPECT_TRUE(isColor(image.at(50, 50), 255, 255, 255));
  EXPECT_TRUE(isColor(image.at(20, 50), 0, 0, 255));
}

TEST_F(PngRendererTest, NonZeroRuleFollowsWindingDirection) {
  std::string same = file("same.png"), opposite = file("opposite.png");
  pak::writePngFile(drawingOf({filled({square(10, 10, 90, 90), square(30, 30, 70, 70)}, kBlue)}), same, {.width = 100});
  pak::writePngFile(drawingOf({filled({square(10, 10, 90, 90), square(30, 30, 70, 70, false)}, kBlue)}), opposite,
                    {.width = 100});
  EXPECT_TRUE(isColor(readPng(same).at(50, 50), 0, 0, 255));
  EXPECT_TRUE(isColor(readPng(opposite).at(50, 50), 255, 255, 255));
}

TEST_F(PngRendererTest, StrokeOnlyShape) {
  std::string path = file("stroke.png");
  pak::DrawnShape outline;
  outline.subpaths = {square(20, 20, 80, 80)};
  outline.stroke = kRed;
  outline.strokeWidth = 8;
  pak::writePngFile(drawingOf({outline}), path, {.width = 100});
  Image image = readPng(path);
  EXPECT_TRUE(isColor(image.at(20, 50), 255, 0, 0));
  EXPECT_TRUE(isColor(image.at(50, 50), 255, 255, 255));
  EXPECT_TRUE(isColor(image.at(10, 50), 255, 255, 255));
}

TEST_F(PngRendererTest, TranslucentFillBlendsWithTheBackground) {
  std::string path = file("translucent.png");
  pak::writePngFile(drawingOf({filled({square(0, 0, 100, 100)}, {255, 0, 0, 0.5})}), path, {.width = 20});
  EXPECT_TRUE(isColor(readPng(path).at(10, 10), 255, 128, 128, 255, 3));
}

TEST_F(PngRendererTest, ShapeOpacityFadesFillAndStrokeTogether) {
  std::string path = file("opacity.png");
  pak::DrawnShape shape = filled({square(20, 20, 80, 80)}, kRed);
  shape.stroke = kBlue;
  shape.strokeWidth = 10;
  shape.opacity = 0.5;
  pak::writePngFile(drawingOf({shape}), path, {.width = 100});
  Image image = readPng(path);
  EXPECT_TRUE(isColor(image.at(50, 50), 255, 128, 128, 255, 3));
  // On the stroke the red fill must not show through the blue: half blue over white.
  EXPECT_TRUE(isColor(image.at(50, 22), 128, 128, 255, 255, 3));
}

TEST_F(PngRendererTest, NestedGroupsAreDrawnInOrder) {
  std::string path = file("nested.png");
  pak::Drawing drawing = drawingOf({filled({square(0, 0, 100, 100)}, kRed)});
  pak::DrawingGroup child;
  child.id = "on-top";
  child.shapes = {filled({square(40, 40, 60, 60)}, kBlue)};
  drawing.groups[0].children.push_back(child);
  pak::writePngFile(drawing, path, {.width = 100});
  Image image = readPng(path);
  EXPECT_TRUE(isColor(image.at(50, 50), 0, 0, 255));
  EXPECT_TRUE(isColor(image.at(10, 10), 255, 0, 0));
}

TEST_F(PngRendererTest, EmptyViewBoxFallsBackToTheDrawingsBounds) {
  std::string path = file("bounds.png");
  pak::Drawing drawing = drawingOf({filled({square(500, 500, 600, 550)}, kRed)}, pak::Box{});
  pak::writePngFile(drawing, path, {.width = 100});
  Image image = readPng(path);
  EXPECT_EQ(image.height, 50);
  EXPECT_TRUE(isColor(image.at(50, 25), 255, 0, 0));
}

TEST_F(PngRendererTest, MissingFolderIsAnInputErrorAndWritesNothing) {
  std::string path = file("missing/out.png");
  EXPECT_THROW(pak::writePngFile(drawingOf({}), path, {}), pak::InputError);
  EXPECT_TRUE(fs::is_empty(folder_));
}

TEST_F(PngRendererTest, WidthOutOfRangeIsAnInputError) {
  EXPECT_THROW(pak::writePngFile(drawingOf({}), file("zero.png"), {.width = 0}), pak::InputError);
  EXPECT_THROW(pak::writePngFile(drawingOf({}), file("huge.png"), {.width = 1000000}), pak::InputError);
  // A very tall drawing at a modest width would still be too many pixels.
  pak::Drawing tall = drawingOf({}, {{0, 0}, {1, 1000}});
  EXPECT_THROW(pak::writePngFile(tall, file("tall.png"), {.width = 1000}), pak::InputError);
  EXPECT_TRUE(fs::is_empty(folder_));
}

TEST_F(PngRendererTest, ConcurrentRendersAreIndependent) {
  std::vector<std::thread> threads;
  std::vector<pak::Color> colors = {{255, 0, 0, 1.0}, {0, 255, 0, 1.0}, {0, 0, 255, 1.0}, {255, 255, 0, 1.0}};
  for (std::size_t i = 0; i < colors.size(); ++i)
    threads.emplace_back([&, i] {
      pak::writePngFile(drawingOf({filled({square(0, 0, 100, 100)}, colors[i])}), file(std::to_string(i) + ".png"),
                        {.width = 64});
    });
  for (auto& thread : threads) thread.join();
  for (std::size_t i = 0; i < colors.size(); ++i)
    EXPECT_TRUE(isColor(readPng(file(std::to_string(i) + ".png")).at(32, 32), colors[i].r, colors[i].g, colors[i].b));
  EXPECT_EQ(std::distance(fs::directory_iterator(folder_), fs::directory_iterator()), 4);
}

}  // namespace
