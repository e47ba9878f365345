#include "pak/geom/clipping.hpp"

#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "pak/error.hpp"
#include "pak/limits.hpp"

namespace pak {
namespace {

namespace cl = ClipperLib;

// Clipper's exact arithmetic covers |coordinate| < 2^62; stay well inside it.
constexpr double kMaxScaledCoordinate = 1e18;
// Up to this many rings, regionFromRings is one Clipper union (results as they always were);
// beyond, it splits them into runs apart in x first (see there).
constexpr std::size_t kRingsUnitedAtOnce = 4096;

double scaleFor(double precision) {
  if (!(precision > 0.0) || !std::isfinite(precision))
    throw InputError("", "clipping precision must be a positive number");
  return 1.0 / precision;
}

cl::IntPoint toInt(Vec2 p, double scale) {
  const double x = p.x * scale, y = p.y * scale;
  if (!std::isfinite(x) || !std::isfinite(y)) throw InputError("", "non-finite coordinate in geometry");
  if (std::abs(x) > kMaxScaledCoordinate || std::abs(y) > kMaxScaledCoordinate) {
    std::ostringstream what;
    what << "coordinate (" << p.x << ", " << p.y << ") is too large for clipping precision "
         << 1.0 / scale;
    throw InputError("", what.str());
  }
  return {static_cast<cl::cInt>(std::llround(x)), static_cast<cl::cInt>(std::llround(y))};
}

// `wantPositive`: force Clipper's orientation (true: positive area) so that a non-zero fill
// of outer rings and holes gives the intended region whatever the caller's orientation.
cl::Path toPath(const Ring& ring, double scale, bool wantPositive) {
  cl::Path path;
  path.reserve(ring.size());
  for (Vec2 p : ring) path.push_back(toInt(p, scale));
  if (path.size() >= 3 && cl::Orientation(path) != wantPositive) std::reverse(path.begin(), path.end());
  return path;
}

cl::Paths toPaths(const Region& region, double scale) {
  cl::Paths paths;
  for (const Polygon& polygon : region) {
    if (polygon.outer.size() < 3) continue;
    paths.push_back(toPath(polygon.outer, scale, true));
    for (const Ring& hole : polygon.holes)
      if (hole.size() >= 3) paths.push_back(toPath(hole, scale, false));
  }
  return paths;
}

Ring toRing(const cl::Path& path, double scale) {
  Ring ring;
  ring.reserve(path.size());
  const double inv = 1.0 / scale;
  for (const cl::IntPoint& p : path)
    ring.push_back({static_cast<double>(p.X) * inv, static_cast<double>(p.Y) * inv});
  return ring;
}

// An outer node holds its holes as children; islands inside a hole are the hole's children.
void collectOuter(const cl::PolyNode& node, double scale, Region& out) {
  Polygon polygon;
  polygon.outer = toRing(node.Contour, scale);
  for (const cl::PolyNode* hole : node.Childs) {
    polygon.holes.push_back(toRing(hole->Contour, scale));
    for (const cl::PolyNode* island : hole->Childs) collectOuter(*island, scale, out);
  }
  normalizeOrientation(polygon);
  out.push_back(std::move(polygon));
}

Region toRegion(const cl::PolyTree& tree, double scale) {
  Region region;
  for (const cl::PolyNode* top : tree.Childs) collectOuter(*top, scale, region);
  return region;
}

cl::PolyFillType toClipper(FillRule rule) {
  return rule == FillRule::EvenOdd ? cl::pftEvenOdd : cl::pftNonZero;
}

// Clipper reports what it cannot represent by throwing its own exception; it is the input's
// fault (a coordinate or an offset too large), so it becomes an InputError the caller places.
template <class Run>
void clipperGuarded(const Run& run) {
  try {
    run();
  } catch (const cl::clipperException& e) {
    throw InputError("", std::string("geometry too large to clip (") + e.what() + ")");
  }
}

Region runBoolean(cl::ClipType type, const cl::Paths& subject, const cl::Paths& clip, double scale) {
  cl::Clipper clipper;
  cl::PolyTree tree;
  clipperGuarded([&] {
    clipper.AddPaths(subject, cl::ptSubject, true);
    clipper.AddPaths(clip, cl::ptClip, true);
    clipper.Execute(type, tree, cl::pftNonZero, cl::pftNonZero);
  });
  return toRegion(tree, scale);
}

// The offset's result reaches |delta| beyond its input: it must stay in Clipper's range too.
Region runOffset(cl::ClipperOffset& offsetter, double delta, double scale) {
  if (!(std::abs(delta * scale) <= kMaxScaledCoordinate))
    throw InputError("", "offset distance " + messageNumber(delta) + " is too large for clipping precision " +
                             messageNumber(1.0 / scale));
  cl::PolyTree tree;
  clipperGuarded([&] { offsetter.Execute(tree, delta * scale); });
  return toRegion(tree, scale);
}

// The arc tolerance an offset by `delta` uses: the asked one, but never so fine that the arcs
// take millions of points (the budget on Clipper's work for offsets).
double arcToleranceFor(double delta, const OffsetOptions& options) {
  return std::max(options.arcTolerance, std::abs(delta) * limits::kMinArcToleranceShare);
}

void checkOffsetOptions(double delta, const OffsetOptions& options) {
  if (!std::isfinite(delta)) throw InputError("", "offset distance must be finite");
  if (!(options.arcTolerance > 0.0) || !std::isfinite(options.arcTolerance))
    throw InputError("", "offset arc tolerance must be a positive number");
}

Region uniteRings(const cl::Paths& paths, FillRule rule, double scale) {
  cl::Clipper clipper;
  cl::PolyTree tree;
  clipperGuarded([&] {
    clipper.AddPaths(paths, cl::ptSubject, true);
    clipper.Execute(cl::ctUnion, tree, toClipper(rule), toClipper(rule));
  });
  return toRegion(tree, scale);
}

// The rings in runs whose x-extents are apart (a gap between each run and the next), left to
// right; rings of different runs cannot meet, so each run is united alone.
std::vector<cl::Paths> columnsApart(cl::Paths paths) {
  std::vector<std::pair<cl::cInt, cl::cInt>> extents;  // (min x, max x) of each path
  for (const cl::Path& path : paths) {
    cl::cInt low = path.front().X, high = low;
    for (const cl::IntPoint& p : path) low = std::min(low, p.X), high = std::max(high, p.X);
    extents.push_back({low, high});
  }
  std::vector<std::size_t> order(paths.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return extents[a].first < extents[b].first; });
  std::vector<cl::Paths> runs;
  cl::cInt reach = 0;
  for (std::size_t i : order) {
    if (runs.empty() || extents[i].first > reach) {
      runs.emplace_back();
      reach = extents[i].second;
    }
    reach = std::max(reach, extents[i].second);
    runs.back().push_back(std::move(paths[i]));
  }
  return runs;
}

}  // namespace

Region regionFromRings(const std::vector<Ring>& rings, FillRule rule, const ClipOptions& options) {
  const double scale = scaleFor(options.precision);
  cl::Paths paths;
  for (const Ring& ring : rings) {
    if (ring.size() < 3) continue;
    cl::Path path;
    path.reserve(ring.size());
    for (Vec2 p : ring) path.push_back(toInt(p, scale));
    paths.push_back(std::move(path));
  }
  if (paths.size() <= kRingsUnitedAtOnce) return uniteRings(paths, rule, scale);
  // Clipper's sweep costs each ring the rings beside it (its active edge list is a linked
  // list): 120,000 tiny subpaths side by side took a second a union. Runs of rings apart in x
  // are united one by one, the same region; few rings keep one union and its polygon order.
  Region region;
  for (const cl::Paths& run : columnsApart(std::move(paths))) {
    Region part = uniteRings(run, rule, scale);
    region.insert(region.end(), std::make_move_iterator(part.begin()), std::make_move_iterator(part.end()));
  }
  return region;
}

Region unite(const Region& a, const Region& b, const ClipOptions& options) {
  const double scale = scaleFor(options.precision);
  return runBoolean(cl::ctUnion, toPaths(a, scale), toPaths(b, scale), scale);
}

Region unite(const std::vector<Region>& regions, const ClipOptions& options) {
  const double scale = scaleFor(options.precision);
  cl::Paths all;
  for (const Region& region : regions) {
    cl::Paths paths = toPaths(region, scale);
    all.insert(all.end(), paths.begin(), paths.end());
  }
  return runBoolean(cl::ctUnion, all, {}, scale);
}

Region subtract(const Region& a, const Region& b, const ClipOptions& options) {
  const double scale = scaleFor(options.precision);
  return runBoolean(cl::ctDifference, toPaths(a, scale), toPaths(b, scale), scale);
}

Region intersect(const Region& a, const Region& b, const ClipOptions& options) {
  const double scale = scaleFor(options.precision);
  return runBoolean(cl::ctIntersection, toPaths(a, scale), toPaths(b, scale), scale);
}

Region offset(const Region& region, double delta, const OffsetOptions& options) {
  checkOffsetOptions(delta, options);
  const double scale = scaleFor(options.precision);
  cl::ClipperOffset offsetter(2.0, arcToleranceFor(delta, options) * scale);
  offsetter.AddPaths(toPaths(region, scale), cl::jtRound, cl::etClosedPolygon);
  return runOffset(offsetter, delta, scale);
}

Region offsetPolyline(const Polyline& line, double delta, const OffsetOptions& options) {
  checkOffsetOptions(delta, options);
  if (line.empty() || delta <= 0.0) return {};
  const double scale = scaleFor(options.precision);
  cl::Path path;
  path.reserve(line.size());
  for (Vec2 p : line) path.push_back(toInt(p, scale));
  cl::ClipperOffset offsetter(2.0, arcToleranceFor(delta, options) * scale);
  offsetter.AddPath(path, cl::jtRound, cl::etOpenRound);
  return runOffset(offsetter, delta, scale);
}

}  // namespace pak

namespace pak {

Region strokeOutline(const Polyline& line, bool closed, double delta, const StrokeStyle& style,
                     const OffsetOptions& options) {
  checkOffsetOptions(delta, options);
  if (line.empty() || delta <= 0.0) return {};
  const double scale = scaleFor(options.precision);
  cl::Path path;
  path.reserve(line.size());
  for (Vec2 p : line) {
    const cl::IntPoint q = toInt(p, scale);
    if (path.empty() || !(path.back() == q)) path.push_back(q);
  }
  if (closed && path.size() > 1 && path.front() == path.back()) path.pop_back();
  // A zero-length subpath: SVG draws a dot for round and square caps, nothing for butt ones
  // (the square is axis-aligned: the subpath has no direction).
  if (path.size() == 1) {
    if (style.cap == StrokeCap::Butt) return {};
    const Vec2 c = line.front();
    if (style.cap == StrokeCap::Square) {
      Polygon square{{{c.x - delta, c.y - delta}, {c.x + delta, c.y - delta}, {c.x + delta, c.y + delta},
                      {c.x - delta, c.y + delta}},
                     {}};
      normalizeOrientation(square);
      return {square};
    }
    // Round: Clipper turns a one-point path with a round join into a disc.
    cl::ClipperOffset offsetter(2.0, arcToleranceFor(delta, options) * scale);
    offsetter.AddPath(path, cl::jtRound, cl::etOpenRound);
    return runOffset(offsetter, delta, scale);
  }
  // Clipper's miter limit is in multiples of delta, the distance SVG's limit bounds too
  // (miter length / stroke width = distance of the miter tip / half width); below 2 it uses 2.
  // Clipper has no bevel: its square join cuts the corner at delta, just outside SVG's bevel.
  const cl::JoinType join = style.join == StrokeJoin::Miter   ? cl::jtMiter
                            : style.join == StrokeJoin::Bevel ? cl::jtSquare
                                                              : cl::jtRound;
  cl::EndType end = cl::etClosedLine;
  if (!closed || path.size() < 3)
    end = style.cap == StrokeCap::Butt ? cl::etOpenButt : style.cap == StrokeCap::Square ? cl::etOpenSquare : cl::etOpenRound;
  cl::ClipperOffset offsetter(std::max(1.0, style.miterLimit), arcToleranceFor(delta, options) * scale);
  offsetter.AddPath(path, join, end);
  return runOffset(offsetter, delta, scale);
}

}  // namespace pak
