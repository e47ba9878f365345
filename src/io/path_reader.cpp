// Reads the original RepulsionPak `.path` text format (grammar: shared data README):
//
//   R                                         number of regions
//   foreground_color_rgb <region> r,g,b …     stroke colour per path (-1,-1,-1: none)
//   background_color_rgb <region> r,g,b …     fill colour per path
//   <region> <isClosed> <pathType> x0 y0 x1 y1 …
//
// The paths become shapes of an SvgDocument so that the rest of Pak treats both formats
// alike; the path type becomes the layer.
#include "pak/io/path_reader.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "pak/error.hpp"
#include "pak/io/text_file.hpp"

namespace pak {
namespace {

constexpr double kAbsurdCoordinate = 1e9;
// The original program drew its containers on a 500 × 500 artboard.
constexpr double kOriginalArtboard = 500.0;

enum class PathType { Boundary = 0, Focal = 2, Field = 3, Skeleton = 6, Hole = 7 };

std::optional<std::string> layerFor(int type) {
  switch (type) {
    case static_cast<int>(PathType::Boundary): return std::string();
    case static_cast<int>(PathType::Focal): return std::string("fixed");
    case static_cast<int>(PathType::Hole): return std::string("holes");
    case static_cast<int>(PathType::Skeleton): return std::string("spines");
    case static_cast<int>(PathType::Field): return std::string("guides");
    default: return std::nullopt;
  }
}

std::vector<std::string_view> splitWhitespace(std::string_view line) {
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    std::size_t start = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
  }
  return tokens;
}

// One line being read: every error names the file and the line.
class LineReader {
 public:
  LineReader(const std::string& file, int lineNumber) : file_(file), lineNumber_(lineNumber) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(file_ + ":" + std::to_string(lineNumber_), what);
  }

  double number(std::string_view token) const {
    double value = 0.0;
    const char* first = token.data();
    const char* last = token.data() + token.size();
    if (!token.empty() && *first == '+') ++first;  // from_chars does not take a leading '+'
    auto [end, error] = std::from_chars(first, last, value);
    if (error != std::errc() || end != last || first == last)
      fail("expected a number, got \"" + std::string(token) + "\"");
    if (!std::isfinite(value)) fail("\"" + std::string(token) + "\" is not a finite number");
    if (std::abs(value) > kAbsurdCoordinate)
      fail("absurd coordinate " + std::string(token) + " (beyond ±1e9)");
    return value;
  }

  int integer(std::string_view token, const char* what) const {
    int value = 0;
    auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc() || end != token.data() + token.size() || token.empty())
      fail(std::string("expected ") + what + " (an integer), got \"" + std::string(token) + "\"");
    return value;
  }

  // "r,g,b" with -1,-1,-1 meaning none.
  std::optional<Color> color(std::string_view token) const {
    int channels[3] = {0, 0, 0};
    std::size_t start = 0;
    for (int c = 0; c < 3; ++c) {
      const std::size_t comma = c < 2 ? token.find(',', start) : token.size();
      if (comma == std::string_view::npos)
        fail("expected a colour r,g,b, got \"" + std::string(token) + "\"");
      channels[c] = integer(token.substr(start, comma - start), "a colour channel");
      start = comma + 1;
    }
    if (channels[0] == -1 && channels[1] == -1 && channels[2] == -1) return std::nullopt;
    for (int c : channels)
      if (c < 0 || c > 255) fail("colour channel out of 0..255 in \"" + std::string(token) + "\"");
    return Color{static_cast<std::uint8_t>(channels[0]), static_cast<std::uint8_t>(channels[1]),
                 static_cast<std::uint8_t>(channels[2]), 1.0};
  }

 private:
  const std::string& file_;
  int lineNumber_;
};

// Colours given per region, one per path of that region in path order.
struct RegionColours {
  std::vector<std::optional<Color>> foreground, background;
  bool hasForeground = false, hasBackground = false;
};

}  // namespace

SvgDocument readPathString(const std::string& text, const std::string& name) {
  SvgDocument document;
  document.file = name;

  std::istringstream in(text);
  std::string line;
  int lineNumber = 0;
  std::optional<int> regionCount;
  std::map<int, RegionColours> colours;
  std::map<int, int> pathsInRegion;
  struct PathRegion { int region; int indexInRegion; };
  std::vector<PathRegion> pathRegions;  // parallel to document.shapes

  while (std::getline(in, line)) {
    ++lineNumber;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::vector<std::string_view> tokens = splitWhitespace(line);
    if (tokens.empty()) continue;
    const LineReader reader(name, lineNumber);

    if (!regionCount) {
      if (tokens.size() != 1) reader.fail("expected the number of regions alone on the first line");
      regionCount = reader.integer(tokens[0], "the number of regions");
      if (*regionCount < 1) reader.fail("the number of regions must be at least 1");
      continue;
    }

    if (tokens[0] == "foreground_color_rgb" || tokens[0] == "background_color_rgb") {
      if (tokens.size() < 2) reader.fail("colour line without a region");
      const int region = reader.integer(tokens[1], "a region");
      if (region < 0 || region >= *regionCount)
        reader.fail("region " + std::to_string(region) + " out of range (the file declares " +
                    std::to_string(*regionCount) + ")");
      RegionColours& regionColours = colours[region];
      const bool foreground = tokens[0] == "foreground_color_rgb";
      auto& list = foreground ? regionColours.foreground : regionColours.background;
      (foreground ? regionColours.hasForeground : regionColours.hasBackground) = true;
      list.clear();
      for (std::size_t i = 2; i < tokens.size(); ++i) list.push_back(reader.color(tokens[i]));
      continue;
    }

    // A path line.
    if (tokens.size() < 3) reader.fail("expected <region> <isClosed> <pathType> x0 y0 …, got \"" + line + "\"");
    const int region = reader.integer(tokens[0], "a region");
    if (region < 0 || region >= *regionCount)
      reader.fail("region " + std::to_string(region) + " out of range (the file declares " +
                  std::to_string(*regionCount) + ")");
    const int closedFlag = reader.integer(tokens[1], "the isClosed flag");
    if (closedFlag != 0 && closedFlag != 1) reader.fail("isClosed must be 0 or 1, got " + std::string(tokens[1]));
    const int type = reader.integer(tokens[2], "the path type");
    if ((tokens.size() - 3) % 2 != 0) reader.fail("odd number of coordinates: a point lacks its y");

    Subpath subpath;
    for (std::size_t i = 3; i + 1 < tokens.size(); i += 2) {
      const Vec2 p{reader.number(tokens[i]), reader.number(tokens[i + 1])};
      if (subpath.points.empty() || !(subpath.points.back() == p)) subpath.points.push_back(p);
    }
    const int indexInRegion = pathsInRegion[region]++;
    const std::optional<std::string> layer = layerFor(type);
    if (!layer) {
      document.warnings.push_back({name + ":" + std::to_string(lineNumber),
                                   "path type " + std::to_string(type) + " is not used by Pak; skipped"});
      continue;
    }
    // Outlines (boundary, focal, hole) were always closed by the original program, whatever
    // the flag says: the snake's silhouette is stored open with its first point repeated.
    const bool outline = layer->empty() || *layer == "fixed" || *layer == "holes";
    subpath.closed = outline || closedFlag == 1;
    if (subpath.closed && subpath.points.size() > 1 && subpath.points.back() == subpath.points.front())
      subpath.points.pop_back();
    if (subpath.points.size() < (outline ? 3u : 2u)) {
      document.warnings.push_back({name + ":" + std::to_string(lineNumber),
                                   "path with too few points (" + std::to_string(subpath.points.size()) +
                                       "); skipped"});
      continue;
    }

    SvgShape shape;
    shape.drawnPoints = static_cast<int>(subpath.points.size());
    shape.subpaths.push_back(std::move(subpath));
    shape.tag = "path-file";
    shape.line = lineNumber;
    shape.id = "path" + std::to_string(document.shapes.size() + 1);
    shape.layer = *layer;
    document.shapes.push_back(std::move(shape));
    pathRegions.push_back({region, indexInRegion});
  }

  if (!regionCount) throw InputError(name, "empty file: expected the number of regions on the first line");
  if (document.shapes.empty()) throw InputError(name, "no paths in the file");

  // Paint: colour lines when given, else filled black like an SVG path without style.
  for (std::size_t i = 0; i < document.shapes.size(); ++i) {
    SvgShape& shape = document.shapes[i];
    const auto found = colours.find(pathRegions[i].region);
    const std::size_t index = static_cast<std::size_t>(pathRegions[i].indexInRegion);
    if (found == colours.end() || (!found->second.hasBackground && !found->second.hasForeground)) {
      shape.fill = Color{};
      continue;
    }
    const RegionColours& regionColours = found->second;
    if (index < regionColours.background.size()) shape.fill = regionColours.background[index];
    else if (!regionColours.hasBackground) shape.fill = std::nullopt;
    else shape.fill = Color{};
    if (index < regionColours.foreground.size()) shape.stroke = regionColours.foreground[index];
    if (!shape.fill && !shape.stroke) {
      // Both "none": the original still used the outline; keep it visible as a thin line.
      shape.stroke = Color{};
    }
  }

  // The original files list an element's details (eyes, belly) first and its silhouette
  // last, and drew the silhouette underneath: move it in front of the details so they show.
  std::vector<std::size_t> boundary;
  for (std::size_t i = 0; i < document.shapes.size(); ++i)
    if (document.shapes[i].layer.empty()) boundary.push_back(i);
  if (boundary.size() > 1)
    std::rotate(document.shapes.begin() + static_cast<std::ptrdiff_t>(boundary.front()),
                document.shapes.begin() + static_cast<std::ptrdiff_t>(boundary.back()),
                document.shapes.begin() + static_cast<std::ptrdiff_t>(boundary.back()) + 1);

  for (const SvgShape& shape : document.shapes)
    if (!shape.layer.empty() &&
        std::find(document.layers.begin(), document.layers.end(), shape.layer) == document.layers.end())
      document.layers.push_back(shape.layer);

  // The coordinate box: the original 500 × 500 artboard when everything lies on it.
  Box drawing = bounds(document.shapes);
  Box artboard;
  artboard.add(Vec2{0, 0});
  artboard.add(Vec2{kOriginalArtboard, kOriginalArtboard});
  document.viewBox = drawing;
  if (!drawing.empty() && drawing.min.x >= 0 && drawing.min.y >= 0 && drawing.max.x <= kOriginalArtboard &&
      drawing.max.y <= kOriginalArtboard)
    document.viewBox = artboard;
  document.width = document.viewBox.width();
  document.height = document.viewBox.height();
  return document;
}

SvgDocument readPathFile(const std::string& path) {
  return readPathString(readTextFile(path), path);
}

}  // namespace pak
