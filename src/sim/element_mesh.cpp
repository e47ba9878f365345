#include "pak/sim/element_mesh.hpp"

#include <algorithm>
#include <functional>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <set>
#include <utility>

#include "pak/error.hpp"
#include "pak/geom/blue_noise.hpp"
#include "pak/geom/clipping.hpp"
#include "pak/geom/closest_point.hpp"
#include "pak/geom/resample.hpp"
#include "pak/geom/triangulation.hpp"

namespace pak {

Polygon elementSkin(const Region& outline, double gap, double arcTolerance) {
  OffsetOptions offsetOptions;
  offsetOptions.arcTolerance = arcTolerance;
  Region skin = fillHoles(offset(outline, gap / 2, offsetOptions));
  // Art made of separate pieces: close the gaps between them (grow then shrink by the same
  // amount) until one polygon remains.
  double closing = std::max(gap, 1e-6);
  for (int attempt = 0; skin.size() > 1 && attempt < 12; ++attempt, closing *= 2) {
    Region grown = offset(skin, closing, offsetOptions);
    skin = fillHoles(offset(fillHoles(grown), -closing, offsetOptions));
  }
  if (skin.empty()) return {};
  // Any remaining stray piece is tiny: keep the largest.
  auto largest = std::max_element(skin.begin(), skin.end(),
                                   [](const Polygon& a, const Polygon& b) { return area(a) < area(b); });
  Polygon result{largest->outer, {}};
  normalizeOrientation(result);
  return result;
}

namespace {

// Uniform samples along the first `1 / pieces` of the skin's arclength every `spacing`, plus
// the skin vertex farthest inside any chord that cuts more than `tolerance` into the skin
// (recursively), so that sharp tips such as ears and tails stay inside the mesh instead of
// hanging outside it.
Ring sampleSkinBoundary(const Ring& skin, double spacing, double tolerance, int pieces = 1) {
  const std::size_t n = skin.size();
  std::vector<double> along(n + 1, 0.0);  // arclength at each skin vertex (and the closing one)
  for (std::size_t j = 0; j < n; ++j) along[j + 1] = along[j] + distance(skin[j], skin[(j + 1) % n]);
  const double total = along[n] / pieces;  // exact for one piece
  // A piece rounds down, so that its copies take no more samples than the whole skin would.
  const std::size_t count = pieces == 1 ? std::max<std::size_t>(3, static_cast<std::size_t>(std::lround(total / spacing)))
                                        : std::max<std::size_t>(1, static_cast<std::size_t>(total / spacing));
  std::vector<double> stops;  // arclengths of the samples
  for (std::size_t k = 0; k < count; ++k) stops.push_back(total * static_cast<double>(k) / count);
  auto at = [&](double s) { return pointAtArclength(skin, s); };
  Ring result;
  for (std::size_t k = 0; k < count; ++k) {
    // Refine [stops[k], next) by splitting at the deepest skin vertex while it is too deep.
    double end = k + 1 < count ? stops[k + 1] : total;
    std::vector<double> pieces;
    std::function<void(double, double)> refine = [&](double s0, double s1) {
      Vec2 a = at(s0), b = at(s1);
      Vec2 chord = b - a;
      double len = length(chord);
      double deepest = tolerance;
      double split = -1.0;
      for (std::size_t j = 0; j < n; ++j) {
        if (!(along[j] > s0 && along[j] < s1)) continue;
        // Skin is positively oriented, so its outside is to the right of the chord.
        double depth = len > 0.0 ? cross(chord, a - skin[j]) / len : distance(a, skin[j]);
        if (depth > deepest) { deepest = depth; split = along[j]; }
      }
      if (split < 0.0) return;
      refine(s0, split);
      pieces.push_back(split);
      refine(split, s1);
    };
    pieces.push_back(stops[k]);
    refine(stops[k], end);
    std::sort(pieces.begin(), pieces.end());
    for (double s : pieces) result.push_back(at(s));
  }
  return result;
}

// p turned about the origin by `step` times 360°/order.
Vec2 turned(Vec2 p, int step, int order) { return rotated(p, 2.0 * std::numbers::pi * step / order); }

// Whether turning the skin by 360°/order about the origin lays it on itself, within `tolerance`.
bool hasSymmetry(const Ring& skin, int order, double tolerance) {
  for (Vec2 p : skin)
    if (closestPointOnRing(turned(p, 1, order), skin).distance > tolerance) return false;
  return true;
}

// The boundary samples of one order-th of the skin, turned `order` times: a ring in order,
// since a turn of a positively oriented ring about a centre inside it runs along the ring.
Ring symmetricBoundary(const Ring& skin, double spacing, double tolerance, int order) {
  const Ring piece = sampleSkinBoundary(skin, spacing, tolerance, order);
  Ring ring;
  for (int j = 0; j < order; ++j)
    for (Vec2 p : piece) ring.push_back(turned(p, j, order));
  return ring;
}

// Blue noise of one sector [0°, 360°/order) turned `order` times, plus the centre: samples
// whose turned copies would come nearer than most of the radius to a kept one are dropped.
std::vector<Vec2> symmetricInterior(const Polygon& polygon, const BlueNoiseOptions& noise, int order) {
  constexpr double kNearest = 0.75;  // of the radius, between kept samples and their copies
  const double sector = 2.0 * std::numbers::pi / order, nearest2 = kNearest * kNearest * noise.radius * noise.radius;
  std::vector<Vec2> kept;  // the sector's samples and the centre
  const Vec2 centre{0.0, 0.0};
  if (pointInPolygon(centre, polygon) && closestPointOnRing(centre, polygon.outer).distance >= noise.boundaryMargin)
    kept.push_back(centre);
  const std::size_t centres = kept.size();
  for (Vec2 p : blueNoiseSample(Region{polygon}, noise)) {
    double angle = std::atan2(p.y, p.x);
    if (angle < 0.0) angle += 2.0 * std::numbers::pi;
    if (!(angle < sector)) continue;
    bool roomy = true;
    for (int j = 0; j < order && roomy; ++j) {
      const Vec2 q = turned(p, j, order);
      if (j > 0 && lengthSquared(q - p) < nearest2) roomy = false;
      for (std::size_t i = 0; i < kept.size() && roomy; ++i) roomy = lengthSquared(q - kept[i]) >= nearest2;
    }
    if (roomy) kept.push_back(p);
  }
  std::vector<Vec2> interior(kept.begin(), kept.begin() + static_cast<std::ptrdiff_t>(centres));
  for (int j = 0; j < order; ++j)
    for (std::size_t i = centres; i < kept.size(); ++i) interior.push_back(turned(kept[i], j, order));
  return interior;
}

std::pair<int, int> edgeKey(int a, int b) { return a < b ? std::pair{a, b} : std::pair{b, a}; }

// Index of the triangle containing p, else of the triangle nearest to p.
ArtBinding bindPoint(Vec2 p, const TriMesh& mesh) {
  ArtBinding best;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    Vec2 a = mesh.vertices[tri[0]], b = mesh.vertices[tri[1]], c = mesh.vertices[tri[2]];
    auto w = barycentric(p, a, b, c);
    double outside = std::max({-w[0], -w[1], -w[2], 0.0});
    double d;
    if (outside == 0.0) {
      d = 0.0;
    } else {
      Ring triangle{a, b, c};
      d = closestPointOnRing(p, triangle).distance;
    }
    if (d < bestDistance) {
      bestDistance = d;
      best.triangle = static_cast<int>(t);
      best.weights = w;
      if (d == 0.0) break;
    }
  }
  return best;
}

}  // namespace

ElementMesh buildElementMesh(const std::vector<Shape>& art, const Region& outline,
                             const ElementMeshOptions& options) {
  Polygon skin = elementSkin(outline, options.gap, options.arcTolerance);
  if (skin.outer.size() < 3) throw InputError("", "element has no area to mesh");
  Ring skinRing = skin.outer;
  if (signedArea(skinRing) < 0) std::reverse(skinRing.begin(), skinRing.end());
  // The skin's own symmetry up to its offset's arcs, and a tenth of the spacing besides.
  const double symmetryTolerance = 2.0 * options.arcTolerance + 0.1 * options.spacing;
  const int symmetry = options.symmetry > 1 && hasSymmetry(skinRing, options.symmetry, symmetryTolerance)
                           ? options.symmetry : 1;
  const double deepest = options.gap / 4.0;
  Ring boundary = symmetry > 1 ? symmetricBoundary(skinRing, options.spacing, deepest, symmetry)
                               : sampleSkinBoundary(skinRing, options.spacing, deepest);
  Polygon meshPolygon{boundary, {}};

  BlueNoiseOptions noise;
  noise.radius = options.spacing;
  noise.boundaryMargin = 0.6 * options.spacing;
  noise.seed = options.seed;
  std::vector<Vec2> interior = symmetry > 1 ? symmetricInterior(meshPolygon, noise, symmetry)
                                            : blueNoiseSample(Region{meshPolygon}, noise);
  TriMesh triangulated = triangulatePolygon(meshPolygon, interior);
  if (triangulated.triangles.empty()) throw InputError("", "element mesh has no triangles");

  // Reorder: the used boundary samples first, in ring order, then interior vertices.
  std::map<std::pair<double, double>, int> indexOf;
  for (std::size_t v = 0; v < triangulated.vertices.size(); ++v)
    indexOf.emplace(std::pair{triangulated.vertices[v].x, triangulated.vertices[v].y}, static_cast<int>(v));
  std::vector<int> newIndex(triangulated.vertices.size(), -1);
  ElementMesh result;
  result.symmetry = symmetry;
  for (Vec2 p : boundary) {
    auto it = indexOf.find({p.x, p.y});
    if (it == indexOf.end() || newIndex[it->second] >= 0) continue;
    newIndex[it->second] = static_cast<int>(result.mesh.vertices.size());
    result.mesh.vertices.push_back(p);
  }
  result.boundaryCount = static_cast<int>(result.mesh.vertices.size());
  for (std::size_t v = 0; v < triangulated.vertices.size(); ++v) {
    if (newIndex[v] >= 0) continue;
    newIndex[v] = static_cast<int>(result.mesh.vertices.size());
    result.mesh.vertices.push_back(triangulated.vertices[v]);
  }
  for (const auto& tri : triangulated.triangles)
    result.mesh.triangles.push_back({newIndex[tri[0]], newIndex[tri[1]], newIndex[tri[2]]});

  Ring meshRing(result.mesh.vertices.begin(), result.mesh.vertices.begin() + result.boundaryCount);
  result.skinArea = signedArea(meshRing);
  result.artArea = area(outline);
  for (Vec2 v : result.mesh.vertices) result.restCentroid += v;
  result.restCentroid = result.restCentroid / static_cast<double>(result.mesh.vertices.size());

  // Springs: triangle edges, shear edges across shared edges, negative-space edges.
  const auto& V = result.mesh.vertices;
  std::set<std::pair<int, int>> used;
  auto addSpring = [&](int a, int b, SpringKind kind) {
    if (a == b || !used.insert(edgeKey(a, b)).second) return;
    result.springs.push_back({a, b, distance(V[a], V[b]), kind});
  };
  std::map<std::pair<int, int>, std::vector<int>> opposite;  // edge -> opposite vertices
  for (const auto& tri : result.mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      addSpring(tri[k], tri[(k + 1) % 3], SpringKind::Edge);
      opposite[edgeKey(tri[k], tri[(k + 1) % 3])].push_back(tri[(k + 2) % 3]);
    }
  for (const auto& [edge, across] : opposite)
    if (across.size() == 2) addSpring(across[0], across[1], SpringKind::Shear);
  // Negative space: the Delaunay triangles of the convex hull that lie outside the skin.
  TriMesh hull = delaunayTriangulation(V);
  for (const auto& tri : hull.triangles) {
    Vec2 c = (hull.vertices[tri[0]] + hull.vertices[tri[1]] + hull.vertices[tri[2]]) / 3.0;
    if (pointInRing(c, meshRing)) continue;
    for (int k = 0; k < 3; ++k) addSpring(tri[k], tri[(k + 1) % 3], SpringKind::NegativeSpace);
  }

  for (const Shape& shape : art)
    for (const Subpath& sub : shape.subpaths)
      for (Vec2 p : sub.points) result.bindings.push_back(bindPoint(p, result.mesh));
  result.smoothing = neighbourhoodFits(result.mesh);
  return result;
}

double librarySkinScale(const Library& library, double nominalSkinArea, double gap) {
  double meanArt = 0.0;
  for (const ElementArt& e : library) {
    const double a = area(e.outline);
    if (!(a > 0.0)) throw InputError(e.source, "element paints no area");
    meanArt += a / library.size();
  }
  double scale = std::sqrt(0.75 * nominalSkinArea / meanArt);
  double meanSkin = 0.0;
  for (const ElementArt& e : library)
    meanSkin += area(Region{elementSkin(transformed(e.outline, scale, -centroid(e.outline) * scale), gap, 0.5)}) /
                library.size();
  if (meanSkin > 0.0) scale *= std::sqrt(nominalSkinArea / meanSkin);
  return scale;
}

void replayArt(const ElementMesh& mesh, const Vec2* deformed, std::vector<Vec2>& artPoints) {
  artPoints.resize(mesh.bindings.size());
  for (std::size_t i = 0; i < mesh.bindings.size(); ++i) {
    const ArtBinding& b = mesh.bindings[i];
    const auto& tri = mesh.mesh.triangles[b.triangle];
    artPoints[i] = deformed[tri[0]] * b.weights[0] + deformed[tri[1]] * b.weights[1] + deformed[tri[2]] * b.weights[2];
  }
}

}  // namespace pak
