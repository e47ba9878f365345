// `pak inspect FILE…`: shows what Pak sees in input files, so artists can check their layers,
// holes and colours before packing. One JSON report per file is the single source of truth;
// the text output is printed from it, so both always say the same thing.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "command.hpp"
#include "pak/error.hpp"
#include "pak/geom/art.hpp"
#include "pak/geom/scene.hpp"
#include "pak/io/message_text.hpp"
#include "pak/io/scene_loader.hpp"
#include "pak/io/svg_reader.hpp"

namespace pak::cli {
namespace {

using nlohmann::json;

struct InspectOptions {
  std::vector<std::string> files;
  bool json = false;
};

// ---- building the report ----------------------------------------------------------------

// Nine significant digits: enough for any file's precision, without the last-bit noise of
// computed areas (412345.60000000003) in the JSON.
double tidy(double value) {
  if (!std::isfinite(value) || value == 0.0) return value == 0.0 ? 0.0 : value;
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.9g", value);
  return std::strtod(buffer, nullptr);
}

json point(Vec2 p) { return json::array({tidy(p.x), tidy(p.y)}); }

json boxJson(const Box& box) {
  if (box.empty()) return nullptr;
  return {{"min", point(box.min)}, {"max", point(box.max)}, {"width", tidy(box.width())}, {"height", tidy(box.height())}};
}

json colorJson(const std::optional<Color>& color) {
  if (!color) return nullptr;
  char hex[8];
  std::snprintf(hex, sizeof hex, "#%02x%02x%02x", color->r, color->g, color->b);
  return {{"hex", hex}, {"alpha", tidy(color->alpha)}};
}

int holeCount(const Region& region) {
  int holes = 0;
  for (const Polygon& polygon : region) holes += static_cast<int>(polygon.holes.size());
  return holes;
}

json shapeJson(const SvgShape& shape) {
  int closed = 0, points = 0;
  for (const Subpath& subpath : shape.subpaths) {
    closed += subpath.closed ? 1 : 0;
    points += static_cast<int>(subpath.points.size());
  }
  // United once: the painted region reuses it.
  const Region filled = shape.fill ? filledRegion(shape) : Region{};
  json out = {
      {"id", shape.id},
      {"tag", shape.tag},
      {"layer", shape.layer},
      {"fill", colorJson(shape.fill)},
      {"fillRule", shape.fillRule == FillRule::EvenOdd ? "evenodd" : "nonzero"},
      {"stroke", colorJson(shape.stroke)},
      {"strokeWidth", shape.stroke ? json(tidy(shape.strokeWidth)) : json(nullptr)},
      {"strokeDashArray", json::array()},
      {"opacity", tidy(shape.opacity)},
      {"subpaths", shape.subpaths.size()},
      {"closedSubpaths", closed},
      {"points", points},
      {"filledArea", tidy(area(filled))},
      {"holes", holeCount(filled)},
      {"paintedArea", tidy(area(paintedRegion(shape, filled)))},
      {"bounds", boxJson(bounds(shape))},
  };
  if (shape.stroke)
    for (double length : shape.dashArray) out["strokeDashArray"].push_back(tidy(length));
  return out;
}

json polylineJson(const Polyline& line) {
  return {{"points", line.size()}, {"length", tidy(polylineLength(line))}, {"bounds", boxJson(bounds(line))}};
}

json sceneJson(const LoadedScene& loaded) {
  const Scene& scene = loaded.scene;
  json containers = json::array();
  for (const Polygon& polygon : scene.container)
    containers.push_back({{"area", tidy(area(polygon))},
                          {"holes", polygon.holes.size()},
                          {"points", polygon.outer.size()},
                          {"bounds", boxJson(bounds(polygon))}});
  json containerShapes = json::array();
  for (const ContainerShape& shape : loaded.layout.containerShapes) containerShapes.push_back(shapeJson(shape.shape));
  json fixed = json::array();
  for (const SvgShape& shape : loaded.layout.fixedShapes) fixed.push_back(shapeJson(shape));
  json guides = json::array();
  for (const Polyline& guide : scene.guides) guides.push_back(polylineJson(guide));
  json spines = json::array();
  for (const Polyline& spine : scene.spines) spines.push_back(polylineJson(spine));
  return {{"containerArea", tidy(area(scene.container))},
          {"containers", containers},
          {"containerShapes", containerShapes},
          {"fixed", fixed},
          {"guides", guides},
          {"spines", spines}};
}

json elementJson(const LoadedElement& loaded) {
  const ElementArt& element = loaded.element;
  json paths = json::array();
  for (const SvgShape& shape : loaded.shapes) paths.push_back(shapeJson(shape));
  json spine = nullptr;
  if (element.spine) spine = json::array({point((*element.spine)[0]), point((*element.spine)[1])});
  return {{"name", element.name},
          {"source", element.source},
          {"paths", paths},
          {"area", tidy(area(element.outline))},
          {"outlinePolygons", element.outline.size()},
          {"holes", holeCount(element.outline)},
          {"bounds", boxJson(bounds(element.outline))},
          {"spine", spine}};
}

bool hasLayer(const SvgDocument& document, const std::string& name) {
  for (const std::string& layer : document.layers)
    if (layer == name) return true;
  return false;
}

// Would a user mean this file as a container? Yes for a container layer (checked before),
// for files with other scene layers, for .path files (their role is decided by use) and for
// a lone shape; an element drawing of several shapes is not shown as a scene.
bool looksLikeScene(const SvgDocument& document) {
  for (const char* layer : {"fixed", "guides", "spines", "holes"})
    if (hasLayer(document, layer)) return true;
  if (document.file.size() >= 5 && document.file.compare(document.file.size() - 5, 5, ".path") == 0) return true;
  return document.shapes.size() == 1;
}

// A file with a container layer is a scene. Any other file is shown as an element, and also
// as a scene when Pak would accept it as a container and it looks meant as one.
json inspectFile(const std::string& file) {
  SvgDocument document = readDocument(file);
  if (document.shapes.empty()) {
    // Say why nothing is left (text, hidden layers …) rather than a bare "no shapes".
    std::string reason = document.warnings.empty() ? "" : " (first skipped: " + document.warnings.front().message + ")";
    throw InputError(file, "no usable shape" + reason);
  }
  std::optional<LoadedScene> scene;
  std::vector<LoadedElement> elements;
  if (hasLayer(document, "container")) {
    scene = sceneFromDocument(document);  // a broken container layer is an error, not a hint
  } else {
    std::optional<InputError> elementError;
    try {
      elements = elementsFromDocument(document);
    } catch (const InputError& error) {
      elementError = error;
    }
    if (looksLikeScene(document) || elements.empty()) {
      try {
        scene = sceneFromDocument(document);
      } catch (const InputError&) {
        // Not usable as a container; the element view (or its error) says what the file is.
      }
    }
    if (elements.empty() && !scene) {
      if (elementError) throw *elementError;
      throw InputError(file, "no usable shape: neither an element nor a container");
    }
  }

  // Warnings may be reported by both the reader and the scene; show each once.
  json warnings = json::array();
  std::set<std::pair<std::string, std::string>> seen;
  auto addWarnings = [&](const std::vector<Warning>& list) {
    for (const Warning& warning : list)
      if (seen.insert({warning.where, warning.message}).second)
        warnings.push_back({{"where", warning.where}, {"message", warning.message}});
  };
  addWarnings(document.warnings);
  if (scene) addWarnings(scene->warnings);
  for (const LoadedElement& element : elements) addWarnings(element.warnings);

  json elementList = json::array();
  for (const LoadedElement& element : elements) elementList.push_back(elementJson(element));
  const Box& box = document.viewBox;
  return {{"file", file},
          {"width", tidy(document.width)},
          {"height", tidy(document.height)},
          {"viewBox", box.empty() ? json(nullptr)
                                  : json::array({tidy(box.min.x), tidy(box.min.y), tidy(box.width()),
                                                 tidy(box.height())})},
          {"layers", document.layers},
          {"shapes", document.shapes.size()},
          {"scene", scene ? sceneJson(*scene) : json(nullptr)},
          {"elements", elementList},
          {"warnings", warnings}};
}

// ---- printing the report as text ---------------------------------------------------------

// About six significant digits, never in exponent form, trailing zeros trimmed.
std::string number(const json& value) {
  double v = value.get<double>();
  if (v == 0.0) return "0";
  int magnitude = static_cast<int>(std::floor(std::log10(std::fabs(v))));
  int decimals = std::clamp(5 - magnitude, 0, 6);
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
  std::string text = buffer;
  if (text.find('.') != std::string::npos) {
    while (text.back() == '0') text.pop_back();
    if (text.back() == '.') text.pop_back();
  }
  return text == "-0" ? "0" : text;
}

std::string plural(std::size_t count, const std::string& word) {
  return std::to_string(count) + " " + word + (count == 1 ? "" : "s");
}

std::string boxText(const json& box) {
  if (box.is_null()) return "empty";
  return "(" + number(box["min"][0]) + ", " + number(box["min"][1]) + ") to (" + number(box["max"][0]) + ", " +
         number(box["max"][1]) + "), " + number(box["width"]) + " x " + number(box["height"]);
}

std::string colorText(const json& color) {
  std::string text = color["hex"].get<std::string>();
  if (color["alpha"].get<double>() < 1.0) text += " at " + number(color["alpha"]) + " opacity";
  return text;
}

std::string quotedName(const json& shape) {
  std::string id = shape["id"].get<std::string>();
  std::string tag = shape["tag"].get<std::string>();
  if (tag.empty()) tag = "shape";
  return id.empty() ? tag : tag + " \"" + id + "\"";
}

void printShape(std::ostream& out, const json& shape, const std::string& indent) {
  out << indent << quotedName(shape) << ": ";
  std::vector<std::string> parts;
  if (!shape["fill"].is_null()) {
    std::string fill = "fill " + colorText(shape["fill"]);
    if (shape["fillRule"] == "evenodd") fill += " (evenodd)";
    parts.push_back(fill);
  } else {
    parts.push_back("no fill");
  }
  if (!shape["stroke"].is_null()) {
    std::string stroke = "stroke " + colorText(shape["stroke"]) + " width " + number(shape["strokeWidth"]);
    if (!shape["strokeDashArray"].empty()) {
      stroke += " dashed";
      for (const json& length : shape["strokeDashArray"]) stroke += " " + number(length);
    }
    parts.push_back(stroke);
  }
  if (shape["opacity"].get<double>() < 1.0) parts.push_back("opacity " + number(shape["opacity"]));
  std::size_t subpaths = shape["subpaths"].get<std::size_t>();
  std::size_t open = subpaths - shape["closedSubpaths"].get<std::size_t>();
  std::string sub = plural(subpaths, "subpath");
  if (open > 0) sub += " (" + std::to_string(open) + " open)";
  parts.push_back(sub);
  if (!shape["fill"].is_null()) {
    std::string filled = "area " + number(shape["filledArea"]);
    if (shape["holes"].get<int>() > 0) filled += " with " + plural(shape["holes"].get<std::size_t>(), "hole");
    parts.push_back(filled);
  } else {
    parts.push_back("painted area " + number(shape["paintedArea"]));
  }
  for (std::size_t i = 0; i < parts.size(); ++i) out << (i ? ", " : "") << parts[i];
  out << "\n";
}

void printLines(std::ostream& out, const json& lines, const std::string& title, const std::string& indent) {
  out << indent << title << ": " << (lines.empty() ? "none" : std::to_string(lines.size())) << "\n";
  for (std::size_t i = 0; i < lines.size(); ++i)
    out << indent << "  #" << i + 1 << ": " << plural(lines[i]["points"].get<std::size_t>(), "point")
        << ", length " << number(lines[i]["length"]) << ", bounds " << boxText(lines[i]["bounds"]) << "\n";
}

void printScene(std::ostream& out, const json& scene, bool alsoElement) {
  out << "  scene" << (alsoElement ? " (if used as a container)" : "") << ":\n";
  const json& containers = scene["containers"];
  out << "    containers: " << containers.size() << ", total area " << number(scene["containerArea"]) << "\n";
  for (std::size_t i = 0; i < containers.size(); ++i)
    out << "      #" << i + 1 << ": area " << number(containers[i]["area"]) << ", "
        << plural(containers[i]["holes"].get<std::size_t>(), "hole") << ", bounds "
        << boxText(containers[i]["bounds"]) << "\n";
  out << "    drawn by " << plural(scene["containerShapes"].size(), "shape") << ":\n";
  for (const json& shape : scene["containerShapes"]) printShape(out, shape, "      ");
  out << "    fixed elements: " << (scene["fixed"].empty() ? "none" : std::to_string(scene["fixed"].size())) << "\n";
  for (const json& shape : scene["fixed"]) printShape(out, shape, "      ");
  printLines(out, scene["guides"], "guides", "    ");
  printLines(out, scene["spines"], "spines", "    ");
}

void printElement(std::ostream& out, const json& element) {
  out << "  element \"" << element["name"].get<std::string>() << "\": "
      << plural(element["paths"].size(), "path") << ", painted area " << number(element["area"]) << ", outline "
      << plural(element["outlinePolygons"].get<std::size_t>(), "polygon");
  if (element["holes"].get<int>() > 0) out << " with " << plural(element["holes"].get<std::size_t>(), "hole");
  out << ", bounds " << boxText(element["bounds"]) << "\n";
  for (const json& shape : element["paths"]) printShape(out, shape, "    ");
  if (!element["spine"].is_null())
    out << "    spine: (" << number(element["spine"][0][0]) << ", " << number(element["spine"][0][1]) << ") to ("
        << number(element["spine"][1][0]) << ", " << number(element["spine"][1][1]) << ")\n";
}

void printReport(std::ostream& out, const json& report) {
  out << report["file"].get<std::string>() << "\n";
  out << "  document: " << number(report["width"]) << " x " << number(report["height"]) << " user units";
  if (!report["viewBox"].is_null())
    out << ", viewBox " << number(report["viewBox"][0]) << " " << number(report["viewBox"][1]) << " "
        << number(report["viewBox"][2]) << " " << number(report["viewBox"][3]);
  out << ", " << plural(report["shapes"].get<std::size_t>(), "shape") << "\n";
  out << "  layers: ";
  if (report["layers"].empty()) out << "none";
  for (std::size_t i = 0; i < report["layers"].size(); ++i)
    out << (i ? ", " : "") << report["layers"][i].get<std::string>();
  out << "\n";
  bool hasElements = !report["elements"].empty();
  if (!report["scene"].is_null()) printScene(out, report["scene"], hasElements);
  for (const json& element : report["elements"]) printElement(out, element);
  out << "  warnings: " << (report["warnings"].empty() ? "none" : std::to_string(report["warnings"].size())) << "\n";
  for (const json& warning : report["warnings"]) {
    std::string where = warning["where"].get<std::string>();
    out << "    " << oneLine((where.empty() ? "" : where + ": ") + warning["message"].get<std::string>()) << "\n";
  }
}

int runInspect(InspectOptions& options, const CLI::App&) {
  // Inspect every file before printing anything: a bad file gives one error line and no
  // half-printed report.
  json reports = json::array();
  for (const std::string& file : options.files) reports.push_back(inspectFile(file));
  std::ostringstream out;
  if (options.json) {
    // The reader makes names UTF-8 (U+FFFD for other bytes); `replace` keeps that promise for
    // file names given on the command line too, where nlohmann would throw.
    out << json{{"files", reports}}.dump(2, ' ', false, json::error_handler_t::replace) << "\n";
  } else {
    for (std::size_t i = 0; i < reports.size(); ++i) {
      if (i) out << "\n";
      printReport(out, reports[i]);
    }
  }
  std::cout << out.str() << std::flush;
  return 0;
}

void declareInspectOptions(CLI::App& command, InspectOptions& options) {
  command.add_option("files", options.files, "SVG (.svg) or legacy RepulsionPak (.path) files to inspect")
      ->required()
      ->type_name("FILE");
  command.add_flag("--json", options.json,
                   "Print the report as JSON ({\"files\": [...]}, one object per file) instead of text "
                   "(default: text)");
}

const CommandRegistrar registrar{subcommand<InspectOptions>(
    "inspect",
    "Show what Pak sees in SVG or .path files: document size and viewBox, layers, containers "
    "(area, holes, bounding box), fixed elements, guides, spines, element art (paths, colours, "
    "areas) and warnings about anything skipped. A file with a `container` layer is shown as a "
    "scene; other files as elements, and also as a scene when they could serve as a container "
    "(a lone closed shape). Areas and coordinates are in the file's own user units.",
    declareInspectOptions, runInspect)};

}  // namespace
}  // namespace pak::cli
