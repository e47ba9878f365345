// One SVG that plays an animation in a browser with SMIL <animate>. When all frames share one
// structure (Pak's packings do: the same elements, each with the same points, only moving),
// every shape is written once and its `d` is interpolated through the frames, which is small
// and smooth. Otherwise every frame is its own group, shown during its time slot. Viewers
// without SMIL (Inkscape) show the first frame.
#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>
#include <vector>

#include "io/animation_frames.hpp"
#include "io/svg_builder.hpp"
#include "pak/error.hpp"
#include "pak/io/animation_output.hpp"
#include "pak/io/atomic_file.hpp"

namespace pak {
namespace {

using svg_builder::formatNumber;
using svg_builder::SvgBuilder;

bool sameBox(const std::optional<Box>& a, const std::optional<Box>& b) {
  if (a.has_value() != b.has_value()) return false;
  return !a || (a->min == b->min && a->max == b->max);
}


// Same paint and the same point counts, so the two `d` strings (and dash lists) have the same
// commands and SMIL can interpolate between them.
bool sameShapeStructure(const DrawnShape& a, const DrawnShape& b) {
  if (a.subpaths.size() != b.subpaths.size() || a.fill != b.fill || a.stroke != b.stroke ||
      a.opacity != b.opacity || a.fillRule != b.fillRule || a.id != b.id || a.dashArray.size() != b.dashArray.size())
    return false;
  for (std::size_t i = 0; i < a.subpaths.size(); ++i)
    if (a.subpaths[i].points.size() != b.subpaths[i].points.size() || a.subpaths[i].closed != b.subpaths[i].closed)
      return false;
  return true;
}

bool sameGroupStructure(const DrawingGroup& a, const DrawingGroup& b) {
  if (a.id != b.id || a.cssClass != b.cssClass || a.attributes != b.attributes || !sameBox(a.clip, b.clip) ||
      a.markup != b.markup || a.markupReplacesGroup != b.markupReplacesGroup || a.shapes.size() != b.shapes.size() || a.children.size() != b.children.size())
    return false;
  for (std::size_t i = 0; i < a.shapes.size(); ++i)
    if (!sameShapeStructure(a.shapes[i], b.shapes[i])) return false;
  for (std::size_t i = 0; i < a.children.size(); ++i)
    if (!sameGroupStructure(a.children[i], b.children[i])) return false;
  return true;
}

bool sameStructure(const std::vector<Drawing>& frames) {
  const Drawing& first = frames.front();
  for (const Drawing& frame : frames) {
    if (frame.groups.size() != first.groups.size()) return false;
    for (std::size_t i = 0; i < frame.groups.size(); ++i)
      if (!sameGroupStructure(first.groups[i], frame.groups[i])) return false;
  }
  return true;
}

// Every shape of the drawing in the order the builder writes them.
void collectShapes(const DrawingGroup& group, std::vector<const DrawnShape*>& shapes) {
  for (const DrawnShape& shape : group.shapes) shapes.push_back(&shape);
  for (const DrawingGroup& child : group.children) collectShapes(child, shapes);
}
std::vector<const DrawnShape*> shapesOf(const Drawing& drawing) {
  std::vector<const DrawnShape*> shapes;
  for (const DrawingGroup& group : drawing.groups) collectShapes(group, shapes);
  return shapes;
}

// About 1/10000 of the view box: finer than any screen shows, and compact.
int precisionFor(const Drawing& first, const AnimationOutputOptions& options) {
  if (options.svgPrecision >= 0) return std::min(options.svgPrecision, 12);
  Box box = svg_builder::drawingBox(first);
  double size = std::max(box.width(), box.height());
  if (!(size > 0.0) || !std::isfinite(size)) return 3;
  return std::clamp(4 - static_cast<int>(std::floor(std::log10(size))), 0, 8);
}

// dur, and how it repeats: forever, or once and then stay on the last frame.
std::string timing(const AnimationOutputOptions& options) {
  std::string text = " dur=\"" + formatNumber(options.duration, 6) + "s\"";
  text += options.loop ? " repeatCount=\"indefinite\"" : " fill=\"freeze\"";
  return text;
}

std::string fraction(std::size_t i, std::size_t n) { return formatNumber(static_cast<double>(i) / n, 6); }

// Each shape once, its `d` animated through the frames. Frame i is reached at i/n of the
// duration; a loop ends on the first frame again, so the wrap from the last is interpolated too.
std::string morphingSvg(const std::vector<Drawing>& frames, const AnimationOutputOptions& options) {
  const std::size_t n = frames.size();
  std::vector<std::vector<const DrawnShape*>> shapes;
  for (const Drawing& frame : frames) shapes.push_back(shapesOf(frame));
  std::unordered_map<const DrawnShape*, std::size_t> indexOf;
  for (std::size_t i = 0; i < shapes[0].size(); ++i) indexOf[shapes[0][i]] = i;

  const std::size_t steps = options.loop ? n : n - 1;  // intervals between the values
  std::string keyTimes;
  for (std::size_t i = 0; steps > 0 && i <= steps; ++i) {
    if (i > 0) keyTimes += ';';
    keyTimes += fraction(i, steps);
  }
  const std::string repeat = timing(options);

  SvgBuilder builder(precisionFor(frames.front(), options), 0.0);
  builder.shapeChildren = [&](const DrawnShape& shape, const std::string& d, int depth) -> std::string {
    if (n < 2) return {};
    std::size_t index = indexOf.at(&shape);
    std::string values = d;
    bool moves = false;
    for (std::size_t k = 1; k < n; ++k) {
      std::string dk = svg_builder::pathData(*shapes[k][index], builder.precision(), 0.0);
      moves = moves || dk != d;
      values += ';';
      values += dk;
    }
    std::string text;
    const std::string indent(static_cast<std::size_t>(depth) * 2, ' ');
    if (moves) {
      if (options.loop) values += ';' + d;
      text += indent + "<animate attributeName=\"d\"" + repeat + " calcMode=\"linear\" keyTimes=\"" + keyTimes +
              "\" values=\"" + values + "\"/>\n";
    }
    // An attribute written as `valueOf` gives it in each frame, animated when it changes.
    auto animateStroke = [&](const char* attribute, auto valueOf) {
      const std::string first = valueOf(shape);
      std::string all = first;
      bool changes = false;
      for (std::size_t k = 1; k < n; ++k) {
        const std::string vk = valueOf(*shapes[k][index]);
        changes = changes || vk != first;
        all += ';' + vk;
      }
      if (!changes) return;
      if (options.loop) all += ';' + first;
      text += indent + "<animate attributeName=\"" + attribute + "\"" + repeat + " calcMode=\"linear\" keyTimes=\"" +
              keyTimes + "\" values=\"" + all + "\"/>\n";
    };
    // A stroke keeps its width and dashes relative to a growing or shrinking shape: animate them too.
    if (shape.stroke) {
      const int precision = builder.precision();
      animateStroke("stroke-width", [&](const DrawnShape& s) { return formatNumber(s.strokeWidth, precision); });
      if (!shape.dashArray.empty()) {
        animateStroke("stroke-dasharray", [&](const DrawnShape& s) { return svg_builder::dashList(s.dashArray, precision); });
        if (shape.dashOffset != 0.0)
          animateStroke("stroke-dashoffset", [&](const DrawnShape& s) { return formatNumber(s.dashOffset, precision); });
      }
    }
    return text;  // empty for a still shape
  };
  builder.beginDocument({&frames.front()});
  for (const DrawingGroup& group : frames.front().groups) builder.writeGroup(group, 1);
  builder.endDocument();
  return std::move(builder.text());
}

// How many groups at the start (`leading`) or the end of every frame are a scene's layer copied
// whole and the same in all frames.
std::size_t sharedCopiedLayers(const std::vector<Drawing>& frames, bool leading) {
  std::size_t count = 0;
  for (;; ++count) {
    const DrawingGroup* first = nullptr;
    for (const Drawing& frame : frames) {
      const std::size_t size = frame.groups.size();
      if (count >= size) return count;
      const DrawingGroup& group = frame.groups[leading ? count : size - 1 - count];
      if (!group.markupReplacesGroup || (first && !sameGroupStructure(*first, group))) return count;
      first = &group;
    }
  }
}

// Every frame its own group (a layer in Inkscape), visible from i/n to (i+1)/n of the duration.
// Ids in the later frames get a "-f<i>" suffix so the document's ids stay unique; a scene's
// copied layers, the same in every frame, are written once, below or above the frames.
std::string flipBookSvg(const std::vector<Drawing>& frames, const AnimationOutputOptions& options) {
  const std::size_t n = frames.size();
  std::vector<const Drawing*> all;
  for (const Drawing& frame : frames) all.push_back(&frame);
  SvgBuilder builder(precisionFor(frames.front(), options), 0.0);
  builder.beginDocument(all);
  std::string& out = builder.text();
  const std::string repeat = timing(options);
  const std::size_t below = sharedCopiedLayers(frames, true);
  std::size_t above = sharedCopiedLayers(frames, false);
  for (const Drawing& frame : frames) above = std::min(above, frame.groups.size() - below);
  const std::vector<DrawingGroup>& firstGroups = frames.front().groups;
  for (std::size_t k = 0; k < below; ++k) builder.writeGroup(firstGroups[k], 1);
  for (std::size_t i = 0; i < n; ++i) {
    const std::string name = animation_frames::frameFileName(i, n, "");
    out += "  <g";
    builder.attribute("id", builder.uniqueId(name));
    builder.attribute("class", "frame");
    builder.attribute("inkscape:groupmode", "layer");
    builder.attribute("inkscape:label", name);
    if (i > 0) builder.attribute("visibility", "hidden");
    out += ">\n";
    if (n > 1) {
      // Discrete: each value holds from its key time to the next one.
      std::string values, keyTimes;
      if (i == 0) {
        values = "visible;hidden";
        keyTimes = "0;" + fraction(1, n);
      } else if (i + 1 == n) {
        values = "hidden;visible";
        keyTimes = "0;" + fraction(i, n);
      } else {
        values = "hidden;visible;hidden";
        keyTimes = "0;" + fraction(i, n) + ";" + fraction(i + 1, n);
      }
      out += "    <animate attributeName=\"visibility\"" + repeat + " calcMode=\"discrete\" keyTimes=\"" +
             keyTimes + "\" values=\"" + values + "\"/>\n";
    }
    builder.idSuffix = i == 0 ? "" : "-f" + std::to_string(i);
    const std::vector<DrawingGroup>& groups = frames[i].groups;
    for (std::size_t k = below; k + above < groups.size(); ++k) builder.writeGroup(groups[k], 2);
    out += "  </g>\n";
  }
  builder.idSuffix.clear();
  for (std::size_t k = firstGroups.size() - above; k < firstGroups.size(); ++k) builder.writeGroup(firstGroups[k], 1);
  builder.endDocument();
  return std::move(out);
}

}  // namespace

std::string animatedSvgText(const std::vector<Drawing>& frames, const std::string& where,
                            const AnimationOutputOptions& options) {
  animation_frames::checkFrames(frames, options, where);
  try {
    return sameStructure(frames) ? morphingSvg(frames, options) : flipBookSvg(frames, options);
  } catch (const InputError& error) {
    throw InputError(where, error.what());
  }
}

void writeAnimatedSvg(const std::vector<Drawing>& frames, const std::string& path, const AnimationOutputOptions& options) {
  animation_frames::checkFrames(frames, options, path);
  checkOutputPath(path);  // a missing folder fails before the work
  writeFileAtomically(path, animatedSvgText(frames, path, options));
}

}  // namespace pak
