#include "pak/geom/triangulation.hpp"

#include <geos_c.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <utility>

#include "pak/error.hpp"

namespace pak {
namespace {

// One GEOS context per thread: the `_r` API is thread-safe as long as a context is never
// shared, and reusing it avoids setting one up on every call.
class GeosContext {
 public:
  GeosContext() : handle_(GEOS_init_r()) {
    GEOSContext_setErrorMessageHandler_r(handle_, &GeosContext::recordError, this);
    GEOSContext_setNoticeMessageHandler_r(handle_, &GeosContext::ignore, nullptr);
  }
  ~GeosContext() { GEOS_finish_r(handle_); }
  GeosContext(const GeosContext&) = delete;
  GeosContext& operator=(const GeosContext&) = delete;

  GEOSContextHandle_t handle() const { return handle_; }
  std::string takeError() { return std::exchange(lastError_, {}); }

 private:
  static void recordError(const char* message, void* self) {
    static_cast<GeosContext*>(self)->lastError_ = message ? message : "unknown GEOS error";
  }
  static void ignore(const char*, void*) {}

  GEOSContextHandle_t handle_;
  std::string lastError_;
};

GeosContext& geosContext() {
  thread_local GeosContext context;
  return context;
}

struct GeometryDeleter {
  GEOSContextHandle_t handle;
  void operator()(GEOSGeometry* g) const { GEOSGeom_destroy_r(handle, g); }
};
using GeometryPtr = std::unique_ptr<GEOSGeometry, GeometryDeleter>;

void checkFinite(const std::vector<Vec2>& points) {
  for (Vec2 p : points)
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) throw InputError("", "non-finite coordinate in a triangulation input");
}

// Finds the index of the first input point with exactly the given coordinates. GEOS hands
// back the input coordinates unchanged, so exact comparison is the right test.
class PointIndex {
 public:
  explicit PointIndex(const std::vector<Vec2>& points) : points_(points), order_(points.size()) {
    for (std::size_t k = 0; k < order_.size(); ++k) order_[k] = static_cast<int>(k);
    std::stable_sort(order_.begin(), order_.end(), [&](int a, int b) { return less(points_[a], points_[b]); });
  }

  int find(Vec2 p) const {
    auto it = std::lower_bound(order_.begin(), order_.end(), p,
                               [&](int k, Vec2 q) { return less(points_[k], q); });
    if (it == order_.end() || points_[*it].x != p.x || points_[*it].y != p.y) return -1;
    return *it;  // the stable sort puts the first occurrence first among equals
  }

 private:
  static bool less(Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }
  const std::vector<Vec2>& points_;
  std::vector<int> order_;
};

// Delaunay triangles over `points` as counter-clockwise index triples (first occurrences of
// duplicates); degenerate (zero-area) triangles are dropped.
std::vector<std::array<int, 3>> delaunayIndices(const std::vector<Vec2>& points) {
  checkFinite(points);
  if (points.size() < 3) return {};
  GeosContext& context = geosContext();
  const GEOSContextHandle_t h = context.handle();

  std::vector<GEOSGeometry*> pointGeometries;
  pointGeometries.reserve(points.size());
  for (Vec2 p : points) pointGeometries.push_back(GEOSGeom_createPointFromXY_r(h, p.x, p.y));
  // The collection takes ownership of the points (GEOS frees them itself if it fails).
  GeometryPtr multipoint(GEOSGeom_createCollection_r(h, GEOS_MULTIPOINT, pointGeometries.data(),
                                                     static_cast<unsigned>(pointGeometries.size())),
                         GeometryDeleter{h});
  if (!multipoint) throw InputError("", "triangulation failed: " + context.takeError());
  GeometryPtr triangles(GEOSDelaunayTriangulation_r(h, multipoint.get(), 0.0, 0), GeometryDeleter{h});
  if (!triangles) throw InputError("", "triangulation failed: " + context.takeError());

  const PointIndex index(points);
  std::vector<std::array<int, 3>> out;
  const int count = GEOSGetNumGeometries_r(h, triangles.get());
  out.reserve(static_cast<std::size_t>(std::max(count, 0)));
  for (int t = 0; t < count; ++t) {
    const GEOSGeometry* polygon = GEOSGetGeometryN_r(h, triangles.get(), t);
    const GEOSGeometry* ring = polygon ? GEOSGetExteriorRing_r(h, polygon) : nullptr;
    const GEOSCoordSequence* coords = ring ? GEOSGeom_getCoordSeq_r(h, ring) : nullptr;
    unsigned size = 0;
    if (!coords || !GEOSCoordSeq_getSize_r(h, coords, &size) || size < 3) continue;
    std::array<int, 3> tri{};
    bool mapped = true;
    for (unsigned c = 0; c < 3 && mapped; ++c) {
      Vec2 p;
      mapped = GEOSCoordSeq_getXY_r(h, coords, c, &p.x, &p.y) && (tri[c] = index.find(p)) >= 0;
    }
    if (!mapped) continue;
    const double a = triangleSignedArea(points[tri[0]], points[tri[1]], points[tri[2]]);
    if (a == 0.0) continue;
    if (a < 0.0) std::swap(tri[1], tri[2]);
    out.push_back(tri);
  }
  return out;
}

// pointInPolygon for many queries: the rings' edges are bucketed into horizontal bands, so
// a query only walks the edges whose y-range meets its band. Same crossing rule and
// per-ring parity as pointInRing, hence the same answers.
class PolygonInsideTest {
 public:
  explicit PolygonInsideTest(const Polygon& polygon) {
    addRing(polygon.outer, 0);
    for (std::size_t h = 0; h < polygon.holes.size(); ++h) addRing(polygon.holes[h], static_cast<int>(h) + 1);
    ringCount_ = polygon.holes.size() + 1;
    Box box;
    for (const Edge& e : edges_) {
      box.add(e.a);
      box.add(e.b);
    }
    if (edges_.empty() || box.empty()) return;
    minY_ = box.min.y;
    bandCount_ = std::max<std::size_t>(1, static_cast<std::size_t>(std::sqrt(static_cast<double>(edges_.size()))));
    bandHeight_ = box.height() / static_cast<double>(bandCount_);
    bands_.assign(bandCount_, {});
    for (std::size_t k = 0; k < edges_.size(); ++k) {
      const Edge& e = edges_[k];
      const std::size_t lo = band(std::min(e.a.y, e.b.y)), hi = band(std::max(e.a.y, e.b.y));
      for (std::size_t b = lo; b <= hi; ++b) bands_[b].push_back(static_cast<int>(k));
    }
  }

  bool contains(Vec2 p) {
    if (bands_.empty() || !(p.y >= minY_) || !(p.y <= minY_ + bandHeight_ * bandCount_)) return false;
    parity_.assign(ringCount_, false);
    for (int k : bands_[band(p.y)]) {
      const Edge& e = edges_[k];
      if ((e.a.y > p.y) != (e.b.y > p.y)) {
        const double x = e.a.x + (p.y - e.a.y) * (e.b.x - e.a.x) / (e.b.y - e.a.y);
        if (p.x < x) parity_[e.ring] = !parity_[e.ring];
      }
    }
    if (!parity_[0]) return false;
    for (std::size_t r = 1; r < ringCount_; ++r)
      if (parity_[r]) return false;
    return true;
  }

 private:
  struct Edge {
    Vec2 a, b;  // pointInRing's (vertex, previous vertex) order
    int ring;
  };

  void addRing(const Ring& ring, int id) {
    const std::size_t n = ring.size();
    if (n < 3) return;
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) edges_.push_back({ring[i], ring[j], id});
  }

  std::size_t band(double y) const {
    if (!(bandHeight_ > 0.0)) return 0;
    const double u = (y - minY_) / bandHeight_;
    return std::min(bandCount_ - 1, static_cast<std::size_t>(std::max(u, 0.0)));
  }

  std::vector<Edge> edges_;
  std::vector<std::vector<int>> bands_;
  std::vector<bool> parity_;
  std::size_t ringCount_ = 0, bandCount_ = 0;
  double minY_ = 0.0, bandHeight_ = 0.0;
};

}  // namespace

TriMesh triangulatePolygon(const Polygon& polygon, const std::vector<Vec2>& interiorPoints) {
  if (polygon.outer.size() < 3) return {};
  std::vector<Vec2> points = polygon.outer;
  for (const Ring& hole : polygon.holes) points.insert(points.end(), hole.begin(), hole.end());
  points.insert(points.end(), interiorPoints.begin(), interiorPoints.end());

  std::vector<std::array<int, 3>> kept;
  PolygonInsideTest inside(polygon);
  for (const std::array<int, 3>& tri : delaunayIndices(points)) {
    const Vec2 c = (points[tri[0]] + points[tri[1]] + points[tri[2]]) / 3.0;
    if (inside.contains(c)) kept.push_back(tri);
  }

  // Renumber the used vertices, keeping their input order (so the outer ring stays first).
  std::vector<int> newIndex(points.size(), -1);
  for (const std::array<int, 3>& tri : kept)
    for (int v : tri) newIndex[v] = 0;
  TriMesh mesh;
  for (std::size_t v = 0; v < points.size(); ++v)
    if (newIndex[v] == 0) {
      newIndex[v] = static_cast<int>(mesh.vertices.size());
      mesh.vertices.push_back(points[v]);
    }
  mesh.triangles.reserve(kept.size());
  for (const std::array<int, 3>& tri : kept)
    mesh.triangles.push_back({newIndex[tri[0]], newIndex[tri[1]], newIndex[tri[2]]});
  return mesh;
}

TriMesh delaunayTriangulation(const std::vector<Vec2>& points) {
  TriMesh mesh;
  mesh.triangles = delaunayIndices(points);
  mesh.vertices = points;
  return mesh;
}

}  // namespace pak
