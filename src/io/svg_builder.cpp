// Pak's SVG markup: number and colour formatting, path data, and the builder that writes
// groups and shapes. Moved out of svg_writer.cpp so the animated SVG writer shares it.
#include "io/svg_builder.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "pak/error.hpp"
#include "pak/geom/bezier_fit.hpp"

namespace pak::svg_builder {
namespace {

// Opacities with three decimals are finer than 8-bit colour; clamp to SVG's [0, 1].
std::string formatOpacity(double opacity) { return formatNumber(std::clamp(opacity, 0.0, 1.0), 3); }

// The values of the id attributes in copied markup, in order (` id="…"` or `id='…'`, with
// any space around the `=`; `data-id` and `inkscape:id` are other attributes).
std::vector<std::string> idsIn(const std::string& markup) {
  std::vector<std::string> ids;
  for (std::size_t at = markup.find("id"); at != std::string::npos; at = markup.find("id", at + 2)) {
    if (at == 0 || !std::isspace(static_cast<unsigned char>(markup[at - 1]))) continue;
    std::size_t i = at + 2;
    while (i < markup.size() && std::isspace(static_cast<unsigned char>(markup[i]))) ++i;
    if (i >= markup.size() || markup[i] != '=') continue;
    ++i;
    while (i < markup.size() && std::isspace(static_cast<unsigned char>(markup[i]))) ++i;
    if (i >= markup.size() || (markup[i] != '"' && markup[i] != '\'')) continue;
    const std::size_t end = markup.find(markup[i], i + 1);
    if (end == std::string::npos) break;
    ids.push_back(markup.substr(i + 1, end - i - 1));
  }
  return ids;
}

}  // namespace

// Escapes text for a double-quoted XML attribute. Characters XML 1.0 forbids (most control
// characters) are dropped, because no escape makes them legal.
std::string escapeAttribute(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      case '\t': out += "&#9;"; break;
      case '\n': out += "&#10;"; break;
      case '\r': out += "&#13;"; break;
      default:
        if (static_cast<unsigned char>(c) >= 0x20 && c != 0x7f) out += c;
    }
  }
  return out;
}

// XML names: a letter, '_' or ':' then letters, digits, '.', '-', '_', ':'. Attribute names
// come from code, not from users, so an invalid one is a programmer mistake; we drop it rather
// than write a file no program can open.
bool isXmlName(const std::string& name) {
  if (name.empty()) return false;
  auto isStart = [](unsigned char c) { return std::isalpha(c) || c == '_' || c == ':'; };
  auto isRest = [&](unsigned char c) { return isStart(c) || std::isdigit(c) || c == '-' || c == '.'; };
  if (!isStart(static_cast<unsigned char>(name[0]))) return false;
  return std::all_of(name.begin() + 1, name.end(), [&](char c) { return isRest(static_cast<unsigned char>(c)); });
}

// Fixed-point with `precision` decimals, trailing zeros trimmed, "-0" written as "0".
std::string formatNumber(double value, int precision) {
  if (!std::isfinite(value)) throw InputError("", "cannot write a non-finite coordinate to SVG");
  std::array<char, 64> buffer{};
  auto [end, error] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value,
                                    std::chars_format::fixed, precision);
  if (error != std::errc()) {
    // Only astronomically large values overflow 64 characters; fall back to exponent form.
    std::snprintf(buffer.data(), buffer.size(), "%.*g", precision + 6, value);
    return buffer.data();
  }
  std::string text(buffer.data(), end);
  if (text.find('.') != std::string::npos) {
    while (text.back() == '0') text.pop_back();
    if (text.back() == '.') text.pop_back();
  }
  if (text == "-0") text = "0";
  return text;
}

std::string dashList(const std::vector<double>& dashes, int precision) {
  std::string text;
  for (double length : dashes) {
    if (!text.empty()) text += ' ';
    text += formatNumber(length, precision);
  }
  return text;
}

std::string hexColor(const Color& color) {
  std::array<char, 8> buffer{};
  std::snprintf(buffer.data(), buffer.size(), "#%02x%02x%02x", color.r, color.g, color.b);
  return buffer.data();
}

std::string pathData(const Shape& shape, int precision, double curveTolerance, SvgPathStats* stats) {
  // The deviation is measured on the chain flattened this finely (about its error).
  constexpr double kDeviationPrecision = 0.05;  // × curveTolerance
  std::string d;
  const std::size_t pointsBefore = stats ? stats->points : 0;
  auto put = [&](Vec2 p) {  // appends "x,y"
    if (stats) ++stats->points;
    d += formatNumber(p.x, precision);
    d += ',';
    d += formatNumber(p.y, precision);
  };
  for (const Subpath& subpath : shape.subpaths) {
    if (subpath.points.empty()) continue;
    if (!d.empty()) d += ' ';
    std::vector<CubicBezier> curves;
    if (curveTolerance > 0.0 && subpath.points.size() >= 3)
      curves = subpath.closed ? fitCubicBeziersClosed(subpath.points, curveTolerance)
                              : fitCubicBeziers(subpath.points, curveTolerance);
    // Curves that hold more points than the polygon (a container flattened coarser than the
    // tolerance, whose chords no curve follows) are not worth it: the polygon is exact.
    if (!curves.empty() && 3 * curves.size() + 1 < subpath.points.size() + (subpath.closed ? 1 : 0)) {
      d += 'M';
      put(curves.front()[0]);
      for (const CubicBezier& c : curves) {
        d += " C";
        put(c[1]);
        d += ' ';
        put(c[2]);
        d += ' ';
        put(c[3]);
      }
      if (stats)
        stats->largestDeviation = std::max(stats->largestDeviation, fitDeviation(subpath.points, subpath.closed, curves,
                                                                                 kDeviationPrecision * curveTolerance));
    } else {
      for (std::size_t i = 0; i < subpath.points.size(); ++i) {
        d += i == 0 ? "M" : (i == 1 ? " L" : " ");
        put(subpath.points[i]);
      }
    }
    if (subpath.points.size() == 1 && !subpath.closed) d += " h0";  // a dot: drawn by round or square caps
    if (subpath.closed) d += " Z";
  }
  if (stats && shape.drawnPoints > 0) {
    stats->drawnPoints += static_cast<std::size_t>(shape.drawnPoints);
    stats->pointsOfDrawnShapes += stats->points - pointsBefore;
  }
  return d;
}

// The drawing's box, or the bounds of what it draws when the box was left empty.
Box drawingBox(const Drawing& drawing) {
  if (!drawing.viewBox.empty()) return drawing.viewBox;
  Box box;
  auto addGroup = [&](const DrawingGroup& group, auto& self) -> void {
    for (const Shape& shape : group.shapes)
      for (const Subpath& subpath : shape.subpaths)
        for (Vec2 p : subpath.points) box.add(p);
    for (const DrawingGroup& child : group.children) self(child, self);
  };
  for (const DrawingGroup& group : drawing.groups) addGroup(group, addGroup);
  if (box.empty()) return Box{{0.0, 0.0}, {1.0, 1.0}};
  return box;
}

std::string SvgBuilder::uniqueId(const std::string& wanted) {
  std::string id = wanted;
  for (int n = 2; takenIds_.count(id); ++n) id = wanted + "-" + std::to_string(n);
  takenIds_.insert(id);
  return id;
}

void SvgBuilder::writeGroup(const DrawingGroup& group, int depth) {
  if (group.markup && group.markupReplacesGroup) {
    if (group.markup->empty()) return;
    // As the input wrote it; a prefix the root binds to another URI is bound again around it.
    indent(depth);
    const std::size_t start = out_.size();
    out_ += "<g";
    declareNamespaces(group.markup->namespaces, false);
    const bool wrapped = out_.size() > start + 2;
    if (wrapped) out_ += ">";
    else out_.resize(start);
    out_ += group.markup->content;
    if (wrapped) out_ += "</g>";
    out_ += '\n';
    return;
  }
  std::string clipId;
  if (group.clip) {
    // A rectangle clip path just before the group that uses it.
    clipId = uniqueId("pak-clip-" + std::to_string(++clipCount_));
    const Box& c = *group.clip;
    indent(depth);
    out_ += "<clipPath";
    attribute("id", clipId);
    out_ += "><rect";
    attribute("x", formatNumber(c.min.x, precision_));
    attribute("y", formatNumber(c.min.y, precision_));
    attribute("width", formatNumber(c.width(), precision_));
    attribute("height", formatNumber(c.height(), precision_));
    out_ += "/></clipPath>\n";
  }
  indent(depth);
  out_ += "<g";
  if (!clipId.empty()) attribute("clip-path", "url(#" + clipId + ")");
  if (!group.id.empty()) attribute("id", uniqueId(group.id + idSuffix));
  if (!group.cssClass.empty()) attribute("class", group.cssClass);
  if (depth == 1 && !group.id.empty()) {
    // Top-level groups open as layers in Inkscape, named like the reader expects.
    attribute("inkscape:groupmode", "layer");
    attribute("inkscape:label", group.id);
  }
  for (const auto& [name, value] : group.attributes)
    if (isXmlName(name)) attribute(name, value);
  if (group.markup) declareNamespaces(group.markup->namespaces, false);
  const bool copied = group.markup && !group.markup->empty();
  if (!copied && group.shapes.empty() && group.children.empty()) {
    out_ += "/>\n";
    return;
  }
  out_ += ">\n";
  if (copied) {
    out_ += group.markup->content;  // as the input wrote it: never re-formatted
    out_ += '\n';
  } else {
    for (const DrawnShape& shape : group.shapes) writeShape(shape, depth + 1);
  }
  for (const DrawingGroup& child : group.children) writeGroup(child, depth + 1);
  indent(depth);
  out_ += "</g>\n";
}

void SvgBuilder::writeShape(const DrawnShape& shape, int depth) {
  std::string d = pathData(shape, precision_, curveTolerance_, stats);
  if (d.empty()) return;  // nothing to draw; an empty d is an SVG error
  indent(depth);
  out_ += "<path";
  if (!shape.id.empty()) attribute("id", uniqueId(shape.id + idSuffix));
  attribute("d", d);
  if (shape.fill) {
    attribute("fill", hexColor(*shape.fill));
    if (shape.fill->alpha < 1.0) attribute("fill-opacity", formatOpacity(shape.fill->alpha));
    if (shape.fillRule == FillRule::EvenOdd) attribute("fill-rule", "evenodd");
  } else {
    attribute("fill", "none");
  }
  if (shape.stroke) {
    attribute("stroke", hexColor(*shape.stroke));
    if (shape.stroke->alpha < 1.0) attribute("stroke-opacity", formatOpacity(shape.stroke->alpha));
    attribute("stroke-width", formatNumber(shape.strokeWidth, precision_));
    // Caps, joins and miter limit when they are not SVG's defaults (butt, miter, 4).
    if (shape.lineCap != StrokeCap::Butt)
      attribute("stroke-linecap", shape.lineCap == StrokeCap::Round ? "round" : "square");
    if (shape.lineJoin != StrokeJoin::Miter)
      attribute("stroke-linejoin", shape.lineJoin == StrokeJoin::Round ? "round" : "bevel");
    else if (shape.miterLimit != 4.0)
      attribute("stroke-miterlimit", formatNumber(shape.miterLimit, precision_));
    if (!shape.dashArray.empty()) {
      attribute("stroke-dasharray", dashList(shape.dashArray, precision_));
      if (shape.dashOffset != 0.0) attribute("stroke-dashoffset", formatNumber(shape.dashOffset, precision_));
    }
  }
  if (shape.opacity < 1.0) attribute("opacity", formatOpacity(shape.opacity));
  std::string children = shapeChildren ? shapeChildren(shape, d, depth + 1) : std::string();
  if (children.empty()) {
    out_ += "/>\n";
    return;
  }
  out_ += ">\n";
  out_ += children;
  indent(depth);
  out_ += "</path>\n";
}

// xmlns:prefix declarations for copied markup: on the root (`root`) for the prefixes the
// root does not bind otherwise, and on the copy's own element for those the root binds to
// another URI (XML scoping then gives the copy its own).
void SvgBuilder::declareNamespaces(const std::vector<std::pair<std::string, std::string>>& namespaces, bool root) {
  for (const auto& [prefix, uri] : namespaces) {
    if (!isXmlName(prefix) || prefix.find(':') != std::string::npos) continue;
    auto bound = rootNamespaces_.find(prefix);
    const bool conflicts = bound != rootNamespaces_.end() && bound->second != uri;
    if (root && bound == rootNamespaces_.end()) {
      rootNamespaces_[prefix] = uri;
      attribute("xmlns:" + prefix, uri);
    } else if (!root && conflicts) {
      attribute("xmlns:" + prefix, uri);
    }
  }
}

void SvgBuilder::attribute(const std::string& name, const std::string& value) {
  out_ += ' ';
  out_ += name;
  out_ += "=\"";
  out_ += escapeAttribute(value);
  out_ += '"';
}

void SvgBuilder::beginDocument(const std::vector<const Drawing*>& drawings) {
  const Drawing& first = *drawings.front();
  Box box = drawingBox(first);
  // A degenerate box (one point, a horizontal line) would make an invalid viewBox.
  double boxWidth = box.width() > 0.0 ? box.width() : 1.0;
  double boxHeight = box.height() > 0.0 ? box.height() : 1.0;
  double width = first.width > 0.0 ? first.width : boxWidth;
  double height = first.height > 0.0 ? first.height : boxHeight;

  out_ += "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n";
  out_ += "<svg xmlns=\"http://www.w3.org/2000/svg\"";
  out_ += " xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\"";
  rootNamespaces_["inkscape"] = "http://www.inkscape.org/namespaces/inkscape";
  // Copied markup (a scene's fixed and other layers): its namespaces on the root, its
  // definitions in <defs>.
  std::vector<const RawMarkup*> markups;
  auto collect = [&](const DrawingGroup& group, auto& self) -> void {
    if (group.markup && !group.markup->empty()) markups.push_back(&*group.markup);
    for (const DrawingGroup& child : group.children) self(child, self);
  };
  for (const Drawing* drawing : drawings)
    for (const DrawingGroup& group : drawing->groups) collect(group, collect);
  for (const RawMarkup* markup : markups) declareNamespaces(markup->namespaces, true);
  out_ += " version=\"1.1\"";
  if (!first.widthText.empty() || !first.heightText.empty()) {
    if (!first.widthText.empty()) attribute("width", first.widthText);
    if (!first.heightText.empty()) attribute("height", first.heightText);
  } else {
    attribute("width", formatNumber(width, precision_));
    attribute("height", formatNumber(height, precision_));
  }
  attribute("viewBox", formatNumber(box.min.x, precision_) + " " + formatNumber(box.min.y, precision_) + " " +
                           formatNumber(boxWidth, precision_) + " " + formatNumber(boxHeight, precision_));
  out_ += ">\n";
  // Copied markup keeps its ids: Pak's own give way (uniqueId). A definition is written once,
  // and not at all when a copy holds it already (the same file's element, copied twice).
  for (const RawMarkup* markup : markups)
    for (std::string& id : idsIn(markup->content)) takenIds_.insert(std::move(id));
  for (const RawMarkup* markup : markups) {
    std::string defs;
    for (const std::string& definition : markup->definitions) {
      const std::vector<std::string> ids = idsIn(definition);
      if (ids.empty() || takenIds_.count(ids.front())) continue;
      takenIds_.insert(ids.begin(), ids.end());
      defs += (defs.empty() ? "" : "\n") + definition;
    }
    if (defs.empty()) continue;
    out_ += "  <defs";
    declareNamespaces(markup->namespaces, false);
    out_ += ">\n";
    out_ += defs;
    out_ += "\n  </defs>\n";
  }
}

}  // namespace pak::svg_builder
