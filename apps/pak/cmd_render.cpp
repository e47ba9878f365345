// `pak render FILE -o OUT`: draws any input or output file (SVG or .path) as PNG or SVG, the
// way Pak understood it: holes as holes, hidden things gone, curves flattened.
#include <algorithm>
#include <cctype>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "command.hpp"
#include "output_files.hpp"
#include "pak/error.hpp"
#include "pak/io/drawing.hpp"
#include "pak/io/output_batch.hpp"
#include "pak/io/png_renderer.hpp"
#include "pak/io/scene_loader.hpp"
#include "pak/io/svg_reader.hpp"
#include "pak/io/svg_writer.hpp"

namespace pak::cli {
namespace {

struct RenderOptions {
  std::string input;
  std::string output;
  int width = 1000;
  std::string background = "white";
};

std::string lowerCase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

int hexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

// "#rgb", "#rrggbb", a few common names, or "none"/"transparent" (nullopt).
std::optional<Color> parseBackground(const std::string& text) {
  std::string value = lowerCase(text);
  if (value == "none" || value == "transparent") return std::nullopt;
  struct Named {
    const char* name;
    Color color;
  };
  static const Named kNames[] = {{"white", {255, 255, 255, 1.0}}, {"black", {0, 0, 0, 1.0}},
                                 {"gray", {128, 128, 128, 1.0}},  {"grey", {128, 128, 128, 1.0}},
                                 {"red", {255, 0, 0, 1.0}},       {"green", {0, 128, 0, 1.0}},
                                 {"blue", {0, 0, 255, 1.0}},      {"yellow", {255, 255, 0, 1.0}}};
  for (const Named& named : kNames)
    if (value == named.name) return named.color;
  if (!value.empty() && value[0] == '#' && (value.size() == 4 || value.size() == 7) &&
      std::all_of(value.begin() + 1, value.end(), [](char c) { return hexDigit(c) >= 0; })) {
    auto channel = [&](int index) {
      if (value.size() == 4) return static_cast<std::uint8_t>(hexDigit(value[1 + index]) * 17);
      return static_cast<std::uint8_t>(hexDigit(value[1 + 2 * index]) * 16 + hexDigit(value[2 + 2 * index]));
    };
    return Color{channel(0), channel(1), channel(2), 1.0};
  }
  throw InputError("--background", "'" + text + "' is not a colour (use #rrggbb, #rgb, white, black, … or none)");
}

std::string extensionOf(const std::string& path) {
  auto slash = path.find_last_of('/');
  auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  return lowerCase(path.substr(dot));
}

// For SVG output a background is an explicit rectangle under everything else.
void addBackground(Drawing& drawing, const Color& color) {
  Box box = drawing.viewBox;
  if (box.empty()) return;
  DrawnShape rectangle;
  rectangle.subpaths = {{{box.min, {box.max.x, box.min.y}, box.max, {box.min.x, box.max.y}}, true}};
  rectangle.fill = color;
  DrawingGroup group;
  group.id = "background";
  group.shapes.push_back(rectangle);
  drawing.groups.insert(drawing.groups.begin(), std::move(group));
}

int runRender(RenderOptions& options, const CLI::App& command) {
  const bool widthGiven = command.count("--width") > 0;            // SVG output keeps the input's size unless asked
  const bool backgroundGiven = command.count("--background") > 0;  // SVG output gets a background only when asked
  std::string extension = extensionOf(options.output);
  if (extension != ".png" && extension != ".svg")
    throw InputError(options.output, "unknown output format '" + extension + "' (use .png or .svg)");
  std::optional<Color> background = parseBackground(options.background);
  checkPngWidth(options.width, "--width");

  SvgDocument document = readDocument(options.input);
  checkOutputsBeforeTheRun({{"-o", options.output}}, {options.input});
  if (document.shapes.empty()) {
    // An empty picture is almost always a mistake (wrong file, everything hidden); say why.
    std::string reason = document.warnings.empty() ? "" : " (first skipped: " + document.warnings.front().message + ")";
    throw InputError(options.input, "no usable shape to draw" + reason);
  }
  Drawing drawing = drawingFromDocument(document);
  OutputBatch outputs;
  if (extension == ".png") {
    writePngFile(drawing, options.output, PngOptions{.width = options.width, .background = background});
  } else {
    // Keep the input's own size unless a width was asked for; the height follows the viewBox.
    if (widthGiven && !drawing.viewBox.empty() && drawing.viewBox.width() > 0) {
      drawing.width = options.width;
      drawing.height = options.width * drawing.viewBox.height() / drawing.viewBox.width();
      drawing.widthText.clear();  // the asked width replaces the input's, units and all
      drawing.heightText.clear();
    }
    if (background && backgroundGiven) addBackground(drawing, *background);
    writeSvgFile(drawing, options.output);
  }
  outputs.commit();
  return 0;
}

void declareRenderOptions(CLI::App& command, RenderOptions& options) {
  command.add_option("file", options.input, "Input file (.svg or .path)")->required()->type_name("FILE");
  command.add_option("-o,--output", options.output,
                     "Output file; the extension picks the format: .png (anti-aliased raster) or .svg")
      ->required()
      ->type_name("OUT");
  command.add_option("--width", options.width,
                     "PNG width in pixels, 1 to 16384; the height follows the drawing's aspect ratio "
                     "(default: 1000). For .svg output it sets the width attribute (default: the input's)")
      ->type_name("N");
  command.add_option("--background", options.background,
                     "Background colour: #rrggbb, #rgb, a name (white, black, gray, red, green, blue, "
                     "yellow) or none for transparent (default: white for PNG; SVG output gets a "
                     "background rectangle only when this is given)")
      ->type_name("COLOR|none");
}

const CommandRegistrar registrar{subcommand<RenderOptions>(
    "render",
    "Draw an SVG or .path file (any Pak input or output) as Pak understood it: PNG for a quick look, "
    "or SVG with every curve flattened and every hidden shape dropped.",
    declareRenderOptions, runRender)};

}  // namespace
}  // namespace pak::cli
