// Skeletal strokes (thesis 3.3.5 after [HLW93]): an element's (along, across) coordinates
// relative to its straight spine become (arclength, normal offset) along a streamline.
#include "pak/flow/skeletal_stroke.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "flow/arclength_frame.hpp"
#include "pak/error.hpp"
#include "pak/geom/closest_point.hpp"
#include "sim/segment_grid.hpp"

namespace pak {

namespace {

using flow_detail::ArclengthFrame;

void checkFinite(double value, const char* where, const char* what) {
  if (!std::isfinite(value)) throw InputError(where, std::string(what) + " must be finite");
}

// Extent of the outline along the spine line.
void spineExtent(const Region& outline, Vec2 spineStart, Vec2 spineEnd, double& alongMin, double& alongMax) {
  const Vec2 axis = normalized(spineEnd - spineStart);
  alongMin = std::numeric_limits<double>::infinity();
  alongMax = -alongMin;
  auto add = [&](const Ring& ring) {
    for (Vec2 p : ring) {
      double a = dot(p - spineStart, axis);
      alongMin = std::min(alongMin, a);
      alongMax = std::max(alongMax, a);
    }
  };
  for (const Polygon& polygon : outline) {
    add(polygon.outer);
    for (const Ring& hole : polygon.holes) add(hole);
  }
}

// Splits every edge into equal pieces no longer than maxEdge; `closed` includes the edge
// from the last point back to the first.
std::vector<Vec2> subdivided(const std::vector<Vec2>& points, bool closed, double maxEdge) {
  std::vector<Vec2> out;
  const std::size_t n = points.size();
  if (n == 0) return out;
  out.reserve(n);
  for (Vec2 p : points)
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) throw InputError("skeletal stroke", "the element has a non-finite point");
  const std::size_t edges = closed ? n : n - 1;
  for (std::size_t k = 0; k < edges; ++k) {
    Vec2 a = points[k], b = points[(k + 1) % n];
    double pieces = std::ceil(distance(a, b) / maxEdge);
    if (!(pieces < 1e6)) throw InputError("skeletal stroke", "maxEdge is too small for the element (over 1e6 pieces per edge)");
    int count = std::max(1, static_cast<int>(pieces));
    for (int i = 0; i < count; ++i) out.push_back(a + (static_cast<double>(i) / count) * (b - a));
  }
  if (!closed) out.push_back(points.back());
  return out;
}

// The whole map of a StrokeFrame onto a streamline.
class StrokeMap {
 public:
  StrokeMap(const StrokeFrame& frame, const Polyline& streamline)
      : curve_(streamline, "skeletal stroke"), frame_(frame) {
    const char* where = "skeletal stroke";
    checkFinite(frame.rotation, where, "the rotation");
    checkFinite(frame.widthScale, where, "the width scale");
    if (frame.widthScale < 0.0) throw InputError(where, "the width scale must not be negative");
    double spineLength = distance(frame.spineStart, frame.spineEnd);
    if (!(spineLength > 0.0) || !std::isfinite(spineLength))
      throw InputError(where, "the spine's two ends must be distinct finite points");
    if (!(frame.alongMax > frame.alongMin) || !std::isfinite(frame.alongMax - frame.alongMin))
      throw InputError(where, "the element has no extent along its spine");
    axis_ = normalized(frame.spineEnd - frame.spineStart);
    normal_ = perp(axis_);
    pivot_ = 0.5 * (frame.spineStart + frame.spineEnd);
    cos_ = std::cos(frame.rotation);
    sin_ = std::sin(frame.rotation);
    across_ = frame.reflection == Reflection::AcrossSpine || frame.reflection == Reflection::Both;
    along_ = frame.reflection == Reflection::AlongSpine || frame.reflection == Reflection::Both;
    arclengthPerAlong_ = curve_.length() / (frame.alongMax - frame.alongMin);
  }

  // Each reflection reverses orientation; the rotation and the bend itself keep it.
  bool reversesOrientation() const { return across_ != along_; }
  double lengthScale() const { return arclengthPerAlong_; }

  // (along, across) of an element point: rotated about the spine's midpoint, then reflected.
  Vec2 local(Vec2 p) const {
    Vec2 r = p - pivot_;
    Vec2 q = pivot_ + Vec2{cos_ * r.x - sin_ * r.y, sin_ * r.x + cos_ * r.y};
    double a = dot(q - frame_.spineStart, axis_), d = dot(q - frame_.spineStart, normal_);
    if (across_) d = -d;
    if (along_) a = frame_.alongMin + frame_.alongMax - a;
    return {a, d};
  }
  // The streamline's point and unit left normal where `along` lands.
  ArclengthFrame::Sample onCurve(double along) const { return curve_.at((along - frame_.alongMin) * arclengthPerAlong_); }

  Vec2 bend(Vec2 p) const {
    Vec2 ad = local(p);
    ArclengthFrame::Sample s = onCurve(ad.x);
    return s.point + (frame_.widthScale * ad.y) * s.normal;
  }

  std::vector<Vec2> bendPoints(const std::vector<Vec2>& points, bool closed, double maxEdge) const {
    std::vector<Vec2> out = subdivided(points, closed, maxEdge);
    for (Vec2& p : out) p = bend(p);
    if (reversesOrientation()) std::reverse(out.begin(), out.end());
    return out;
  }

 private:
  ArclengthFrame curve_;
  StrokeFrame frame_;
  Vec2 axis_, normal_, pivot_;
  double cos_ = 1.0, sin_ = 0.0, arclengthPerAlong_ = 1.0;
  bool across_ = false, along_ = false;
};

void checkMaxEdge(double maxEdge) {
  if (!(maxEdge > 0.0) || !std::isfinite(maxEdge))
    throw InputError("skeletal stroke", "maxEdge must be a positive finite length");
}

// Whether segment pq leaves the blob through boundary segment ab: some part of pq lies
// beyond ab's line on the outside (by more than tol) and pq meets the segment ab (within
// tol). Blob rings are oriented with the interior on the left of each edge.
bool leavesThrough(Vec2 p, Vec2 q, Vec2 a, Vec2 b, double tol) {
  Vec2 e = b - a;
  double len = length(e);
  if (len == 0.0) return false;
  double dp = cross(e, p - a) / len, dq = cross(e, q - a) / len;  // > 0 inside
  if ((dp >= -tol) == (dq >= -tol)) return false;  // both on one side of the outside band
  double t = std::clamp(dp / (dp - dq), 0.0, 1.0);  // where pq meets ab's line (or its near end)
  Vec2 x = p + t * (q - p);
  double u = dot(x - a, e) / len;
  return u >= -tol && u <= len + tol;
}

}  // namespace

StrokeFrame strokeFrameFor(const Region& outline, Vec2 spineStart, Vec2 spineEnd, double rotation) {
  const char* where = "strokeFrameFor";
  checkFinite(rotation, where, "the rotation");
  double spineLength = distance(spineStart, spineEnd);
  if (!(spineLength > 0.0) || !std::isfinite(spineLength))
    throw InputError(where, "the spine's two ends must be distinct finite points");
  StrokeFrame frame;
  frame.spineStart = spineStart;
  frame.spineEnd = spineEnd;
  frame.rotation = rotation;
  spineExtent(rotatedElement(outline, frame), spineStart, spineEnd, frame.alongMin, frame.alongMax);
  if (!(frame.alongMax > frame.alongMin) || !std::isfinite(frame.alongMax - frame.alongMin))
    throw InputError(where, "the outline is empty or has no extent along its spine");
  return frame;
}

Region rotatedElement(const Region& outline, const StrokeFrame& frame) {
  if (frame.rotation == 0.0) return outline;
  const Vec2 pivot = 0.5 * (frame.spineStart + frame.spineEnd);
  Region out = outline;
  for (Polygon& polygon : out) {
    for (Vec2& p : polygon.outer) p = pivot + rotated(p - pivot, frame.rotation);
    for (Ring& hole : polygon.holes)
      for (Vec2& p : hole) p = pivot + rotated(p - pivot, frame.rotation);
  }
  return out;
}

Ring bendRing(const Ring& ring, const StrokeFrame& frame, const Polyline& streamline, double maxEdge) {
  checkMaxEdge(maxEdge);
  return StrokeMap(frame, streamline).bendPoints(ring, true, maxEdge);
}

Region bendRegion(const Region& region, const StrokeFrame& frame, const Polyline& streamline, double maxEdge) {
  checkMaxEdge(maxEdge);
  StrokeMap map(frame, streamline);
  Region out;
  out.reserve(region.size());
  for (const Polygon& polygon : region) {
    Polygon& bent = out.emplace_back();
    bent.outer = map.bendPoints(polygon.outer, true, maxEdge);
    for (const Ring& hole : polygon.holes) bent.holes.push_back(map.bendPoints(hole, true, maxEdge));
  }
  normalizeOrientation(out);
  return out;
}

std::vector<Shape> bendShapes(const std::vector<Shape>& shapes, const StrokeFrame& frame, const Polyline& streamline,
                              double maxEdge) {
  checkMaxEdge(maxEdge);
  StrokeMap map(frame, streamline);
  // Reversing every subpath of a shape negates all its winding numbers: neither the nonzero
  // nor the even-odd fill changes, and outer rings stay counter-clockwise.
  const double strokeScale = std::sqrt(map.lengthScale() * frame.widthScale);
  std::vector<Shape> out = shapes;
  for (Shape& shape : out) {
    for (Subpath& subpath : shape.subpaths) subpath.points = map.bendPoints(subpath.points, subpath.closed, maxEdge);
    shape.strokeWidth *= strokeScale;
  }
  return out;
}

double fitWidthScale(const Region& outline, StrokeFrame frame, const Polyline& streamline, const Region& blob,
                     double maxEdge, double maxScale) {
  const char* where = "fitWidthScale";
  checkMaxEdge(maxEdge);
  if (!(maxScale > 0.0) || !std::isfinite(maxScale)) throw InputError(where, "maxScale must be a positive finite number");
  Region blobRegion = blob;
  normalizeOrientation(blobRegion);  // interior on the left of every boundary edge
  Box blobBox = bounds(blobRegion);
  if (blobBox.empty() || outline.empty()) return 0.0;
  frame.widthScale = 1.0;
  const StrokeMap map(frame, streamline);

  // The bent outline is base + s * offset per vertex: the subdivision, the streamline
  // lookups and the normals are shared by every trial scale.
  struct BentRing { std::vector<Vec2> base, offset; };
  std::vector<std::vector<BentRing>> bentPolygons;  // per polygon: outer first, then holes
  auto prepare = [&](const Ring& ring, std::vector<BentRing>& into) {
    BentRing& bent = into.emplace_back();
    for (Vec2 p : subdivided(ring, true, maxEdge)) {
      Vec2 ad = map.local(p);
      ArclengthFrame::Sample s = map.onCurve(ad.x);
      bent.base.push_back(s.point);
      bent.offset.push_back(ad.y * s.normal);
    }
  };
  for (const Polygon& polygon : outline) {
    std::vector<BentRing>& rings = bentPolygons.emplace_back();
    prepare(polygon.outer, rings);
    for (const Ring& hole : polygon.holes) prepare(hole, rings);
  }

  // The blob's boundary segments in a uniform grid.
  std::vector<Vec2> positions;
  std::vector<int> ends;
  std::vector<const Ring*> blobRings;
  double perimeterSum = 0.0;
  auto addBlobRing = [&](const Ring& ring) {
    if (ring.size() < 3) return;
    blobRings.push_back(&ring);
    int first = static_cast<int>(positions.size()), n = static_cast<int>(ring.size());
    positions.insert(positions.end(), ring.begin(), ring.end());
    for (int k = 0; k < n; ++k) {
      ends.push_back(first + k);
      ends.push_back(first + (k + 1) % n);
    }
    perimeterSum += perimeter(ring);
  };
  for (const Polygon& polygon : blobRegion) {
    addBlobRing(polygon.outer);
    for (const Ring& hole : polygon.holes) addBlobRing(hole);
  }
  const std::size_t segmentCount = ends.size() / 2;
  if (segmentCount == 0) return 0.0;
  const double diagonal = length(blobBox.max - blobBox.min);
  const double tol = 1e-9 * diagonal;
  // Cells about two boundary segments long, at most ~65k of them.
  double cell = std::max({2.0 * perimeterSum / segmentCount, std::sqrt(blobBox.width() * blobBox.height() / 65536.0),
                          1e-6 * diagonal});
  SegmentGrid grid;
  grid.configure(blobBox, cell, segmentCount);
  grid.rebuild(positions.data(), ends.data(), segmentCount);

  Region bentRegion;
  auto fits = [&](double scale) {
    bentRegion.clear();
    for (const std::vector<BentRing>& rings : bentPolygons) {
      Polygon& polygon = bentRegion.emplace_back();
      for (std::size_t r = 0; r < rings.size(); ++r) {
        Ring& ring = r == 0 ? polygon.outer : polygon.holes.emplace_back();
        ring.resize(rings[r].base.size());
        for (std::size_t k = 0; k < ring.size(); ++k) ring[k] = rings[r].base[k] + scale * rings[r].offset[k];
      }
    }
    // 1. No bent edge leaves through the blob's boundary.
    for (const Polygon& polygon : bentRegion) {
      for (std::size_t r = 0; r <= polygon.holes.size(); ++r) {
        const Ring& ring = r == 0 ? polygon.outer : polygon.holes[r - 1];
        for (std::size_t k = 0, j = ring.size() - 1; k < ring.size(); j = k++) {
          Vec2 p = ring[j], q = ring[k];
          int i0 = grid.cellX(std::min(p.x, q.x) - tol), i1 = grid.cellX(std::max(p.x, q.x) + tol);
          int j0 = grid.cellY(std::min(p.y, q.y) - tol), j1 = grid.cellY(std::max(p.y, q.y) + tol);
          bool leaves = false;
          grid.forEachNear(0.5 * (p + q), std::max(i1 - i0, j1 - j0), [&](int s) {
            if (!leaves) leaves = leavesThrough(p, q, positions[ends[2 * s]], positions[ends[2 * s + 1]], tol);
          });
          if (leaves) return false;
        }
      }
    }
    // 2. So each bent ring is wholly inside or wholly outside: one vertex clear of the
    // boundary decides.
    for (const Polygon& polygon : bentRegion) {
      for (std::size_t r = 0; r <= polygon.holes.size(); ++r) {
        const Ring& ring = r == 0 ? polygon.outer : polygon.holes[r - 1];
        for (Vec2 p : ring) {
          bool inside = pointInRegion(p, blobRegion);
          if (closestPointOnBoundary(p, blobRegion).distance <= tol) continue;  // on it: undecided
          if (!inside) return false;
          break;
        }
      }
    }
    // 3. No part of the blob's boundary (a hole, another piece) lies inside the element.
    for (const Ring* ring : blobRings)
      if (pointInRegion(ring->front(), bentRegion)) return false;
    return true;
  };

  // Initial guess (3.3.5): the element's extents against the blob's, sample by sample.
  const int samples = 32;
  LRFunction element = reflected(elementLRFunction(rotatedElement(outline, frame), frame.spineStart, frame.spineEnd, samples), frame.reflection);
  LRFunction space = blobLRFunction(blobRegion, streamline, samples);
  double guess = maxScale;
  const double negligible = 1e-9 * std::max(element.maxLeft, element.maxRight);
  for (int i = 0; i < samples; ++i) {
    if (element.left[i] > negligible) guess = std::min(guess, space.left[i] / element.left[i]);
    if (element.right[i] > negligible) guess = std::min(guess, space.right[i] / element.right[i]);
  }
  // Bracket the answer with steps that start small (the guess is usually close) and square
  // their ratio each time, then bisect.
  const double sliver = 1e-6 * maxScale;
  double scale = std::clamp(guess, sliver, maxScale), lo = 0.0, hi = 0.0, ratio = 1.02;
  if (fits(scale)) {
    for (lo = scale; lo < maxScale; ratio *= ratio) {  // grow until it no longer fits
      hi = std::min(lo * ratio, maxScale);
      if (!fits(hi)) break;
      lo = hi;
    }
    if (lo >= maxScale) return maxScale;
  } else {
    for (hi = scale; hi > sliver; ratio *= ratio) {  // shrink until it fits
      double trial = std::max(hi / ratio, sliver);
      if (fits(trial)) { lo = trial; break; }
      hi = trial;
    }
    if (lo == 0.0) return 0.0;
  }
  while (hi - lo > 5e-4 * lo) {
    double middle = 0.5 * (lo + hi);
    (fits(middle) ? lo : hi) = middle;
  }
  return lo;
}

}  // namespace pak
