// Reads SVG documents into flattened, painted shapes. SVG++ walks the XML tree, parses
// attribute values (paths, transforms, lengths, colours, style="…") and turns every shape
// into path events with relative commands, shorthands, quadratics, arcs and basic shapes
// already rewritten as absolute lines and cubics. This file adds what SVG++ leaves to its
// user: property inheritance, the current transform, layers, paint servers, flattening and
// the checks that turn bad input into InputError.
//
// All SVG++ code lives in this one translation unit on purpose: it takes ~20 s to compile.
#include "pak/io/svg_reader.hpp"

#include <rapidxml_ns/rapidxml_ns.hpp>
#include <svgpp/policy/xml/rapidxml_ns.hpp>
#include <svgpp/svgpp.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "io/rgb_components.hpp"
#include "io/xml_nesting.hpp"
#include "pak/error.hpp"
#include "pak/io/message_text.hpp"
#include "pak/io/text_file.hpp"

namespace pak {
namespace {

using XmlNode = rapidxml_ns::xml_node<char>;
namespace tag = svgpp::tag;

constexpr std::string_view kSvgNamespace = "http://www.w3.org/2000/svg";
constexpr std::string_view kInkscapeNamespace = "http://www.inkscape.org/namespaces/inkscape";
// Coordinates beyond this are a broken file, not a drawing (and would overflow the integer
// grid of the boolean operations).
constexpr double kAbsurdCoordinate = 1e9;
// Flattening never cuts one cubic into more pieces than this, whatever the tolerance.
constexpr int kMaxSegmentsPerCubic = 4096;

// Layer names with a meaning in Pak (DESIGN.md, "Input conventions").
bool isKnownLayerName(const std::string& name) {
  return name == "container" || name == "fixed" || name == "guides" || name == "spines" ||
         name == "elements" || name == "holes";
}

std::string lowerCased(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

std::string trimmedView(std::string_view text) {
  std::size_t begin = 0, end = text.size();
  while (begin < end && std::isspace(static_cast<unsigned char>(text[begin]))) ++begin;
  while (end > begin && std::isspace(static_cast<unsigned char>(text[end - 1]))) --end;
  return std::string(text.substr(begin, end - begin));
}

// A group's layer name: lower-cased; Illustrator's de-duplicating suffix ("container_1_")
// is dropped when what remains is a Pak layer name.
std::string layerName(const std::string& raw) {
  std::string name = lowerCased(raw);
  const std::size_t end = name.size();
  if (end >= 3 && name[end - 1] == '_') {
    std::size_t digits = end - 1;
    while (digits > 0 && std::isdigit(static_cast<unsigned char>(name[digits - 1]))) --digits;
    if (digits < end - 1 && digits > 0 && name[digits - 1] == '_' && isKnownLayerName(name.substr(0, digits - 1)))
      return name.substr(0, digits - 1);
  }
  return name;
}

template <class Range>
std::string toString(const Range& range) {
  return std::string(boost::begin(range), boost::end(range));
}

std::string formatNumber(double value) {
  std::ostringstream out;
  out.precision(10);
  out << value;
  return out.str();
}

// ---------------------------------------------------------------------------------------
// Affine maps, stored as SVG's matrix(a b c d e f): x' = a x + c y + e, y' = b x + d y + f.
struct Affine {
  double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;

  Vec2 apply(Vec2 p) const { return {a * p.x + c * p.y + e, b * p.x + d * p.y + f}; }
  // Scale factor for lengths such as stroke widths (exact for similarity transforms).
  double lengthScale() const { return std::sqrt(std::abs(a * d - b * c)); }
  static Affine translation(double tx, double ty) { return {1, 0, 0, 1, tx, ty}; }
  static Affine scaling(double sx, double sy) { return {sx, 0, 0, sy, 0, 0}; }
};

// `outer * inner` applies `inner` first.
Affine operator*(const Affine& m, const Affine& n) {
  return {m.a * n.a + m.c * n.b, m.b * n.a + m.d * n.b, m.a * n.c + m.c * n.d,
          m.b * n.c + m.d * n.d, m.a * n.e + m.c * n.f + m.e, m.b * n.e + m.d * n.f + m.f};
}

std::optional<Affine> inverse(const Affine& m) {
  const double det = m.a * m.d - m.b * m.c;
  if (!(std::abs(det) > 0.0) || !std::isfinite(1.0 / det)) return std::nullopt;
  return Affine{m.d / det, -m.b / det, -m.c / det, m.a / det, (m.c * m.f - m.d * m.e) / det,
                (m.b * m.e - m.a * m.f) / det};
}

// Does m stretch lengths differently in different directions (scale x and y apart, or skew)?
// Then no one width is the width of a stroke it transforms. A similarity's columns are
// orthogonal and equally long.
bool stretches(const Affine& m) {
  const double x = m.a * m.a + m.b * m.b, y = m.c * m.c + m.d * m.d;
  return std::abs(m.a * m.c + m.b * m.d) > 1e-9 * (x + y) || std::abs(x - y) > 1e-9 * (x + y);
}

// ---------------------------------------------------------------------------------------
// Paint as written in the file; resolved to a Color once the whole document is read
// (a gradient may be defined after the shape that uses it).
enum class PaintKind { None, Color, CurrentColor };

struct SolidPaint {
  PaintKind kind = PaintKind::None;
  std::uint32_t rgb = 0;  // 0xRRGGBB
};

struct Paint {
  SolidPaint solid;
  std::string server;                 // id of a gradient or pattern; empty for solid paint
  std::optional<SolidPaint> fallback; // fill="url(#g) red"
};

Paint solidPaint(PaintKind kind, std::uint32_t rgb = 0) { return Paint{{kind, rgb}, {}, {}}; }

// Inherited presentation properties (SVG's defaults).
struct Style {
  Paint fill = solidPaint(PaintKind::Color, 0x000000);
  Paint stroke = solidPaint(PaintKind::None);
  double fillOpacity = 1.0;
  double strokeOpacity = 1.0;
  double strokeWidth = 1.0;
  FillRule fillRule = FillRule::NonZero;
  StrokeCap lineCap = StrokeCap::Butt;
  StrokeJoin lineJoin = StrokeJoin::Miter;
  double miterLimit = 4.0;
  std::vector<double> dashArray;  // empty: solid
  double dashOffset = 0.0;
  FillRule clipRule = FillRule::NonZero;
  bool visible = true;
  std::uint32_t color = 0x000000;  // the `color` property, used by currentColor
};

// ---------------------------------------------------------------------------------------
// Geometry of one shape after its transform, before flattening.
struct CurveSegment {
  bool cubic = false;
  Vec2 control1, control2;  // used when cubic
  Vec2 end;
};

struct CurveSubpath {
  Vec2 start;
  std::vector<CurveSegment> segments;
  bool closed = false;
};

// A clip-path="url(#id)" on the shape or one of its groups, with the user space it is in
// (the element's transform, its own included: clipPathUnits="userSpaceOnUse").
struct ClipUse {
  std::string id;
  Affine ctm;
};

// One shape of a <clipPath>, in the clipPath's coordinates (its own transform applied).
struct ClipShape {
  std::vector<CurveSubpath> subpaths;
  FillRule rule = FillRule::NonZero;  // clip-rule
};

struct PendingShape {
  SvgShape shape;  // everything but the subpaths and the paint
  std::vector<ClipUse> clips;
  std::vector<CurveSubpath> subpaths;
  Paint fill, stroke;
  double fillOpacity = 1.0, strokeOpacity = 1.0;
  std::uint32_t color = 0;
  std::string description;  // for messages: <path id="…">
  // The transform, when it stretches (see `stretches`), and the stroke width before it.
  std::optional<Affine> stretch;
  double localStrokeWidth = 1.0;
};

struct GradientStop {
  std::uint32_t rgb = 0;
  double opacity = 1.0;
};

struct Gradient {
  std::string href;  // stops inherited from another gradient when it has none
  std::vector<GradientStop> stops;
};

// A visible `fixed` layer group, to copy as written: the transform and the opacity its
// ancestors give it (its own transform included).
struct FixedLayerSource {
  const XmlNode* node = nullptr;
  Affine ctm;
  double inheritedOpacity = 1.0;
};

// Line numbers of the source text: rapidxml parses in place, so a node's name points into the
// buffer at its offset in the text.
class LineIndex {
 public:
  explicit LineIndex(const std::vector<char>& buffer) : buffer_(&buffer) {
    for (std::size_t i = 0; i < buffer.size(); ++i)
      if (buffer[i] == '\n') newlines_.push_back(i);
  }
  // The 1-based line of the element, 0 when its name is not in the source text.
  int lineOf(const XmlNode* node) const {
    const char* name = node ? node->name() : nullptr;
    if (!name || name < buffer_->data() || name >= buffer_->data() + buffer_->size()) return 0;
    const std::size_t offset = static_cast<std::size_t>(name - buffer_->data());
    return static_cast<int>(std::upper_bound(newlines_.begin(), newlines_.end(), offset) - newlines_.begin()) + 1;
  }

 private:
  const std::vector<char>* buffer_;
  std::vector<std::size_t> newlines_;
};

// Everything one reading shares between the element contexts.
struct ReaderState {
  std::string file;
  const LineIndex* lines = nullptr;
  SvgDocument* document = nullptr;
  // Lengths with units; percentages are relative to the root viewBox once known.
  svgpp::factory::length::unitless<> lengths;
  std::vector<PendingShape> shapes;
  std::map<std::string, Gradient> gradients;
  std::map<std::string, std::vector<ClipShape>> clipPaths;  // by id; an empty one clips all away
  std::set<std::string> boundingBoxClips;                   // clipPathUnits="objectBoundingBox"
  std::string currentElement = "<svg>";  // the element being read, for error messages
  const XmlNode* currentNode = nullptr;
  std::optional<Box> viewBox;
  std::optional<double> width, height;
  int topLevelGroups = 0;
  std::vector<const XmlNode*> topGroupNodes;  // by SvgShape::topGroup
  std::vector<FixedLayerSource> fixedLayers;
  int currentTopGroup = -1;  // of the element being read: what its warnings are about
  std::set<std::string> ids;  // of every element: a paint server that is not among them is missing
  // Attribute values whose non-ASCII bytes became '?' for SVG++ (asciiForSvgpp), as written.
  struct AsciiFolded { const char* begin; std::size_t size; std::string written; };
  std::vector<AsciiFolded> asciiFolded;

  void warn(const std::string& where, const std::string& message) {
    document->warnings.push_back({file + (where.empty() ? "" : ": " + where), message, currentTopGroup});
  }
  // Where an error is: "file:line: <path id="…">" (the line when the element has one).
  std::string placeOf(const XmlNode* node, const std::string& element) const {
    const int line = lines ? lines->lineOf(node) : 0;
    return file + (line > 0 ? ":" + std::to_string(line) : "") + ": " + element;
  }
  // The text of [begin, begin + size) in an attribute value as the file wrote it, so that a
  // message quotes "réd", not the "r??d" SVG++ was given.
  std::string asWritten(const char* begin, std::size_t size) const {
    for (const AsciiFolded& folded : asciiFolded)
      if (begin >= folded.begin && begin + size <= folded.begin + folded.size)
        return folded.written.substr(static_cast<std::size_t>(begin - folded.begin), size);
    return std::string(begin, size);
  }
};

// SVG++ hands its error policy only the context of the failing element (sometimes wrapped
// in an adapter), so the policy finds the current reading here. One per thread.
thread_local ReaderState* currentReader = nullptr;

// ---------------------------------------------------------------------------------------
// Error policy: geometry that cannot be read is an InputError naming the element;
// unknown elements, attributes and CSS properties (Inkscape and Illustrator write many)
// are skipped, with a warning where the artist may care.
bool isGeometryAttribute(std::string_view name) {
  static const char* const names[] = {"d",  "points", "x",  "y",  "width", "height",
                                      "rx", "ry",     "r",  "cx", "cy",    "x1",
                                      "y1", "x2",     "y2", "transform", "viewBox"};
  return std::any_of(std::begin(names), std::end(names),
                     [&](const char* n) { return name == n; });
}

bool looksNonFinite(const std::string& value) {
  std::string lower = lowerCased(value);
  return lower.find("nan") != std::string::npos || lower.find("inf") != std::string::npos;
}

class NodeContext;

struct ErrorPolicy {
  using context_type = NodeContext;  // every context derives from it

  // Named by itself, <tag id="…">: the element read last may be a sibling's child.
  template <class Context, class XmlElement, class Name>
  static bool unknown_element(const Context&, const XmlElement& element, const Name& name) {
    if (!currentReader) return true;
    const std::string tag = toString(name);
    std::string where = "<" + tag;
    for (auto* a = element->first_attribute(); a; a = a->next_attribute())
      if (std::string_view(a->name(), a->name_size()) == "id")
        where += " id=\"" + std::string(a->value(), a->value_size()) + "\"";
    where += ">";
    // Inkscape 0.92 wrote text in a frame as <flowRoot>: text, as far as the artist knows.
    currentReader->warn(where, tag == "flowRoot"
                                   ? "<flowRoot> (flowed text) is not supported; skipped (convert it to paths)"
                                   : "unknown element <" + tag + "> skipped");
    return true;
  }
  template <class Context, class... Rest>
  static bool unknown_attribute(const Context&, const Rest&...) {
    return true;
  }
  template <class Context, class... Rest>
  static bool unexpected_attribute(const Context&, const Rest&...) {
    return true;
  }
  template <class Context, class XmlElement>
  static bool unexpected_element(const Context&, const XmlElement& element) {
    if (currentReader)
      currentReader->warn(currentReader->currentElement,
                          "<" + std::string(element->local_name(), element->local_name_size()) +
                              "> is not allowed here; skipped");
    return true;
  }
  template <class Context, class AttributeTag>
  static bool required_attribute_not_found(const Context&, AttributeTag) {
    if (currentReader)
      currentReader->warn(currentReader->currentElement,
                          std::string("required attribute ") +
                              svgpp::attribute_name<char>::get<AttributeTag>() +
                              " is missing; element skipped");
    return true;
  }
  template <class Context, class AttributeTag>
  static bool negative_value(const Context&, AttributeTag) {
    if (currentReader)
      currentReader->warn(currentReader->currentElement,
                          std::string("negative ") +
                              svgpp::attribute_name<char>::get<AttributeTag>() +
                              "; element not drawn (SVG error)");
    return true;
  }
  template <class Context, class AttributeTag, class Value>
  static bool parse_failed(const Context& context, AttributeTag, const Value& value) {
    const std::string name = svgpp::attribute_name<char>::get<AttributeTag>();
    std::string text = toString(value);
    if (currentReader && !text.empty()) text = currentReader->asWritten(&*boost::begin(value), text.size());
    if (text.size() > 80) text = text.substr(0, 77) + "...";
    const std::string where =
        currentReader ? currentReader->currentElement : std::string("<svg>");
    if (isGeometryAttribute(name)) {
      const std::string place = currentReader ? currentReader->placeOf(currentReader->currentNode, where) : where;
      throw InputError(place, "attribute " + name + "=\"" + text + "\" " +
                                  (looksNonFinite(text) ? "contains a non-finite number (NaN or infinity)"
                                                        : "cannot be parsed"));
    }
    if constexpr (std::is_same_v<AttributeTag, tag::attribute::stroke_dasharray> && std::is_base_of_v<NodeContext, Context>)
      const_cast<Context&>(context).rejectDashArray();
    if (currentReader)
      currentReader->warn(where, "ignored " + name + "=\"" + text + "\" (cannot be parsed)");
    return true;
  }
};

// Attribute order: the root's viewBox first, so that percentages in width/height resolve
// against it.
struct AttributeOrder {
  static const bool parse_style = true;
  static const bool css_hides_presentation_attribute = true;
  struct get_priority_attributes_by_element {
    template <class ElementTag>
    struct apply {
      using type = typename boost::mpl::if_<std::is_same<ElementTag, tag::element::svg>,
                                            boost::mpl::vector1<tag::attribute::viewBox>,
                                            boost::mpl::vector0<>>::type;
    };
  };
  using get_deferred_attributes_by_element = boost::mpl::always<boost::mpl::empty_sequence>;
  // Missing geometry attributes simply draw nothing, as browsers do.
  using get_required_attributes_by_element = boost::mpl::always<boost::mpl::empty_sequence>;
};

// ---------------------------------------------------------------------------------------
// Contexts: one object per element, living on the stack while SVG++ reads the element and
// its children. A child starts as a copy of its parent's inherited state.
template <class Tag>
constexpr bool isPaintAttribute =
    std::is_same_v<Tag, tag::attribute::fill> || std::is_same_v<Tag, tag::attribute::stroke>;

std::string attributeOf(const XmlNode* node, std::string_view name) {
  if (!node) return {};
  for (auto* a = node->first_attribute(); a; a = a->next_attribute())
    if (std::string_view(a->name(), a->name_size()) == name) return std::string(a->value(), a->value_size());
  return {};
}

// An attribute in Inkscape's namespace (inkscape:label, inkscape:groupmode), by its local name.
std::string inkscapeAttribute(const XmlNode* node, std::string_view name) {
  for (auto* a = node->first_attribute(); a; a = a->next_attribute()) {
    std::string_view local(a->local_name(), a->local_name_size());
    std::string_view ns(a->namespace_uri(), a->namespace_uri_size());
    std::string_view qname(a->name(), a->name_size());
    if (local == name && (ns == kInkscapeNamespace || qname == "inkscape:" + std::string(name)))
      return std::string(a->value(), a->value_size());
  }
  return {};
}
std::string inkscapeLabel(const XmlNode* node) { return inkscapeAttribute(node, "label"); }

// A presentation property as the element gives it: its style="…" declaration (stylesheets
// already folded in) wins over the attribute; "" when it has neither.
std::string propertyOf(const XmlNode* node, std::string_view name) {
  std::string value;
  const std::string style = attributeOf(node, "style");
  std::size_t from = 0;
  while (from < style.size()) {
    std::size_t end = style.find(';', from);
    if (end == std::string::npos) end = style.size();
    const std::string_view declaration = std::string_view(style).substr(from, end - from);
    from = end + 1;
    const std::size_t colon = declaration.find(':');
    if (colon == std::string_view::npos) continue;
    if (lowerCased(trimmedView(declaration.substr(0, colon))) == name) value = trimmedView(declaration.substr(colon + 1));
  }
  if (!value.empty()) return value;
  return trimmedView(attributeOf(node, name));
}

// Effects Pak does not draw, named so the artist knows what is missing: the property, what
// Pak does instead. A value of none (or normal, for blending) is no effect.
struct UnsupportedEffect {
  const char* property;
  const char* consequence;
};
constexpr UnsupportedEffect kUnsupportedEffects[] = {
    {"mask", "mask is not supported; drawn unmasked"},
    {"filter", "filter is not supported; drawn without it"},
    {"marker", "markers are not supported; not drawn"},
    {"marker-start", "markers are not supported; not drawn"},
    {"marker-mid", "markers are not supported; not drawn"},
    {"marker-end", "markers are not supported; not drawn"},
    {"mix-blend-mode", "mix-blend-mode is not supported; blended normally"},
};

class NodeContext {
 public:
  using length_factory_type = svgpp::factory::length::unitless<>;

  // The root <svg>.
  NodeContext(ReaderState& state, const XmlNode* node) : state_(&state), node_(node), isRoot_(true) {
    tag_ = "svg";
    id_ = attributeOf(node, "id");
    state_->currentNode = node;
  }

  // Any other element.
  NodeContext(NodeContext& parent, const XmlNode* node)
      : state_(parent.state_),
        node_(node),
        style_(parent.style_),
        parentCtm_(parent.childCtm()),
        inheritedOpacity_(parent.effectiveOpacity()),
        ancestorHidden_(parent.hidden()),
        nonRendered_(parent.nonRendered_),
        layer_(parent.layer_),
        layerKnown_(parent.layerKnown_),
        topGroup_(parent.topGroup_),
        layerGroup_(parent.layerGroup_),
        elements_(parent.elements_),
        gap_(parent.gap_),
        clips_(parent.clips_),
        clipPathId_(parent.clipPathId_) {
    tag_ = std::string(node->local_name(), node->local_name_size());
    id_ = attributeOf(node, "id");
    if (!parent.ownClip_.empty()) clips_.push_back({parent.ownClip_, parent.ctm()});
    ownClip_ = clipReference(propertyOf(node, "clip-path"));
    if (tag_ == "clipPath") {
      // Its shapes are in the user space of the element it clips: recorded in its own
      // coordinates, placed by each use.
      nonRendered_ = true;
      clipPathId_ = id_;
      parentCtm_ = Affine{};
      ownClip_.clear();
      clips_.clear();
      if (!id_.empty()) state_->clipPaths[id_];  // exists, even empty
      if (attributeOf(node, "clipPathUnits") == "objectBoundingBox") state_->boundingBoxClips.insert(id_);
    }
    if (std::string own = attributeOf(node, "data-elements"); !own.empty()) elements_ = std::move(own);
    if (std::string own = attributeOf(node, "data-gap"); !own.empty()) gap_ = std::move(own);
    if (tag_ == "defs") nonRendered_ = true;
    if (tag_ == "g") {
      if (parent.isRoot_) {
        topGroup_ = state_->topLevelGroups++;
        state_->topGroupNodes.push_back(node);
        SvgTopGroup& top = state_->document->topGroups.emplace_back();
        top.name = inkscapeLabel(node);
        if (top.name.empty()) top.name = id_;
        state_->document->inkscapeLayers.push_back(inkscapeAttribute(node, "groupmode") == "layer");
      }
      if (parent.isLayerGroup_) layerGroup_ = parent.childGroups_++;
      enterGroupLayer();
    }
    state_->currentTopGroup = topGroup_;
    state_->currentElement = describe();
    state_->currentNode = node;
  }

  NodeContext(const NodeContext&) = delete;
  NodeContext& operator=(const NodeContext&) = delete;

  const length_factory_type& length_factory() const { return state_->lengths; }
  void on_exit_element() {
    state_->currentTopGroup = topGroup_;
    if (fixedLayer_ && !hidden() && !nonRendered_) state_->fixedLayers.push_back({node_, ctm(), inheritedOpacity_});
    if (!hidden() && !nonRendered_) warnUnsupportedEffects();
  }
  template <class Range>
  void set_text(const Range&) {}

  void transform_matrix(const boost::array<double, 6>& m) {
    for (double v : m)
      if (!std::isfinite(v) || std::abs(v) > kAbsurdCoordinate)
        throw InputError(place(), "transform has a non-finite or absurd value " +
                                           formatNumber(v));
    ownTransform_ = Affine{m[0], m[1], m[2], m[3], m[4], m[5]};
  }

  // --- the viewport attributes of <svg> elements
  void set(tag::attribute::viewBox, double x, double y, double w, double h) {
    for (double v : {x, y, w, h})
      if (!std::isfinite(v) || std::abs(v) > kAbsurdCoordinate)
        throw InputError(place(), "viewBox has a non-finite or absurd value " +
                                           formatNumber(v));
    if (w <= 0 || h <= 0) {
      state_->warn(describe(), "viewBox with zero or negative size ignored");
      return;
    }
    Box box;
    box.add(Vec2{x, y});
    box.add(Vec2{x + w, y + h});
    viewBox_ = box;
    if (isRoot_) {
      state_->viewBox = box;
      state_->lengths.set_viewport_size(w, h);
    }
  }
  void set(tag::attribute::width, double v) { checkedViewportLength("width", v, viewportWidth_); }
  void set(tag::attribute::height, double v) { checkedViewportLength("height", v, viewportHeight_); }
  void set(tag::attribute::x, double v) { viewportX_ = v; }
  void set(tag::attribute::y, double v) { viewportY_ = v; }

  // --- paint
  template <class P>
    requires isPaintAttribute<P>
  void set(P, tag::value::none) { paintOf(P()) = solidPaint(PaintKind::None); }
  template <class P>
    requires isPaintAttribute<P>
  void set(P, tag::value::currentColor) { paintOf(P()) = solidPaint(PaintKind::CurrentColor); }
  template <class P>
    requires isPaintAttribute<P>
  void set(P, int rgb) { paintOf(P()) = solidPaint(PaintKind::Color, static_cast<std::uint32_t>(rgb)); }
  template <class P>
    requires isPaintAttribute<P>
  void set(P, int rgb, tag::skip_icc_color) { set(P(), rgb); }
  template <class P, class Range>
    requires isPaintAttribute<P>
  void set(P, tag::iri_fragment, const Range& id) { paintOf(P()) = serverPaint(id, std::nullopt); }
  template <class P, class Range>
    requires isPaintAttribute<P>
  void set(P, tag::iri_fragment, const Range& id, tag::value::none) {
    paintOf(P()) = serverPaint(id, SolidPaint{PaintKind::None, 0});
  }
  template <class P, class Range>
    requires isPaintAttribute<P>
  void set(P, tag::iri_fragment, const Range& id, tag::value::currentColor) {
    paintOf(P()) = serverPaint(id, SolidPaint{PaintKind::CurrentColor, 0});
  }
  template <class P, class Range>
    requires isPaintAttribute<P>
  void set(P, tag::iri_fragment, const Range& id, int rgb) {
    paintOf(P()) = serverPaint(id, SolidPaint{PaintKind::Color, static_cast<std::uint32_t>(rgb)});
  }
  template <class P, class Range>
    requires isPaintAttribute<P>
  void set(P, tag::iri_fragment, const Range& id, int rgb, tag::skip_icc_color) {
    set(P(), tag::iri_fragment(), id, rgb);
  }
  // A paint server in another file: only its fallback can be used.
  template <class P, class Range>
    requires isPaintAttribute<P>
  void set(P, const Range& iri) {
    state_->warn(describe(), "external paint " + toString(iri) + " not supported; painted grey");
    paintOf(P()) = solidPaint(PaintKind::Color, 0x808080);
  }
  template <class P, class Range>
    requires isPaintAttribute<P>
  void set(P, const Range&, tag::value::none) { set(P(), tag::value::none()); }
  template <class P, class Range>
    requires isPaintAttribute<P>
  void set(P, const Range&, tag::value::currentColor) { set(P(), tag::value::currentColor()); }
  template <class P, class Range>
    requires isPaintAttribute<P>
  void set(P, const Range&, int rgb) { set(P(), rgb); }
  template <class P, class Range>
    requires isPaintAttribute<P>
  void set(P, const Range&, int rgb, tag::skip_icc_color) { set(P(), rgb); }

  void set(tag::attribute::color, int rgb) { style_.color = static_cast<std::uint32_t>(rgb); }
  void set(tag::attribute::color, int rgb, tag::skip_icc_color) { set(tag::attribute::color(), rgb); }

  // --- other presentation properties
  void set(tag::attribute::fill_opacity, double v) { setOpacity(style_.fillOpacity, "fill-opacity", v); }
  void set(tag::attribute::stroke_opacity, double v) { setOpacity(style_.strokeOpacity, "stroke-opacity", v); }
  void set(tag::attribute::opacity, double v) { setOpacity(ownOpacity_, "opacity", v); }
  // A width beyond any coordinate is a broken file; outlining it would overflow the clipper.
  void set(tag::attribute::stroke_width, double v) {
    if (std::isfinite(v) && v >= 0 && v <= kAbsurdCoordinate) style_.strokeWidth = v;
    else state_->warn(describe(), "ignored stroke-width " + formatNumber(v) + " (must be 0 to 1e9)");
  }
  void set(tag::attribute::stroke_linecap, tag::value::butt) { style_.lineCap = StrokeCap::Butt; }
  void set(tag::attribute::stroke_linecap, tag::value::round) { style_.lineCap = StrokeCap::Round; }
  void set(tag::attribute::stroke_linecap, tag::value::square) { style_.lineCap = StrokeCap::Square; }
  void set(tag::attribute::stroke_linejoin, tag::value::miter) { style_.lineJoin = StrokeJoin::Miter; }
  void set(tag::attribute::stroke_linejoin, tag::value::round) { style_.lineJoin = StrokeJoin::Round; }
  void set(tag::attribute::stroke_linejoin, tag::value::bevel) { style_.lineJoin = StrokeJoin::Bevel; }
  // SVG: a miter limit below 1 is an error; the property is then ignored.
  void set(tag::attribute::stroke_miterlimit, double v) {
    if (std::isfinite(v) && v >= 1.0) style_.miterLimit = v;
    else state_->warn(describe(), "ignored stroke-miterlimit " + formatNumber(v) + " (must be at least 1)");
  }
  // Dashes as SVG reads them: an odd count repeats to an even one; all zeros is solid; a
  // negative length is an error, and the property is then ignored.
  void set(tag::attribute::stroke_dasharray, tag::value::none) { style_.dashArray.clear(); }
  void set(tag::attribute::stroke_dasharray, tag::value::inherit) {}
  template <class Range>
  void set(tag::attribute::stroke_dasharray, const Range& lengths) {
    dashBeforeSet_ = style_.dashArray;
    std::vector<double> dashes(boost::begin(lengths), boost::end(lengths));
    double sum = 0.0;
    for (double length : dashes) {
      if (!std::isfinite(length) || length < 0.0) {
        state_->warn(describe(), "ignored stroke-dasharray with the length " + formatNumber(length) +
                                     " (lengths must be finite and not negative)");
        return;
      }
      sum += length;
    }
    if (!(sum > 0.0)) dashes.clear();
    if (dashes.size() % 2 == 1) {
      const std::vector<double> once = dashes;
      dashes.insert(dashes.end(), once.begin(), once.end());
    }
    style_.dashArray = std::move(dashes);
  }
  // SVG++ reports a list it could not parse after handing over what it read: back to before.
  void rejectDashArray() { style_.dashArray = dashBeforeSet_; }
  // An opacity is clamped to [0, 1] as SVG says; NaN (which clamping keeps) is ignored.
  void setOpacity(double& target, const char* name, double v) {
    if (std::isnan(v)) state_->warn(describe(), std::string("ignored ") + name + " NaN");
    else target = std::clamp(v, 0.0, 1.0);
  }
  void set(tag::attribute::stroke_dashoffset, double v) {
    if (std::isfinite(v)) style_.dashOffset = v;
  }
  void set(tag::attribute::clip_rule, tag::value::nonzero) { style_.clipRule = FillRule::NonZero; }
  void set(tag::attribute::clip_rule, tag::value::evenodd) { style_.clipRule = FillRule::EvenOdd; }
  void set(tag::attribute::fill_rule, tag::value::nonzero) { style_.fillRule = FillRule::NonZero; }
  void set(tag::attribute::fill_rule, tag::value::evenodd) { style_.fillRule = FillRule::EvenOdd; }
  void set(tag::attribute::display, tag::value::none) { displayNone_ = true; }
  void set(tag::attribute::display, tag::value::inherit) {}
  template <class Value>
  void set(tag::attribute::display, Value) { displayNone_ = false; }
  void set(tag::attribute::visibility, tag::value::visible) { style_.visible = true; }
  void set(tag::attribute::visibility, tag::value::hidden) { style_.visible = false; }
  void set(tag::attribute::visibility, tag::value::collapse) { style_.visible = false; }
  // `inherit` on a non-inherited property (opacity, display): keep the default.
  template <class AttributeTag>
  void set(AttributeTag, tag::value::inherit) {}

 protected:
  std::string describe() const {
    std::string text = "<" + tag_;
    if (!id_.empty()) text += " id=\"" + id_ + "\"";
    return text + ">";
  }
  // One warning per effect the element asks for and Pak does not draw.
  void warnUnsupportedEffects() const {
    for (const UnsupportedEffect& effect : kUnsupportedEffects) {
      const std::string value = propertyOf(node_, effect.property);
      const std::string lower = lowerCased(value);
      if (value.empty() || lower == "none" || lower == "inherit" || lower == "initial" ||
          (std::string_view(effect.property) == "mix-blend-mode" && lower == "normal"))
        continue;
      state_->warn(describe(), std::string(effect.property) + "=\"" + value + "\": " + effect.consequence);
    }
  }
  // Where an error in this element is: file, line and the element.
  std::string place() const { return state_->placeOf(node_, describe()); }
  Affine ctm() const { return parentCtm_ * ownTransform_; }
  double effectiveOpacity() const { return inheritedOpacity_ * ownOpacity_; }
  bool hidden() const { return ancestorHidden_ || displayNone_; }

  ReaderState* state_;
  const XmlNode* node_;
  std::string tag_, id_;
  Style style_;
  Affine parentCtm_, ownTransform_;
  double inheritedOpacity_ = 1.0, ownOpacity_ = 1.0;
  bool displayNone_ = false;
  bool ancestorHidden_ = false;
  bool nonRendered_ = false;  // inside <defs>: definitions, never drawn directly
  std::string layer_;
  bool layerKnown_ = false;
  int topGroup_ = -1;
  int layerGroup_ = -1;       // see SvgShape::layerGroup
  bool isLayerGroup_ = false; // this group names the layer: its child groups are numbered
  int childGroups_ = 0;
  bool isRoot_ = false;
  bool fixedLayer_ = false;   // the outermost group of a `fixed` layer
  std::string elements_;      // see SvgShape::elements
  std::string gap_;           // see SvgShape::gap
  std::vector<ClipUse> clips_;  // clip paths of the ancestors
  std::string ownClip_;         // this element's clip-path id ("" if none)
  std::string clipPathId_;      // inside <clipPath id=…>: its id
  std::vector<double> dashBeforeSet_;  // see rejectDashArray

  // The id of clip-path="url(#id)"; "" for none or anything else.
  static std::string clipReference(const std::string& value) {
    const std::size_t open = value.find("url(");
    if (open == std::string::npos) return {};
    std::size_t begin = open + 4, end = value.find(')', begin);
    if (end == std::string::npos) return {};
    std::string inside = trimmedView(std::string_view(value).substr(begin, end - begin));
    if (inside.size() >= 2 && (inside.front() == '"' || inside.front() == '\'')) inside = inside.substr(1, inside.size() - 2);
    return inside.size() > 1 && inside[0] == '#' ? inside.substr(1) : std::string();
  }

 private:
  // The layer of a named group: the nearest ancestor named like a Pak layer wins, else the
  // outermost named group.
  void enterGroupLayer() {
    const std::string label = layerName(inkscapeLabel(node_));
    const std::string id = layerName(id_);
    std::string name;
    if (isKnownLayerName(label)) name = label;
    else if (isKnownLayerName(id)) name = id;
    else name = !label.empty() ? label : id;
    if (name.empty()) return;
    const bool known = isKnownLayerName(name);
    if (known || layer_.empty()) {
      if (known || !layerKnown_) {
        fixedLayer_ = name == "fixed" && layer_ != "fixed";
        layer_ = name;
        layerKnown_ = known;
        isLayerGroup_ = true;
        layerGroup_ = -1;
        auto& layers = state_->document->layers;
        if (std::find(layers.begin(), layers.end(), name) == layers.end()) layers.push_back(name);
        if (topGroup_ >= 0) {
          auto& inTop = state_->document->topGroups[static_cast<std::size_t>(topGroup_)].layers;
          if (std::find(inTop.begin(), inTop.end(), name) == inTop.end()) inTop.push_back(name);
        }
      }
    }
  }

  void checkedViewportLength(const char* name, double v, std::optional<double>& out) {
    if (!std::isfinite(v) || std::abs(v) > kAbsurdCoordinate)
      throw InputError(place(), std::string(name) + " is non-finite or absurd: " + formatNumber(v));
    if (v <= 0) return;  // zero or negative: as if absent
    out = v;
    if (isRoot_) {
      (std::string_view(name) == "width" ? state_->width : state_->height) = v;
      // Without a viewBox, percentages of later elements are relative to the document size.
      if (!state_->viewBox)
        state_->lengths.set_viewport_size(state_->width.value_or(0), state_->height.value_or(0));
    }
  }

  template <class P>
  Paint& paintOf(P) {
    if constexpr (std::is_same_v<P, tag::attribute::fill>) return style_.fill;
    else return style_.stroke;
  }

  template <class Range>
  static Paint serverPaint(const Range& id, std::optional<SolidPaint> fallback) {
    Paint paint;
    paint.server = toString(id);
    paint.fallback = fallback;
    return paint;
  }

  // A nested <svg> maps its viewBox into its viewport (x, y, width, height), centred and
  // scaled uniformly (preserveAspectRatio's default). The root's viewBox is *the*
  // coordinate system of the document, so it maps nothing.
  Affine childCtm() const {
    Affine m = ctm();
    if (isRoot_ || tag_ != "svg") return m;
    m = m * Affine::translation(viewportX_, viewportY_);
    if (!viewBox_) return m;
    const double boxW = viewBox_->width(), boxH = viewBox_->height();
    const double w = viewportWidth_.value_or(state_->viewBox ? state_->viewBox->width() : boxW);
    const double h = viewportHeight_.value_or(state_->viewBox ? state_->viewBox->height() : boxH);
    const double s = std::min(w / boxW, h / boxH);
    return m * Affine::translation((w - boxW * s) / 2, (h - boxH * s) / 2) * Affine::scaling(s, s) *
           Affine::translation(-viewBox_->min.x, -viewBox_->min.y);
  }

  std::optional<Box> viewBox_;
  std::optional<double> viewportWidth_, viewportHeight_;
  double viewportX_ = 0, viewportY_ = 0;
};

// <path>, <rect>, <circle>, <ellipse>, <line>, <polyline>, <polygon>: SVG++ converts all of
// them to absolute move/line/cubic/close events.
class ShapeContext : public NodeContext {
 public:
  ShapeContext(NodeContext& parent, const XmlNode* node) : NodeContext(parent, node) {}

  void path_move_to(double x, double y, tag::coordinate::absolute) {
    CurveSubpath subpath;
    subpath.start = local(x, y);
    subpaths_.push_back(std::move(subpath));
    current_ = subpaths_.back().start;
  }
  void path_line_to(double x, double y, tag::coordinate::absolute) {
    CurveSegment segment;
    segment.end = local(x, y);
    append(segment);
  }
  void path_cubic_bezier_to(double x1, double y1, double x2, double y2, double x, double y,
                            tag::coordinate::absolute) {
    CurveSegment segment;
    segment.cubic = true;
    segment.control1 = local(x1, y1);
    segment.control2 = local(x2, y2);
    segment.end = local(x, y);
    append(segment);
  }
  // An arc as SVG's implementation notes (F.6.2) say: none between one point and itself, a
  // line when a radius is zero, else cubics of at most a quarter turn each (radii too small
  // to reach the end scaled up by SVG++).
  void path_elliptical_arc_to(double rx, double ry, double xAxisRotation, bool largeArc, bool sweep, double x,
                              double y, tag::coordinate::absolute) {
    const Vec2 from = current_, to = local(x, y);
    if (from == to) return;
    if (!(rx > 0.0) || !(ry > 0.0)) {
      path_line_to(x, y, tag::coordinate::absolute());
      return;
    }
    const double rotation = xAxisRotation * boost::math::constants::degree<double>();
    double cx = 0, cy = 0, theta1 = 0, theta2 = 0;
    svgpp::arc_endpoint_to_center(from.x, from.y, to.x, to.y, rx, ry, rotation, largeArc, sweep, cx, cy, theta1,
                                  theta2);
    // Coordinates or radii near 1e308 overflow the centre's squares; SVG++ would then cast
    // the NaN angles to a cubic count (undefined behaviour).
    if (!std::isfinite(cx) || !std::isfinite(cy) || !std::isfinite(theta1) || !std::isfinite(theta2))
      throw InputError(place(), "arc to (" + formatNumber(x) + ", " + formatNumber(y) +
                                    "): its centre is not a finite number (a coordinate or radius too large)");
    constexpr double turn = boost::math::constants::two_pi<double>();
    if (sweep && theta2 < theta1) theta2 += turn;
    if (!sweep && theta2 > theta1) theta2 -= turn;
    using ArcToCubics = svgpp::arc_to_bezier<double>;
    ArcToCubics cubics(cx, cy, rx, ry, rotation, ArcToCubics::circle_angle_tag(), theta1, theta2,
                       ArcToCubics::max_angle_tag(), boost::math::constants::half_pi<double>());
    // SVG++'s iterator sets its points before eof() turns false; g++ cannot see that.
#if defined(__GNUC__) && !defined(__clang__)  // clang has no such warning
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
    for (ArcToCubics::iterator it(cubics); !it.eof(); it.advance())
      path_cubic_bezier_to(it.p1x(), it.p1y(), it.p2x(), it.p2y(), it.p3x(), it.p3y(), tag::coordinate::absolute());
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
  }
  void path_close_subpath() {
    if (subpaths_.empty()) return;
    subpaths_.back().closed = true;
    current_ = subpaths_.back().start;
  }
  void path_exit() {}

  void on_exit_element() {
    state_->currentTopGroup = topGroup_;
    if (!clipPathId_.empty()) {
      // A shape of a <clipPath>: its geometry only (paint does not matter).
      if (hidden() || !style_.visible || subpaths_.empty()) return;
      ClipShape clip;
      clip.rule = style_.clipRule;
      clip.subpaths = std::move(subpaths_);
      mapAll(ctm(), clip.subpaths);
      state_->clipPaths[clipPathId_].push_back(std::move(clip));
      return;
    }
    if (hidden() || nonRendered_ || !style_.visible || subpaths_.empty()) return;
    warnUnsupportedEffects();
    PendingShape pending;
    pending.clips = clips_;
    if (!ownClip_.empty()) pending.clips.push_back({ownClip_, ctm()});
    pending.description = describe();
    const Affine m = ctm();
    mapAll(m, subpaths_);
    pending.subpaths = std::move(subpaths_);
    SvgShape& shape = pending.shape;
    shape.strokeWidth = style_.strokeWidth;
    if (stretches(m)) pending.stretch = m;
    pending.localStrokeWidth = style_.strokeWidth;
    shape.opacity = effectiveOpacity();
    shape.fillRule = style_.fillRule;
    shape.lineCap = style_.lineCap;
    shape.lineJoin = style_.lineJoin;
    shape.miterLimit = style_.miterLimit;
    shape.dashArray = style_.dashArray;
    shape.dashOffset = style_.dashOffset;
    scaleStroke(shape, m.lengthScale());
    shape.id = id_;
    shape.tag = tag_;
    shape.line = state_->lines->lineOf(node_);
    shape.layer = layer_;
    shape.topGroup = topGroup_;
    shape.layerGroup = layerGroup_;
    shape.elements = elements_;
    shape.gap = gap_;
    pending.fill = style_.fill;
    pending.stroke = style_.stroke;
    pending.fillOpacity = style_.fillOpacity;
    pending.strokeOpacity = style_.strokeOpacity;
    pending.color = style_.color;
    state_->shapes.push_back(std::move(pending));
  }

 private:
  // Local coordinates are only checked for finiteness here; the absurdity check happens
  // after the transform, on the coordinates Pak will use.
  Vec2 local(double x, double y) {
    if (!std::isfinite(x) || !std::isfinite(y))
      throw InputError(place(), "non-finite coordinate (" + formatNumber(x) +
                                         ", " + formatNumber(y) + ")");
    return {x, y};
  }

  // Every point of `subpaths` (control points too) through m, checked as `mapped` checks one.
  void mapAll(const Affine& m, std::vector<CurveSubpath>& subpaths) const {
    for (CurveSubpath& subpath : subpaths) {
      subpath.start = mapped(m, subpath.start);
      for (CurveSegment& segment : subpath.segments) {
        if (segment.cubic) {
          segment.control1 = mapped(m, segment.control1);
          segment.control2 = mapped(m, segment.control2);
        }
        segment.end = mapped(m, segment.end);
      }
    }
  }

  Vec2 mapped(const Affine& m, Vec2 p) const {
    const Vec2 q = m.apply(p);
    if (!std::isfinite(q.x) || !std::isfinite(q.y))
      throw InputError(place(), "coordinate is not a finite number after its transform");
    if (std::abs(q.x) > kAbsurdCoordinate || std::abs(q.y) > kAbsurdCoordinate)
      throw InputError(place(), "absurd coordinate (" + formatNumber(q.x) + ", " +
                                         formatNumber(q.y) + "), beyond ±1e9");
    return q;
  }

  // After a closepath, drawing continues from the closed subpath's start in a new subpath.
  void append(const CurveSegment& segment) {
    if (subpaths_.empty() || subpaths_.back().closed) {
      CurveSubpath subpath;
      subpath.start = current_;
      subpaths_.push_back(std::move(subpath));
    }
    subpaths_.back().segments.push_back(segment);
    current_ = segment.end;
  }

  std::vector<CurveSubpath> subpaths_;
  Vec2 current_;
};

// <linearGradient>/<radialGradient>: Pak paints flat colours, so a gradient becomes the
// mean of its stops.
class GradientContext : public NodeContext {
 public:
  GradientContext(NodeContext& parent, const XmlNode* node) : NodeContext(parent, node) {}

  using NodeContext::set;
  template <class Range>
  void set(tag::attribute::xlink::href, tag::iri_fragment, const Range& id) { gradient_.href = toString(id); }
  template <class Range>
  void set(tag::attribute::xlink::href, const Range&) {}

  void addStop(const GradientStop& stop) { gradient_.stops.push_back(stop); }
  void on_exit_element() {
    if (!id_.empty()) state_->gradients[id_] = gradient_;
  }

 private:
  Gradient gradient_;
};

class StopContext : public NodeContext {
 public:
  StopContext(GradientContext& parent, const XmlNode* node) : NodeContext(parent, node), gradient_(&parent) {}

  using NodeContext::set;
  void set(tag::attribute::stop_color, int rgb) { stop_.rgb = static_cast<std::uint32_t>(rgb); }
  void set(tag::attribute::stop_color, int rgb, tag::skip_icc_color) { set(tag::attribute::stop_color(), rgb); }
  void set(tag::attribute::stop_color, tag::value::currentColor) { stop_.rgb = style_.color; }
  void set(tag::attribute::stop_opacity, double v) {
    if (!std::isnan(v)) stop_.opacity = std::clamp(v, 0.0, 1.0);  // NaN: ignored, as a missing value
  }
  void on_exit_element() { gradient_->addStop(stop_); }

 private:
  GradientContext* gradient_;
  GradientStop stop_;
};

// <use>, <text>, <image>: not drawn; the artist is told.
class UnsupportedContext : public NodeContext {
 public:
  UnsupportedContext(NodeContext& parent, const XmlNode* node) : NodeContext(parent, node) {}
  void on_exit_element() {
    state_->currentTopGroup = topGroup_;
    if (hidden() || nonRendered_ || !style_.visible) return;
    state_->warn(describe(), "<" + tag_ + "> is not supported; skipped (convert it to paths)");
  }
};

}  // namespace
}  // namespace pak

// Adapters inside SVG++ (basic shapes, viewport) look the error policy up by context type
// rather than through document_traversal's parameter: give them ours too.
namespace svgpp::policy::error {
template <> struct default_policy<pak::NodeContext> : pak::ErrorPolicy {};
template <> struct default_policy<pak::ShapeContext> : pak::ErrorPolicy {};
template <> struct default_policy<pak::GradientContext> : pak::ErrorPolicy {};
template <> struct default_policy<pak::StopContext> : pak::ErrorPolicy {};
template <> struct default_policy<pak::UnsupportedContext> : pak::ErrorPolicy {};
}  // namespace svgpp::policy::error

namespace pak {
namespace {

template <class Context>
using OnStack = svgpp::factory::context::on_stack_with_xml_element<Context>;

struct ContextFactories {
  template <class ParentContext, class ElementTag, class Enable = void>
  struct apply {
    using type = OnStack<NodeContext>;  // svg, g, a, switch, defs
  };
};

template <class ParentContext, class ElementTag>
struct ContextFactories::apply<ParentContext, ElementTag,
                               typename boost::enable_if<boost::mpl::has_key<svgpp::traits::shape_elements, ElementTag>>::type> {
  using type = OnStack<ShapeContext>;
};
template <class ParentContext>
struct ContextFactories::apply<ParentContext, tag::element::linearGradient> {
  using type = OnStack<GradientContext>;
};
template <class ParentContext>
struct ContextFactories::apply<ParentContext, tag::element::radialGradient> {
  using type = OnStack<GradientContext>;
};
template <class ParentContext>
struct ContextFactories::apply<ParentContext, tag::element::stop> {
  using type = OnStack<StopContext>;
};
template <class ParentContext>
struct ContextFactories::apply<ParentContext, tag::element::use_> {
  using type = OnStack<UnsupportedContext>;
};
template <class ParentContext>
struct ContextFactories::apply<ParentContext, tag::element::text> {
  using type = OnStack<UnsupportedContext>;
};
template <class ParentContext>
struct ContextFactories::apply<ParentContext, tag::element::image> {
  using type = OnStack<UnsupportedContext>;
};

// Elements SVG++ walks into. Everything else (clipPath, mask, symbol, marker, pattern,
// metadata, editor namespaces …) is skipped with its whole subtree, so it is never drawn.
using ProcessedElements =
    boost::mpl::set<tag::element::svg, tag::element::g, tag::element::a, tag::element::switch_,
                    tag::element::defs, tag::element::path, tag::element::rect, tag::element::circle,
                    tag::element::ellipse, tag::element::line, tag::element::polyline,
                    tag::element::polygon, tag::element::linearGradient, tag::element::radialGradient,
                    tag::element::stop, tag::element::use_, tag::element::text,
                    tag::element::image, tag::element::clipPath>::type;

using StyleAttributes =
    boost::mpl::vector<tag::attribute::transform, tag::attribute::fill, tag::attribute::stroke,
                       tag::attribute::fill_opacity, tag::attribute::stroke_opacity,
                       tag::attribute::opacity, tag::attribute::stroke_width, tag::attribute::fill_rule,
                       tag::attribute::stroke_linecap, tag::attribute::stroke_linejoin,
                       tag::attribute::stroke_miterlimit, tag::attribute::stroke_dasharray,
                       tag::attribute::stroke_dashoffset, tag::attribute::clip_rule, tag::attribute::display, tag::attribute::visibility, tag::attribute::color>;

using StructureAttributes = boost::mpl::vector<
    boost::mpl::pair<tag::element::svg, tag::attribute::viewBox>,
    boost::mpl::pair<tag::element::svg, tag::attribute::width>,
    boost::mpl::pair<tag::element::svg, tag::attribute::height>,
    boost::mpl::pair<tag::element::svg, tag::attribute::x>,
    boost::mpl::pair<tag::element::svg, tag::attribute::y>,
    boost::mpl::pair<tag::element::stop, tag::attribute::stop_color>,
    boost::mpl::pair<tag::element::stop, tag::attribute::stop_opacity>,
    boost::mpl::pair<tag::element::linearGradient, tag::attribute::xlink::href>,
    boost::mpl::pair<tag::element::radialGradient, tag::attribute::xlink::href>>;

template <class Set, class Sequence>
using InsertAll =
    typename boost::mpl::fold<Sequence, Set, boost::mpl::insert<boost::mpl::_1, boost::mpl::_2>>::type;

using ProcessedAttributes =
    InsertAll<InsertAll<InsertAll<boost::mpl::set<>::type, svgpp::traits::shapes_attributes_by_element>,
                        StyleAttributes>,
              StructureAttributes>;

// SVG++'s minimal path events, except arcs: they come to ShapeContext as arcs, because SVG++
// converts them to cubics without SVG's special cases (a zero radius gave NaN).
struct PathEvents : svgpp::policy::path::minimal {
  static const bool arc_as_cubic_bezier = false;
};

using DocumentTraversal = svgpp::document_traversal<
    svgpp::processed_elements<ProcessedElements>, svgpp::processed_attributes<ProcessedAttributes>,
    svgpp::context_factories<ContextFactories>, svgpp::path_policy<PathEvents>,
    svgpp::length_policy<svgpp::policy::length::forward_to_method<NodeContext>>,
    svgpp::error_policy<ErrorPolicy>, svgpp::attribute_traversal_policy<AttributeOrder>>;

// ---------------------------------------------------------------------------------------
// Flattening. A cubic is cut into n equal parameter steps with n from Wang's bound: the
// distance between a Bézier of degree 3 and its chords is at most
// (3/4) · max|P_i − 2 P_{i+1} + P_{i+2}| / n², so n = ceil(sqrt(3 M / (4 tolerance))).
void flattenCubic(Vec2 p0, Vec2 p1, Vec2 p2, Vec2 p3, double tolerance, std::vector<Vec2>& out) {
  const double m = std::max(length(p0 - 2.0 * p1 + p2), length(p1 - 2.0 * p2 + p3));
  int n = 1;
  if (m > 0 && tolerance > 0)
    n = static_cast<int>(std::ceil(std::sqrt(0.75 * m / tolerance)));
  n = std::clamp(n, 1, kMaxSegmentsPerCubic);
  for (int i = 1; i < n; ++i) {
    const double t = static_cast<double>(i) / n, s = 1.0 - t;
    out.push_back(s * s * s * p0 + 3 * s * s * t * p1 + 3 * s * t * t * p2 + t * t * t * p3);
  }
  out.push_back(p3);
}

// The larger side of the box of subpaths' points and control points.
double curveExtent(const std::vector<CurveSubpath>& subpaths) {
  Box box;
  for (const CurveSubpath& subpath : subpaths) {
    box.add(subpath.start);
    for (const CurveSegment& segment : subpath.segments) {
      box.add(segment.end);
      if (segment.cubic) box.add(segment.control1), box.add(segment.control2);
    }
  }
  return box.empty() ? 0.0 : std::max(box.width(), box.height());
}

Subpath flatten(const CurveSubpath& curves, double tolerance) {
  std::vector<Vec2> points{curves.start};
  for (const CurveSegment& segment : curves.segments) {
    if (segment.cubic) flattenCubic(points.back(), segment.control1, segment.control2, segment.end, tolerance, points);
    else points.push_back(segment.end);
  }
  // Points closer than this are one point (arcs converted to cubics end a rounding error
  // away from where they should).
  const double samePoint = 1e-3 * tolerance;
  Subpath subpath;
  subpath.closed = curves.closed;
  for (Vec2 p : points)
    if (subpath.points.empty() || distance(subpath.points.back(), p) > samePoint) subpath.points.push_back(p);
  // A subpath that ends where it started encloses the same area with or without its "Z"
  // (MDI icons often omit it): treat it as closed.
  auto endsAtStart = [&] { return distance(subpath.points.back(), subpath.points.front()) <= samePoint; };
  if (!subpath.closed && subpath.points.size() > 3 && endsAtStart()) subpath.closed = true;
  if (subpath.closed && subpath.points.size() > 1 && endsAtStart()) subpath.points.pop_back();
  return subpath;
}

// ---------------------------------------------------------------------------------------
Color colorFrom(std::uint32_t rgb, double alpha) {
  return Color{static_cast<std::uint8_t>((rgb >> 16) & 0xff), static_cast<std::uint8_t>((rgb >> 8) & 0xff),
               static_cast<std::uint8_t>(rgb & 0xff), alpha};
}

std::optional<Color> resolveSolid(const SolidPaint& paint, std::uint32_t currentColor, double alpha) {
  switch (paint.kind) {
    case PaintKind::None: return std::nullopt;
    case PaintKind::CurrentColor: return colorFrom(currentColor, alpha);
    case PaintKind::Color: return colorFrom(paint.rgb, alpha);
  }
  return std::nullopt;
}

// Stops of a gradient, following xlink:href chains (Inkscape writes one gradient with the
// stops and another that references it).
const std::vector<GradientStop>* gradientStops(const ReaderState& state, const std::string& id) {
  std::string current = id;
  for (int hops = 0; hops < 16; ++hops) {
    auto it = state.gradients.find(current);
    if (it == state.gradients.end()) return nullptr;
    if (!it->second.stops.empty()) return &it->second.stops;
    if (it->second.href.empty()) return nullptr;
    current = it->second.href;
  }
  return nullptr;
}

std::optional<Color> resolvePaint(ReaderState& state, const Paint& paint, std::uint32_t currentColor,
                                  double alpha, const std::string& where) {
  if (paint.server.empty()) return resolveSolid(paint.solid, currentColor, alpha);
  if (const auto* stops = gradientStops(state, paint.server)) {
    double r = 0, g = 0, b = 0, a = 0;
    for (const GradientStop& stop : *stops) {
      r += (stop.rgb >> 16) & 0xff;
      g += (stop.rgb >> 8) & 0xff;
      b += stop.rgb & 0xff;
      a += stop.opacity;
    }
    const double n = static_cast<double>(stops->size());
    state.warn(where, "gradient #" + paint.server + " drawn with the mean colour of its stops");
    auto channel = [&](double sum) { return static_cast<std::uint8_t>(std::lround(sum / n)); };
    return Color{channel(r), channel(g), channel(b), alpha * a / n};
  }
  if (paint.fallback) return resolveSolid(*paint.fallback, currentColor, alpha);
  // A reference to nothing paints nothing, as in a browser (SVG 2: treated as none).
  if (!state.ids.count(paint.server)) {
    state.warn(where, "paint server #" + paint.server + " does not exist; not painted");
    return std::nullopt;
  }
  state.warn(where, "paint server #" + paint.server + " is not supported; painted grey");
  return colorFrom(0x808080, alpha);
}

// Every element without a namespace (a hand-written file without xmlns) or in the root's own
// namespace (Illustrator's xmlns="&ns_svg;" entity, which XML parsers without DTD support
// leave unexpanded) is treated as SVG, so that SVG++ walks into it.
void adoptSvgNamespace(XmlNode* root) {
  const std::string rootNamespace(root->namespace_uri(), root->namespace_uri_size());
  if (rootNamespace == kSvgNamespace) return;
  std::vector<XmlNode*> stack{root};
  while (!stack.empty()) {
    XmlNode* node = stack.back();
    stack.pop_back();
    if (node->type() != rapidxml_ns::node_element) continue;
    const std::string_view ns(node->namespace_uri(), node->namespace_uri_size());
    if (ns.empty() || ns == rootNamespace)
      node->namespace_uri(kSvgNamespace.data(), kSvgNamespace.size());
    for (XmlNode* child = node->first_node(); child; child = child->next_sibling()) stack.push_back(child);
  }
}

// ---------------------------------------------------------------------------------------
// Stylesheets. Illustrator writes its colours as `<style>.cls-1{fill:#f00}</style>` with
// class="cls-1" on the shapes; SVG++ reads only style="…". Rules with simple selectors
// (tag, .class, #id, tag.class, *) are folded into each matching element's style
// attribute, before its own declarations so that those still win, in order of
// specificity. Other selectors (descendants, pseudo-classes, attributes) are ignored.
struct CssRule {
  std::string tag, cssClass, id;  // empty: any
  int specificity = 0;
  int order = 0;
  std::string declarations;
};

std::string trimmed(std::string_view text) {
  std::size_t begin = 0, end = text.size();
  while (begin < end && std::isspace(static_cast<unsigned char>(text[begin]))) ++begin;
  while (end > begin && std::isspace(static_cast<unsigned char>(text[end - 1]))) --end;
  return std::string(text.substr(begin, end - begin));
}

std::optional<CssRule> simpleSelector(const std::string& selector) {
  if (selector.empty() || selector.find_first_of(" \t\n>+~:[") != std::string::npos) return std::nullopt;
  CssRule rule;
  if (selector == "*") return rule;
  std::size_t i = 0;
  auto name = [&] {
    const std::size_t start = i;
    while (i < selector.size() && selector[i] != '.' && selector[i] != '#') ++i;
    return selector.substr(start, i - start);
  };
  if (selector[0] != '.' && selector[0] != '#') {
    rule.tag = name();
    rule.specificity += 1;
  }
  while (i < selector.size()) {
    const char kind = selector[i++];
    const std::string value = name();
    if (value.empty() || (kind == '.' && !rule.cssClass.empty()) || (kind == '#' && !rule.id.empty()))
      return std::nullopt;  // a.b.c and the like: beyond these simple rules
    if (kind == '.') { rule.cssClass = value; rule.specificity += 10; }
    else { rule.id = value; rule.specificity += 100; }
  }
  return rule;
}

void parseStylesheet(std::string text, std::vector<CssRule>& rules) {
  for (std::size_t start; (start = text.find("/*")) != std::string::npos;) {
    const std::size_t end = text.find("*/", start + 2);
    text.erase(start, end == std::string::npos ? std::string::npos : end + 2 - start);
  }
  std::size_t i = 0;
  while (i < text.size()) {
    const std::size_t open = text.find('{', i);
    if (open == std::string::npos) break;
    std::string selectors = trimmed(std::string_view(text).substr(i, open - i));
    // Skip at-rules (@media …{…{…}}) as a whole block, counting braces.
    std::size_t close = open + 1;
    for (int depth = 1; close < text.size() && depth > 0; ++close) {
      if (text[close] == '{') ++depth;
      else if (text[close] == '}') --depth;
    }
    const std::string body = text.substr(open + 1, close - open - 2);
    i = close;
    if (selectors.empty() || selectors[0] == '@') continue;
    std::size_t from = 0;
    while (from <= selectors.size()) {
      std::size_t comma = selectors.find(',', from);
      if (comma == std::string::npos) comma = selectors.size();
      if (auto rule = simpleSelector(trimmed(std::string_view(selectors).substr(from, comma - from)))) {
        rule->declarations = trimmed(body);
        rule->order = static_cast<int>(rules.size());
        rules.push_back(std::move(*rule));
      }
      from = comma + 1;
    }
  }
}

bool hasClass(const std::string& classes, const std::string& wanted) {
  std::istringstream words(classes);
  for (std::string word; words >> word;)
    if (word == wanted) return true;
  return false;
}

template <class F>
void forEachElement(XmlNode* root, F&& f) {
  std::vector<XmlNode*> stack{root};
  while (!stack.empty()) {
    XmlNode* node = stack.back();
    stack.pop_back();
    if (node->type() != rapidxml_ns::node_element) continue;
    f(node);
    const std::size_t firstChild = stack.size();
    for (XmlNode* child = node->first_node(); child; child = child->next_sibling()) stack.push_back(child);
    std::reverse(stack.begin() + static_cast<std::ptrdiff_t>(firstChild), stack.end());  // document order
  }
}

// Returns the elements a rule styled: their source text lacks those colours.
std::set<const XmlNode*> applyStylesheets(rapidxml_ns::xml_document<char>& xml, XmlNode* root) {
  std::set<const XmlNode*> styled;
  std::vector<CssRule> rules;
  forEachElement(root, [&](XmlNode* node) {
    if (std::string_view(node->local_name(), node->local_name_size()) != "style") return;
    std::string text;
    for (XmlNode* child = node->first_node(); child; child = child->next_sibling())
      if (child->type() == rapidxml_ns::node_data || child->type() == rapidxml_ns::node_cdata)
        text.append(child->value(), child->value_size());
    parseStylesheet(text, rules);
  });
  if (rules.empty()) return styled;
  std::stable_sort(rules.begin(), rules.end(),
                   [](const CssRule& a, const CssRule& b) { return a.specificity < b.specificity; });
  forEachElement(root, [&](XmlNode* node) {
    const std::string tag(node->local_name(), node->local_name_size());
    const std::string classes = attributeOf(node, "class");
    const std::string id = attributeOf(node, "id");
    std::string style;
    for (const CssRule& rule : rules)
      if ((rule.tag.empty() || rule.tag == tag) && (rule.id.empty() || rule.id == id) &&
          (rule.cssClass.empty() || hasClass(classes, rule.cssClass)))
        style += rule.declarations + ";";
    if (style.empty()) return;
    styled.insert(node);
    rapidxml_ns::xml_attribute<char>* inline_ = nullptr;
    for (auto* a = node->first_attribute(); a; a = a->next_attribute())
      if (std::string_view(a->name(), a->name_size()) == "style") inline_ = a;
    if (inline_) {
      style.append(inline_->value(), inline_->value_size());
      inline_->value(xml.allocate_string(style.c_str(), style.size()), style.size());
    } else {
      const char* value = xml.allocate_string(style.c_str(), style.size());
      node->append_attribute(xml.allocate_attribute("style", value, 5, style.size()));
    }
  });
  return styled;
}

// rgb() with decimal components, which Inkscape writes, rounded for SVG++ (rgb_components.hpp):
// in the paint and colour attributes and in style (stylesheets already applied).
void roundRgbComponents(rapidxml_ns::xml_document<char>& xml, XmlNode* root) {
  constexpr std::string_view kColourAttributes[] = {"fill", "stroke", "color", "stop-color", "flood-color",
                                                    "lighting-color", "style"};
  forEachElement(root, [&](XmlNode* node) {
    for (auto* a = node->first_attribute(); a; a = a->next_attribute()) {
      const std::string_view name(a->local_name(), a->local_name_size());
      if (std::find(std::begin(kColourAttributes), std::end(kColourAttributes), name) == std::end(kColourAttributes))
        continue;
      if (const std::optional<std::string> rounded = roundedRgbComponents({a->value(), a->value_size()}))
        a->value(xml.allocate_string(rounded->c_str(), rounded->size()), rounded->size());
    }
  });
}

// Whether SVG++ parses the attribute `a` (with Boost.Spirit, whose character classes are
// undefined beyond ASCII): every SVG attribute but the free-text ones, names and labels.
bool parsedBySvgpp(const rapidxml_ns::xml_attribute<char>* a) {
  const std::string_view name(a->name(), a->name_size()), local(a->local_name(), a->local_name_size());
  if (local == "id" || local == "class" || local.starts_with("data-")) return false;
  // inkscape:label, sodipodi:…, xml:lang: prefixed attributes other than xlink are not SVG's.
  return name.find(':') == std::string_view::npos || name.starts_with("xlink:");
}

// Non-ASCII bytes in the values SVG++ parses become '?', in place: such a value (a colour
// "réd", a length "1０") is not valid SVG, so it is then skipped with a warning like any other
// unreadable value. The source text, which layers are copied from, keeps the bytes as written,
// and so does `folded`, which messages quote.
void asciiForSvgpp(XmlNode* root, std::vector<ReaderState::AsciiFolded>& folded) {
  forEachElement(root, [&](XmlNode* node) {
    for (auto* a = node->first_attribute(); a; a = a->next_attribute()) {
      if (!parsedBySvgpp(a)) continue;
      char* value = a->value();
      const std::size_t size = a->value_size();
      if (std::none_of(value, value + size, [](char c) { return static_cast<unsigned char>(c) >= 0x80; })) continue;
      folded.push_back({value, size, std::string(value, size)});
      for (std::size_t i = 0; i < size; ++i)
        if (static_cast<unsigned char>(value[i]) >= 0x80) value[i] = '?';
    }
  });
}

// The deepest element nesting under `root`, counted without recursion.
int nestingDepth(XmlNode* root) {
  int deepest = 0;
  std::vector<std::pair<XmlNode*, int>> stack{{root, 1}};
  while (!stack.empty()) {
    const auto [node, depth] = stack.back();
    stack.pop_back();
    deepest = std::max(deepest, depth);
    for (XmlNode* child = node->first_node(); child; child = child->next_sibling())
      if (child->type() == rapidxml_ns::node_element) stack.push_back({child, depth + 1});
  }
  return deepest;
}

// ---------------------------------------------------------------------------------------
// <use>, expanded as SVG defines it: the <use> becomes a <g> with its attributes, its
// transform followed by translate(x, y), holding a copy of the referenced element (a
// <symbol> copied as a <g>). The copy inherits from the <use>, not from where the original
// is, and is drawn even when the original sits in <defs>. Uses inside a copy are expanded in
// turn; a reference to the use's own ancestor (a cycle), nesting beyond kMaxUseDepth or more
// than kMaxUseCopies copied elements is a warning and draws nothing.
constexpr int kMaxUseDepth = 32;
constexpr std::size_t kMaxUseCopies = 20000;

// href="#id" or xlink:href="#id" (the copies' attributes lose their namespace: match the name).
std::string useReference(const XmlNode* node) {
  for (auto* a = node->first_attribute(); a; a = a->next_attribute()) {
    const std::string_view name(a->name(), a->name_size());
    const std::string_view local(a->local_name(), a->local_name_size());
    if (name == "href" || name == "xlink:href" || local == "href") return std::string(a->value(), a->value_size());
  }
  return {};
}

// A deep copy keeping the namespaces (rapidxml's clone_node drops them), names and values
// shared with the source.
XmlNode* copyElement(rapidxml_ns::xml_document<char>& xml, const XmlNode* source, std::size_t& copies) {
  XmlNode* copy = xml.allocate_node(source->type());
  copy->qname(source->name(), source->name_size(), source->local_name());
  copy->namespace_uri(source->namespace_uri(), source->namespace_uri_size());
  copy->value(source->value(), source->value_size());
  ++copies;
  for (auto* a = source->first_attribute(); a; a = a->next_attribute()) {
    auto* attribute = xml.allocate_attribute(a->name(), a->value(), a->name_size(), a->value_size());
    attribute->qname(a->name(), a->name_size(), a->local_name());
    attribute->namespace_uri(a->namespace_uri(), a->namespace_uri_size());
    copy->append_attribute(attribute);
  }
  for (const XmlNode* child = source->first_node(); child; child = child->next_sibling())
    copy->append_node(copyElement(xml, child, copies));
  return copy;
}

double useCoordinate(const XmlNode* node, std::string_view name) {
  const std::string text = attributeOf(node, name);
  if (text.empty()) return 0.0;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  return std::isfinite(value) && std::abs(value) <= kAbsurdCoordinate ? value : 0.0;
}

void expandUses(rapidxml_ns::xml_document<char>& xml, XmlNode* root, ReaderState& state, const LineIndex& lines) {
  std::map<std::string, const XmlNode*> byId;
  std::vector<std::pair<XmlNode*, int>> pending;  // a <use> and how deep in copies it is
  forEachElement(root, [&](XmlNode* node) {
    const std::string id = attributeOf(node, "id");
    if (!id.empty()) byId.emplace(id, node);
    if (std::string_view(node->local_name(), node->local_name_size()) == "use") pending.push_back({node, 0});
  });
  std::size_t copies = 0;
  bool overBudget = false;
  for (std::size_t next = 0; next < pending.size(); ++next) {
    // Plain variables, not a structured binding: the lambdas below capture them (clang 14,
    // which builds the fuzz targets, cannot capture a binding).
    XmlNode* const use = pending[next].first;
    const int depth = pending[next].second;
    const std::string id = attributeOf(use, "id");
    const std::string where = state.placeOf(use, "<use" + (id.empty() ? std::string() : " id=\"" + id + "\"") + ">");
    auto drop = [&](const std::string& why) {
      state.document->warnings.push_back({where, why});
      use->parent()->remove_node(use);
    };
    const std::string href = useReference(use);
    if (href.size() < 2 || href[0] != '#') {
      drop(href.empty() ? "<use> without href; skipped" : "<use> of \"" + href + "\" (another file) is not supported; skipped");
      continue;
    }
    const std::string target = href.substr(1);
    auto found = byId.find(target);
    if (found == byId.end()) {
      drop("<use> of #" + target + ": no element has that id; skipped");
      continue;
    }
    bool cycle = false;
    for (const XmlNode* up = use; up && !cycle; up = up->parent())
      if (up->type() == rapidxml_ns::node_element && attributeOf(up, "id") == target) cycle = true;
    if (cycle || found->second == use) {
      drop("<use> of #" + target + " refers to an element that contains it (a cycle); skipped");
      continue;
    }
    if (depth >= kMaxUseDepth) {
      drop("<use> of #" + target + " is nested more than " + std::to_string(kMaxUseDepth) + " uses deep; skipped");
      continue;
    }
    if (copies > kMaxUseCopies) {  // said once: the rest are skipped silently
      if (!overBudget)
        drop("<use> of #" + target + " and those after it: the document's uses copy more than " +
             std::to_string(kMaxUseCopies) + " elements; skipped");
      else
        use->parent()->remove_node(use);
      overBudget = true;
      continue;
    }
    (void)lines;
    XmlNode* group = xml.allocate_node(rapidxml_ns::node_element);
    group->name("g", 1);
    group->namespace_uri(kSvgNamespace.data(), kSvgNamespace.size());
    std::string transform = attributeOf(use, "transform");
    const double x = useCoordinate(use, "x"), y = useCoordinate(use, "y");
    if (x != 0.0 || y != 0.0) transform += " translate(" + formatNumber(x) + " " + formatNumber(y) + ")";
    for (auto* a = use->first_attribute(); a; a = a->next_attribute()) {
      const std::string_view name(a->name(), a->name_size());
      const std::string_view local(a->local_name(), a->local_name_size());
      if (name == "x" || name == "y" || name == "width" || name == "height" || name == "transform" || local == "href" ||
          name == "xlink:href")
        continue;
      auto* attribute = xml.allocate_attribute(a->name(), a->value(), a->name_size(), a->value_size());
      attribute->qname(a->name(), a->name_size(), a->local_name());
      attribute->namespace_uri(a->namespace_uri(), a->namespace_uri_size());
      group->append_attribute(attribute);
    }
    if (!transform.empty()) {
      const char* value = xml.allocate_string(transform.c_str(), transform.size());
      group->append_attribute(xml.allocate_attribute("transform", value, 9, transform.size()));
    }
    XmlNode* copy = copyElement(xml, found->second, copies);
    if (std::string_view(copy->local_name(), copy->local_name_size()) == "symbol") {
      copy->name("g", 1);
      copy->namespace_uri(kSvgNamespace.data(), kSvgNamespace.size());
    }
    group->append_node(copy);
    use->parent()->insert_node(use, group);
    use->parent()->remove_node(use);
    forEachElement(copy, [&](XmlNode* node) {
      if (std::string_view(node->local_name(), node->local_name_size()) == "use") pending.push_back({node, depth + 1});
    });
  }
}

std::string parseErrorPlace(const std::vector<char>& buffer, const char* where) {
  if (!where || where < buffer.data() || where > buffer.data() + buffer.size())
    return "";
  const std::size_t offset = static_cast<std::size_t>(where - buffer.data());
  int line = 1, column = 1;
  for (std::size_t i = 0; i < offset; ++i) {
    if (buffer[i] == '\n') { ++line; column = 1; }
    else ++column;
  }
  return " at line " + std::to_string(line) + ", column " + std::to_string(column) +
         " (byte offset " + std::to_string(offset) + ")";
}

class CurrentReaderScope {
 public:
  explicit CurrentReaderScope(ReaderState* state) : previous_(currentReader) { currentReader = state; }
  ~CurrentReaderScope() { currentReader = previous_; }
  CurrentReaderScope(const CurrentReaderScope&) = delete;
  CurrentReaderScope& operator=(const CurrentReaderScope&) = delete;

 private:
  ReaderState* previous_;
};


// ---------------------------------------------------------------------------------------
// The fixed layer, copied byte for byte. rapidxml parses in place, so a name or value it
// points at sits at the same offset in the source text as in its buffer; the source text
// around it is scanned for the element's extent (the document parsed, so it is well formed).
struct SourceText {
  const std::string& text;
  const std::vector<char>& buffer;

  // Offset in the source of a pointer into the buffer; npos for strings rapidxml or the
  // stylesheet pass made elsewhere (those are not the source's bytes).
  std::size_t offsetOf(const char* p) const {
    if (p < buffer.data() || p >= buffer.data() + text.size()) return std::string::npos;
    return static_cast<std::size_t>(p - buffer.data());
  }

  // Just past the '>' of the tag starting at `at` (quoted values may hold '>').
  std::size_t tagEnd(std::size_t at) const {
    char quote = 0;
    for (std::size_t i = at + 1; i < text.size(); ++i) {
      const char c = text[i];
      if (quote) { if (c == quote) quote = 0; }
      else if (c == '"' || c == '\'') quote = c;
      else if (c == '>') return i + 1;
    }
    return text.size();
  }

  // [start of the element's tag, end of its start tag, start of its end tag, end of the element].
  std::array<std::size_t, 4> extent(const XmlNode* node) const {
    const std::size_t name = offsetOf(node->name());
    if (name == std::string::npos || name == 0) return {0, 0, 0, 0};
    const std::size_t start = name - 1, open = tagEnd(start);
    if (text[open - 2] == '/') return {start, open, open, open};
    std::size_t i = open;
    for (int depth = 1; i < text.size();) {
      i = text.find('<', i);
      if (i == std::string::npos) break;
      auto skipPast = [&](const char* end) {
        const std::size_t at = text.find(end, i);
        return at == std::string::npos ? text.size() : at + std::strlen(end);
      };
      if (text.compare(i, 4, "<!--") == 0) i = skipPast("-->");
      else if (text.compare(i, 9, "<![CDATA[") == 0) i = skipPast("]]>");
      else if (text.compare(i, 2, "<?") == 0) i = skipPast("?>");
      else if (text.compare(i, 2, "</") == 0) {
        if (--depth == 0) return {start, open, i, tagEnd(i)};
        i = tagEnd(i);
      } else {
        const std::size_t end = tagEnd(i);
        if (text[i + 1] != '!' && text[end - 2] != '/') ++depth;
        i = end;
      }
    }
    return {start, open, text.size(), text.size()};
  }

  std::string between(std::size_t begin, std::size_t end) const { return text.substr(begin, end - begin); }

  // An attribute as written: name="value" with the source's quotes and escapes.
  std::string attribute(const rapidxml_ns::xml_attribute<char>* a) const {
    const std::string name(a->name(), a->name_size());
    const std::size_t value = offsetOf(a->value());
    if (value == std::string::npos || value == 0) return {};
    const char quote = text[value - 1];
    const std::size_t end = text.find(quote, value);
    return name + "=" + quote + between(value, end) + quote;
  }
};

// Ids an XML fragment points at: url(#id), url('#id'), href="#id" (xlink:href too).
std::vector<std::string> referencedIds(const std::string& text) {
  std::vector<std::string> ids;
  auto take = [&](std::size_t at, const char* stops) {
    const std::size_t end = text.find_first_of(stops, at);
    if (end != std::string::npos && end > at) ids.push_back(text.substr(at, end - at));
  };
  for (std::size_t at = text.find("url("); at != std::string::npos; at = text.find("url(", at + 4)) {
    std::size_t i = at + 4;
    while (i < text.size() && (text[i] == '\'' || text[i] == '"' || std::isspace(static_cast<unsigned char>(text[i])))) ++i;
    if (i < text.size() && text[i] == '#') take(i + 1, ")'\" \t\n");
  }
  for (std::size_t at = text.find("href="); at != std::string::npos; at = text.find("href=", at + 5))
    if (at + 6 < text.size() && (text[at + 5] == '"' || text[at + 5] == '\'') && text[at + 6] == '#')
      take(at + 7, "\"'");
  return ids;
}

void addNamespacesOf(const XmlNode* subtree, std::map<std::string, std::string>& namespaces) {
  auto add = [&](const char* prefix, std::size_t prefixSize, const char* uri, std::size_t uriSize) {
    const std::string p(prefix, prefixSize);
    if (p.empty() || p == "xml" || p == "xmlns" || uriSize == 0) return;
    namespaces.emplace(p, std::string(uri, uriSize));
  };
  forEachElement(const_cast<XmlNode*>(subtree), [&](XmlNode* node) {
    add(node->prefix(), node->prefix_size(), node->namespace_uri(), node->namespace_uri_size());
    for (auto* a = node->first_attribute(); a; a = a->next_attribute())
      add(a->prefix(), a->prefix_size(), a->namespace_uri(), a->namespace_uri_size());
  });
}

// The prefixes the root declares that a copy's text uses (`prefix:name`): names of elements
// the reader has replaced since (a <use>, expanded) are in the text only.
void addRootNamespacesUsedIn(const XmlNode* root, const RawMarkup& markup, std::map<std::string, std::string>& namespaces) {
  for (auto* a = root->first_attribute(); a; a = a->next_attribute()) {
    const std::string_view name(a->name(), a->name_size());
    if (name.substr(0, 6) != "xmlns:" || a->value_size() == 0) continue;
    const std::string prefix(name.substr(6));
    if (prefix == "xml" || prefix == "xmlns" || namespaces.count(prefix)) continue;
    auto uses = [&](const std::string& text) {
      for (std::size_t at = text.find(prefix + ":"); at != std::string::npos; at = text.find(prefix + ":", at + 1)) {
        const char before = at == 0 ? ' ' : text[at - 1];
        if (before == '<' || before == '/' || std::isspace(static_cast<unsigned char>(before))) return true;
      }
      return false;
    };
    if (uses(markup.content) || std::any_of(markup.definitions.begin(), markup.definitions.end(), uses))
      namespaces.emplace(prefix, std::string(a->value(), a->value_size()));
  }
}

// Whether a stylesheet rule styles an element of the subtree (`styled`: applyStylesheets's):
// the source's bytes would then lose the colours CSS classes gave them.
bool styledByStylesheet(const std::set<const XmlNode*>& styled, const XmlNode* subtree) {
  bool found = false;
  forEachElement(const_cast<XmlNode*>(subtree), [&](XmlNode* node) { found = found || styled.count(node) > 0; });
  return found;
}

using Extent = std::array<std::size_t, 4>;  // SourceText::extent
using IdIndex = std::map<std::string, const XmlNode*>;

IdIndex elementsById(XmlNode* root) {
  IdIndex byId;
  forEachElement(root, [&](XmlNode* node) {
    const std::string id = attributeOf(node, "id");
    if (!id.empty()) byId.emplace(id, node);
  });
  return byId;
}

// The definitions `references` points at, and those they reference in turn (a gradient's
// xlink:href), each once, into markup.definitions; those inside `copied` (the copy's own
// extents) already travel with it.
void addDefinitions(RawMarkup& markup, const std::string& references, std::vector<Extent> copied, const IdIndex& byId,
                    const SourceText& source, std::map<std::string, std::string>& namespaces) {
  auto isCopied = [&](const Extent& e) {
    return std::any_of(copied.begin(), copied.end(), [&](const Extent& c) { return e[0] >= c[0] && e[3] <= c[3]; });
  };
  std::vector<std::string> pending = referencedIds(references);
  std::set<std::string> seen;
  while (!pending.empty()) {
    const std::string id = pending.back();
    pending.pop_back();
    if (!seen.insert(id).second) continue;
    auto it = byId.find(id);
    if (it == byId.end()) continue;
    const Extent extent = source.extent(it->second);
    if (extent[0] == extent[3] || isCopied(extent)) continue;
    copied.push_back(extent);
    std::string text = source.between(extent[0], extent[3]);
    addNamespacesOf(it->second, namespaces);
    for (std::string& more : referencedIds(text)) pending.push_back(std::move(more));
    markup.definitions.push_back(std::move(text));
  }
}

// The fixed layers' children as written, wrapped in a <g> that places them as the input did
// (the layer's transform and those of its ancestors, the ancestors' opacity) and one that
// keeps the layer's own presentation attributes; the definitions they reference; the
// namespaces their names use.
RawMarkup fixedLayerMarkup(ReaderState& state, const SourceText& source, const XmlNode* root, const IdIndex& byId,
                           const std::set<const XmlNode*>& styled) {
  RawMarkup markup;
  if (state.fixedLayers.empty()) return markup;
  std::map<std::string, std::string> namespaces;
  std::vector<Extent> copied;  // extents already in the output
  std::string references;
  for (const FixedLayerSource& layer : state.fixedLayers) {
    if (styledByStylesheet(styled, layer.node)) {
      state.warn("fixed layer", "styled by a <style> sheet: the output re-draws it instead of copying it");
      return {};
    }
  }
  for (const FixedLayerSource& layer : state.fixedLayers) {
    const Extent extent = source.extent(layer.node);
    if (extent[0] == extent[3]) continue;
    copied.push_back(extent);
    const Affine& m = layer.ctm;
    std::string outer = "<g";
    if (m.a != 1 || m.b != 0 || m.c != 0 || m.d != 1 || m.e != 0 || m.f != 0)
      outer += " transform=\"matrix(" + formatNumber(m.a) + " " + formatNumber(m.b) + " " + formatNumber(m.c) + " " +
               formatNumber(m.d) + " " + formatNumber(m.e) + " " + formatNumber(m.f) + ")\"";
    if (layer.inheritedOpacity < 1.0) outer += " opacity=\"" + formatNumber(layer.inheritedOpacity) + "\"";
    std::string inner = "<g";
    for (auto* a = layer.node->first_attribute(); a; a = a->next_attribute()) {
      const std::string_view name(a->name(), a->name_size());
      if (a->prefix_size() > 0 || name == "id" || name == "transform" || name == "xmlns") continue;
      const std::string written = source.attribute(a);
      if (!written.empty()) inner += " " + written;
    }
    const std::string children = source.between(extent[1], extent[2]);
    references += inner + children;
    markup.content += outer + ">" + inner + ">" + children + "</g></g>";
    addNamespacesOf(layer.node, namespaces);
  }
  if (markup.content.empty()) return markup;
  addDefinitions(markup, references, copied, byId, source, namespaces);
  addRootNamespacesUsedIn(root, markup, namespaces);
  markup.namespaces.assign(namespaces.begin(), namespaces.end());
  return markup;
}

// Each top-level group as written, its own tag included: a group at the top of the document
// has no ancestor that moves or fades it, so its bytes alone draw it where it is.
void topGroupMarkups(ReaderState& state, const SourceText& source, const XmlNode* root, const IdIndex& byId,
                     const std::set<const XmlNode*>& styled) {
  std::vector<SvgTopGroup>& groups = state.document->topGroups;
  for (std::size_t k = 0; k < groups.size() && k < state.topGroupNodes.size(); ++k) {
    const XmlNode* node = state.topGroupNodes[k];
    if (styledByStylesheet(styled, node)) {
      groups[k].styledBySheet = true;
      continue;
    }
    const Extent extent = source.extent(node);
    if (extent[0] == extent[3]) continue;
    RawMarkup& markup = groups[k].markup;
    markup.content = source.between(extent[0], extent[3]);
    std::map<std::string, std::string> namespaces;
    addNamespacesOf(node, namespaces);
    addDefinitions(markup, markup.content, {extent}, byId, source, namespaces);
    addRootNamespacesUsedIn(root, markup, namespaces);
    markup.namespaces.assign(namespaces.begin(), namespaces.end());
  }
}

}  // namespace

// ---------------------------------------------------------------------------------------
// Clip paths. The region a shape may paint: the intersection of its clip paths and its
// groups' (each the union of its shapes under their clip-rule, in the user space of the
// element that references it). nullopt: no clip applies (missing or unsupported, with a
// warning).
Region asRegion(const std::vector<ClipShape>& shapes, const Affine& m, double tolerance, const ClipOptions& options) {
  std::vector<Region> parts;
  for (const ClipShape& clip : shapes) {
    std::vector<Ring> rings;
    for (const CurveSubpath& curves : clip.subpaths) {
      CurveSubpath placed = curves;
      placed.start = m.apply(placed.start);
      for (CurveSegment& segment : placed.segments) {
        segment.control1 = m.apply(segment.control1);
        segment.control2 = m.apply(segment.control2);
        segment.end = m.apply(segment.end);
      }
      Subpath subpath = flatten(placed, tolerance);
      if (subpath.points.size() >= 3) rings.push_back(std::move(subpath.points));
    }
    if (!rings.empty()) parts.push_back(regionFromRings(rings, clip.rule, options));
  }
  if (parts.empty()) return {};
  return parts.size() == 1 ? parts.front() : unite(parts, options);
}

ClipOptions clipOptionsFor(double tolerance) { return ClipOptions{std::max(tolerance * 0.01, 1e-9)}; }

std::optional<Region> clipRegion(ReaderState& state, const PendingShape& pending, double tolerance) {
  const ClipOptions options = clipOptionsFor(tolerance);
  std::optional<Region> result;
  for (const ClipUse& use : pending.clips) {
    auto found = state.clipPaths.find(use.id);
    if (found == state.clipPaths.end()) {
      state.warn(pending.description, "clip-path #" + use.id + ": no <clipPath> has that id; drawn unclipped");
      continue;
    }
    if (state.boundingBoxClips.count(use.id)) {
      state.warn(pending.description, "clip-path #" + use.id +
                                          ": clipPathUnits=\"objectBoundingBox\" is not supported; drawn unclipped");
      continue;
    }
    Region region = asRegion(found->second, use.ctm, tolerance, options);
    result = result ? intersect(*result, region, options) : region;
  }
  return result;
}

void appendRegion(SvgShape& shape, const Region& region) {
  for (const Polygon& polygon : region) {
    shape.subpaths.push_back({polygon.outer, true});
    for (const Ring& hole : polygon.holes) shape.subpaths.push_back({hole, true});
  }
}

// A stroke under a stretching transform, as a browser draws it: outlined in the shape's own
// coordinates, where it has one width, then transformed. It becomes a second shape filling
// the band in the stroke's colour; the first keeps the fill. A transform that cannot be
// undone keeps the stroke as it is.
std::vector<SvgShape> withStretchedStroke(SvgShape shape, const PendingShape& pending, double tolerance) {
  const std::optional<Affine> back = pending.stretch ? inverse(*pending.stretch) : std::nullopt;
  if (!back || !shape.stroke || !(shape.strokeWidth > 0.0)) return {std::move(shape)};
  const Affine& m = *pending.stretch;
  Shape local = shape;
  local.fill.reset();
  local.strokeWidth = pending.localStrokeWidth;
  for (Subpath& subpath : local.subpaths)
    for (Vec2& p : subpath.points) p = back->apply(p);
  // The grid fine enough after the transform's largest stretch.
  const double largest = std::sqrt(std::max(m.a * m.a + m.b * m.b, m.c * m.c + m.d * m.d));
  Region band = paintedRegion(local, clipOptionsFor(tolerance / std::max(largest, 1e-12)));
  for (Polygon& polygon : band) {
    for (Vec2& p : polygon.outer) p = m.apply(p);
    for (Ring& hole : polygon.holes)
      for (Vec2& p : hole) p = m.apply(p);
  }
  normalizeOrientation(band);  // a mirroring transform turns the rings around

  std::vector<SvgShape> out;
  SvgShape stroke = shape;
  stroke.subpaths.clear();
  stroke.fill = shape.stroke;
  stroke.stroke.reset();
  stroke.fillRule = FillRule::EvenOdd;  // disjoint polygons with their holes
  if (!stroke.id.empty() && shape.fill) stroke.id += "-stroke";  // ids stay unique
  appendRegion(stroke, band);
  shape.stroke.reset();
  // The fill of open lines (SVG's default black on a path drawn as a stroke) paints nothing.
  const ClipOptions options = clipOptionsFor(tolerance);
  if (shape.fill && area(filledRegion(shape, options)) > 0.0) out.push_back(std::move(shape));
  if (!stroke.subpaths.empty()) out.push_back(std::move(stroke));
  return out;
}

// The shape cut by the clip: its fill as the clipped filled region; its stroke, when it has
// one, as a second shape filling the clipped stroke band in the stroke's colour.
std::vector<SvgShape> clippedShapes(const SvgShape& shape, const Region& clip, double tolerance) {
  const ClipOptions options = clipOptionsFor(tolerance);
  std::vector<SvgShape> out;
  SvgShape base = shape;
  base.subpaths.clear();
  base.stroke.reset();
  base.dashArray.clear();
  base.fillRule = FillRule::EvenOdd;  // disjoint polygons with their holes
  if (shape.fill) {
    SvgShape fill = base;
    appendRegion(fill, intersect(filledRegion(shape, options), clip, options));
    if (!fill.subpaths.empty()) out.push_back(std::move(fill));
  }
  if (shape.stroke && shape.strokeWidth > 0.0) {
    Shape strokeOnly = shape;
    strokeOnly.fill.reset();
    SvgShape stroke = base;
    stroke.fill = shape.stroke;
    if (!stroke.id.empty() && shape.fill) stroke.id += "-stroke";  // ids stay unique
    appendRegion(stroke, intersect(paintedRegion(strokeOnly, options), clip, options));
    if (!stroke.subpaths.empty()) out.push_back(std::move(stroke));
  }
  return out;
}

SvgDocument readSvgString(const std::string& input, const std::string& name, const SvgReadOptions& options) {
  SvgDocument document;
  document.file = name;
  if (!(options.flatness > 0) || !std::isfinite(options.flatness))
    throw InputError(name, "flatness must be a positive number, got " + formatNumber(options.flatness));
  // The input boundary: from here on, and in every output, text is UTF-8.
  std::size_t notUtf8 = 0;
  const std::string text = validUtf8(input, &notUtf8);
  if (notUtf8 > 0)
    document.warnings.push_back({name, "the file is not UTF-8: " + std::to_string(notUtf8) +
                                           " byte(s) replaced by U+FFFD (save it as UTF-8)"});
  checkXmlNesting(text, name);  // before rapidxml and SVG++, which recurse per level

  // rapidxml parses in place and keeps pointers into the buffer: it must outlive the walk.
  std::vector<char> buffer(text.begin(), text.end());
  buffer.push_back('\0');
  rapidxml_ns::xml_document<char> xml;
  try {
    xml.parse<rapidxml_ns::parse_default>(buffer.data());
  } catch (const rapidxml_ns::parse_error& e) {
    throw InputError(name, std::string("not a valid XML document: ") + e.what() +
                               parseErrorPlace(buffer, e.where<char>()));
  }
  XmlNode* root = xml.first_node();
  while (root && root->type() != rapidxml_ns::node_element) root = root->next_sibling();
  if (!root) throw InputError(name, "not an SVG document: the XML has no root element");
  const std::string rootName(root->local_name(), root->local_name_size());
  if (rootName != "svg")
    throw InputError(name, "not an SVG document: the root element is <" + rootName + ">, not <svg>");
  adoptSvgNamespace(root);
  const std::set<const XmlNode*> styled = applyStylesheets(xml, root);
  roundRgbComponents(xml, root);

  const LineIndex lines(buffer);
  ReaderState state;
  state.file = name;
  state.lines = &lines;
  state.document = &document;
  expandUses(xml, root, state, lines);
  if (nestingDepth(root) > kMaxXmlNesting)
    throw InputError(name, "elements nested more than " + std::to_string(kMaxXmlNesting) +
                               " deep once <use> copies are expanded");
  asciiForSvgpp(root, state.asciiFolded);
  forEachElement(root, [&](XmlNode* node) {
    if (std::string id = attributeOf(node, "id"); !id.empty()) state.ids.insert(std::move(id));
  });
  state.lengths.set_viewport_size(0, 0);  // no percentages until a viewBox or size is known
  {
    CurrentReaderScope scope(&state);
    NodeContext rootContext(state, root);
    try {
      DocumentTraversal::load_document(static_cast<const XmlNode*>(root), rootContext);
    } catch (const InputError&) {
      throw;
    } catch (const std::exception& e) {
      throw InputError(state.placeOf(state.currentNode, state.currentElement), e.what());
    }
  }

  state.currentTopGroup = -1;  // what follows is about the document
  {
    const SourceText source{text, buffer};
    const IdIndex byId = elementsById(root);
    document.fixedMarkup = fixedLayerMarkup(state, source, root, byId, styled);
    topGroupMarkups(state, source, root, byId, styled);
  }

  // The document's coordinate box: viewBox, else the size, else the drawing itself.
  Box drawingBounds;
  for (const PendingShape& pending : state.shapes)
    for (const CurveSubpath& subpath : pending.subpaths) {
      drawingBounds.add(subpath.start);
      for (const CurveSegment& segment : subpath.segments) drawingBounds.add(segment.end);
    }
  if (state.viewBox) {
    document.viewBox = *state.viewBox;
  } else if (state.width && state.height) {
    document.viewBox.add(Vec2{0, 0});
    document.viewBox.add(Vec2{*state.width, *state.height});
  } else if (!drawingBounds.empty()) {
    document.viewBox = drawingBounds;
    document.warnings.push_back({name, "no viewBox and no width/height: using the drawing's bounds"});
  }
  if (state.viewBox || (state.width && state.height)) {
    if (state.width) document.widthText = trimmedView(attributeOf(root, "width"));
    if (state.height) document.heightText = trimmedView(attributeOf(root, "height"));
  }
  document.width = state.width.value_or(document.viewBox.empty() ? 0.0 : document.viewBox.width());
  document.height = state.height.value_or(document.viewBox.empty() ? 0.0 : document.viewBox.height());

  double extent = document.viewBox.empty() ? 0.0 : std::max(document.viewBox.width(), document.viewBox.height());
  if (!(extent > 0) && !drawingBounds.empty()) extent = std::max(drawingBounds.width(), drawingBounds.height());
  const double tolerance = extent > 0 ? options.flatness * extent : options.flatness;

  for (PendingShape& pending : state.shapes) {
    state.currentTopGroup = pending.shape.topGroup;
    // A shape far larger than the document (sheared by skewX(89.9999), say) is flattened
    // relative to its own size: per the document's, its curves would make thousands of
    // almost collinear points, on which the boolean operations take minutes. (Clip paths and
    // strokes keep the document's tolerance, and with it the clipping precision.)
    const double flattening = std::max(tolerance, options.flatness * curveExtent(pending.subpaths));
    SvgShape shape = std::move(pending.shape);
    // A zero-length subpath (`M4 20h0`, a dot in outline icons) is painted by round and
    // square caps; it is kept as one point.
    const bool strokesDots = pending.stroke.solid.kind != PaintKind::None || !pending.stroke.server.empty();
    const bool dots = strokesDots && shape.strokeWidth > 0.0 && shape.lineCap != StrokeCap::Butt;
    for (const CurveSubpath& curves : pending.subpaths) {
      shape.drawnPoints += 1;
      for (const CurveSegment& segment : curves.segments) shape.drawnPoints += segment.cubic ? 3 : 1;
      Subpath subpath = flatten(curves, flattening);
      const bool dot = dots && subpath.points.size() == 1 && (!curves.segments.empty() || curves.closed);
      if (dot) subpath.closed = false;
      if (subpath.points.size() >= 2 || dot) shape.subpaths.push_back(std::move(subpath));
    }
    if (shape.subpaths.empty()) {
      state.warn(pending.description, "no drawable geometry; skipped");
      continue;
    }
    shape.fill = resolvePaint(state, pending.fill, pending.color, pending.fillOpacity, pending.description);
    shape.stroke = resolvePaint(state, pending.stroke, pending.color, pending.strokeOpacity, pending.description);
    // The geometry routines know no file: what they reject is said to be this shape's.
    try {
      std::optional<Region> clip = pending.clips.empty() ? std::nullopt : clipRegion(state, pending, tolerance);
      if (clip && shape.stroke && !shape.dashArray.empty())
        state.warn(pending.description, "stroke-dasharray under a clip-path: the clipped stroke is drawn solid");
      std::vector<SvgShape> parts = withStretchedStroke(std::move(shape), pending, tolerance);
      for (SvgShape& part : parts) {
        if (!clip) {
          document.shapes.push_back(std::move(part));
          continue;
        }
        for (SvgShape& clipped : clippedShapes(part, *clip, tolerance)) document.shapes.push_back(std::move(clipped));
      }
    } catch (const InputError& error) {
      throw attributed(error, name + ": " + pending.description);
    }
  }
  state.currentTopGroup = -1;
  return document;
}

SvgDocument readSvgFile(const std::string& path, const SvgReadOptions& options) {
  return readSvgString(readTextFile(path), path, options);
}

}  // namespace pak
