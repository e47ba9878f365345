#pragma once
// The pieces of Pak's SVG output, shared by the static writer (svg_writer.cpp) and the
// animated one (animated_svg_writer.cpp), so both write the same groups, ids, classes and paint.
#include <functional>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "pak/io/drawing.hpp"
#include "pak/io/svg_writer.hpp"

namespace pak::svg_builder {

// Escapes text for a double-quoted XML attribute; drops characters XML 1.0 forbids.
std::string escapeAttribute(const std::string& text);
// Whether `name` is a valid XML name (attribute names come from code; invalid ones are dropped).
bool isXmlName(const std::string& name);
// Fixed-point with `precision` decimals, trailing zeros trimmed, "-0" written as "0". Throws
// InputError for a non-finite value.
std::string formatNumber(double value, int precision);
std::string hexColor(const Color& color);
// A stroke-dasharray value: the lengths with `precision` decimals, separated by spaces.
std::string dashList(const std::vector<double>& dashes, int precision);
// The `d` of a shape: M/L/Z with line segments, or cubic Béziers fitted within curveTolerance > 0.
// `stats`, when given, counts its points and takes the fits' largest deviation into account.
std::string pathData(const Shape& shape, int precision, double curveTolerance, SvgPathStats* stats = nullptr);
// The drawing's box, or the bounds of what it draws when the box was left empty.
Box drawingBox(const Drawing& drawing);

class SvgBuilder {
 public:
  SvgBuilder(int precision, double curveTolerance) : precision_(precision), curveTolerance_(curveTolerance) {}

  // Optional: markup written inside a shape's <path> (e.g. an <animate>); `d` is the shape's
  // path data. Empty: the path is self-closing.
  std::function<std::string(const DrawnShape& shape, const std::string& d, int depth)> shapeChildren;
  // Appended to every group and shape id (and clip id), to keep ids unique when one document
  // holds several copies of a drawing.
  std::string idSuffix;
  // Optional: what the written paths hold (pathData's stats).
  SvgPathStats* stats = nullptr;

  // The XML declaration and the <svg> root sized by the first drawing, with the namespaces and
  // <defs> of copied markup in all of them.
  void beginDocument(const std::vector<const Drawing*>& drawings);
  void endDocument() { out_ += "</svg>\n"; }
  void writeGroup(const DrawingGroup& group, int depth);
  void writeShape(const DrawnShape& shape, int depth);
  // `wanted`, or wanted-2, wanted-3 … when the document already has that id (copied markup
  // keeps its own ids, so Pak's give way); taken from then on.
  std::string uniqueId(const std::string& wanted);

  void attribute(const std::string& name, const std::string& value);
  void indent(int depth) { out_.append(static_cast<std::size_t>(depth) * 2, ' '); }
  std::string& text() { return out_; }
  int precision() const { return precision_; }

 private:
  void declareNamespaces(const std::vector<std::pair<std::string, std::string>>& namespaces, bool root);

  int precision_;
  double curveTolerance_;
  int clipCount_ = 0;
  std::string out_;
  std::map<std::string, std::string> rootNamespaces_;  // prefix -> URI bound on the root
  std::set<std::string> takenIds_;                      // ids already in the document
};

}  // namespace pak::svg_builder
