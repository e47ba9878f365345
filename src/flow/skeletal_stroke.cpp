// Skeletal strokes (thesis 3.3.5 after [HLW93]): an element's (along, across) coordinates
// relative to its straight spine become (arclength, normal offset) along a streamline.
#include "pak/flow/skeletal_stroke.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
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

// A widening profile (StrokeFrame::widenLeft/Right) at `at` (0–1 along the element): its
// samples lie at (i + 0.5) / n, as the LR functions'; linear between, flat beyond; 1 if empty.
double widening(const std::vector<double>& profile, double at) {
  const int n = static_cast<int>(profile.size());
  if (n == 0) return 1.0;
  const double position = std::clamp(at * n - 0.5, 0.0, static_cast<double>(n - 1));
  const int i = std::min(static_cast<int>(position), n - 1);
  if (i == n - 1) return profile[static_cast<std::size_t>(i)];
  const double f = position - i;
  return (1.0 - f) * profile[static_cast<std::size_t>(i)] + f * profile[static_cast<std::size_t>(i + 1)];
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
    for (const std::vector<double>* profile : {&frame.widenLeft, &frame.widenRight})
      for (double w : *profile)
        if (!(w > 0.0) || !std::isfinite(w)) throw InputError(where, "the widening must be positive and finite");
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

  // Where `along` lies in the element's extent, 0 to 1 (clamped).
  double at(double along) const {
    return std::clamp((along - frame_.alongMin) / (frame_.alongMax - frame_.alongMin), 0.0, 1.0);
  }

  Vec2 bend(Vec2 p) const {
    Vec2 ad = local(p);
    ArclengthFrame::Sample s = onCurve(ad.x);
    const double widen = widening(ad.y > 0.0 ? frame_.widenLeft : frame_.widenRight, at(ad.x));
    return s.point + (frame_.widthScale * widen * ad.y) * s.normal;
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
    scaleStroke(shape, strokeScale);
  }
  return out;
}

namespace {

// An outline bent at width scale 1, vertex by vertex as base + offset (its point on the
// streamline and its unscaled normal offset), with the vertex's place along the element (0–1)
// and side: any width, uniform or profiled, is tried without bending again.
struct BentOutline {
  struct Ring {
    std::vector<Vec2> base, offset;
    std::vector<double> at;         // 0–1 along the element
    std::vector<std::uint8_t> left;  // on the streamline's left
  };
  std::vector<std::vector<Ring>> polygons;  // per polygon: outer first, then holes

  BentOutline(const Region& outline, const StrokeMap& map, double maxEdge) {
    for (const Polygon& polygon : outline) {
      std::vector<Ring>& rings = polygons.emplace_back();
      auto prepare = [&](const pak::Ring& ring) {
        Ring& bent = rings.emplace_back();
        for (Vec2 p : subdivided(ring, true, maxEdge)) {
          Vec2 ad = map.local(p);
          ArclengthFrame::Sample s = map.onCurve(ad.x);
          bent.base.push_back(s.point);
          bent.offset.push_back(ad.y * s.normal);
          bent.at.push_back(map.at(ad.x));
          bent.left.push_back(ad.y > 0.0 ? 1 : 0);
        }
      };
      prepare(polygon.outer);
      for (const pak::Ring& hole : polygon.holes) prepare(hole);
    }
  }

  // The region with vertex k of ring r of polygon q at base + width(q, r, k) * offset.
  template <typename Width>
  void build(Region& out, Width width) const {
    out.resize(polygons.size());
    for (std::size_t q = 0; q < polygons.size(); ++q) {
      Polygon& polygon = out[q];
      polygon.holes.resize(polygons[q].size() - 1);
      for (std::size_t r = 0; r < polygons[q].size(); ++r) {
        const Ring& bent = polygons[q][r];
        pak::Ring& ring = r == 0 ? polygon.outer : polygon.holes[r - 1];
        ring.resize(bent.base.size());
        for (std::size_t k = 0; k < ring.size(); ++k) ring[k] = bent.base[k] + width(bent, k) * bent.offset[k];
      }
    }
  }
};

// Whether a region lies inside a blob, from a grid of the blob's boundary segments (no
// Clipper): no edge of the region leaves through the boundary, one clear vertex of each ring
// is inside, and no ring of the blob lies inside the region.
class BlobContainment {
 public:
  explicit BlobContainment(const Region& blob) : blob_(blob) {
    normalizeOrientation(blob_);  // interior on the left of every boundary edge
    const Box box = bounds(blob_);
    double perimeterSum = 0.0;
    auto addRing = [&](const pak::Ring& ring) {
      if (ring.size() < 3) return;
      rings_.push_back(&ring);
      const int first = static_cast<int>(positions_.size()), n = static_cast<int>(ring.size());
      positions_.insert(positions_.end(), ring.begin(), ring.end());
      for (int k = 0; k < n; ++k) {
        ends_.push_back(first + k);
        ends_.push_back(first + (k + 1) % n);
      }
      perimeterSum += perimeter(ring);
    };
    for (const Polygon& polygon : blob_) {
      addRing(polygon.outer);
      for (const pak::Ring& hole : polygon.holes) addRing(hole);
    }
    const std::size_t segments = ends_.size() / 2;
    if (box.empty() || segments == 0) return;
    const double diagonal = length(box.max - box.min);
    tol_ = 1e-9 * diagonal;
    // Cells about two boundary segments long, at most ~65k of them.
    const double cell = std::max({2.0 * perimeterSum / static_cast<double>(segments),
                                  std::sqrt(box.width() * box.height() / 65536.0), 1e-6 * diagonal});
    grid_.configure(box, cell, segments);
    grid_.rebuild(positions_.data(), ends_.data(), segments);
    usable_ = true;
  }

  bool usable() const { return usable_; }
  const Region& blob() const { return blob_; }

  // Whether segment pq leaves the blob through its boundary.
  bool leaves(Vec2 p, Vec2 q) const {
    const int i0 = grid_.cellX(std::min(p.x, q.x) - tol_), i1 = grid_.cellX(std::max(p.x, q.x) + tol_);
    const int j0 = grid_.cellY(std::min(p.y, q.y) - tol_), j1 = grid_.cellY(std::max(p.y, q.y) + tol_);
    bool out = false;
    grid_.forEachNear(0.5 * (p + q), std::max(i1 - i0, j1 - j0), [&](int s) {
      if (!out) out = leavesThrough(p, q, positions_[ends_[2 * s]], positions_[ends_[2 * s + 1]], tol_);
    });
    return out;
  }

  bool contains(const Region& region) const {
    // 1. No edge leaves through the blob's boundary.
    for (const Polygon& polygon : region)
      for (std::size_t r = 0; r <= polygon.holes.size(); ++r) {
        const pak::Ring& ring = r == 0 ? polygon.outer : polygon.holes[r - 1];
        for (std::size_t k = 0, j = ring.size() - 1; k < ring.size(); j = k++)
          if (leaves(ring[j], ring[k])) return false;
      }
    // 2. So each ring is wholly inside or wholly outside: one vertex clear of the boundary decides.
    for (const Polygon& polygon : region)
      for (std::size_t r = 0; r <= polygon.holes.size(); ++r) {
        const pak::Ring& ring = r == 0 ? polygon.outer : polygon.holes[r - 1];
        for (Vec2 p : ring) {
          const bool inside = pointInRegion(p, blob_);
          if (closestPointOnBoundary(p, blob_).distance <= tol_) continue;  // on it: undecided
          if (!inside) return false;
          break;
        }
      }
    // 3. No part of the blob's boundary (a hole, another piece) lies inside the region.
    for (const pak::Ring* ring : rings_)
      if (pointInRegion(ring->front(), region)) return false;
    return true;
  }

 private:
  Region blob_;
  std::vector<Vec2> positions_;
  std::vector<int> ends_;
  std::vector<const pak::Ring*> rings_;
  SegmentGrid grid_;
  double tol_ = 0.0;
  bool usable_ = false;
};

// Samples of the LR functions that guess the widths.
constexpr int kWidthSamples = 32;

}  // namespace

double fitWidthScale(const Region& outline, StrokeFrame frame, const Polyline& streamline, const Region& blob,
                     double maxEdge, double maxScale) {
  const char* where = "fitWidthScale";
  checkMaxEdge(maxEdge);
  if (!(maxScale > 0.0) || !std::isfinite(maxScale)) throw InputError(where, "maxScale must be a positive finite number");
  if (outline.empty()) return 0.0;
  const BlobContainment containment(blob);
  if (!containment.usable()) return 0.0;
  frame.widthScale = 1.0;
  frame.widenLeft.clear(), frame.widenRight.clear();
  const BentOutline bent(outline, StrokeMap(frame, streamline), maxEdge);
  Region trial;
  auto fits = [&](double scale) {
    bent.build(trial, [scale](const BentOutline::Ring&, std::size_t) { return scale; });
    return containment.contains(trial);
  };

  // Initial guess (3.3.5): the element's extents against the blob's, sample by sample.
  const int samples = kWidthSamples;
  LRFunction element = reflected(elementLRFunction(rotatedElement(outline, frame), frame.spineStart, frame.spineEnd, samples), frame.reflection);
  LRFunction space = blobLRFunction(containment.blob(), streamline, samples);
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

void fitWidening(const Region& outline, StrokeFrame& frame, const Polyline& streamline, const Region& blob,
                 double margin, double maxEdge, double maxWiden) {
  checkMaxEdge(maxEdge);
  frame.widenLeft.clear(), frame.widenRight.clear();
  if (!(maxWiden > 1.0) || !std::isfinite(maxWiden) || !(frame.widthScale > 0.0) || outline.empty()) return;
  const BlobContainment containment(blob);
  if (!containment.usable()) return;
  // Per side, how much wider than the uniform width each part could be, from the LR functions.
  const int n = kWidthSamples;
  const LRFunction element =
      reflected(elementLRFunction(rotatedElement(outline, frame), frame.spineStart, frame.spineEnd, n), frame.reflection);
  // The room past the margin, measured along the streamline's normals as the LR functions are.
  LRFunction space = blobLRFunction(containment.blob(), streamline, n);
  for (std::vector<double>* side : {&space.left, &space.right})
    for (double& extent : *side) extent = std::max(0.0, extent - margin);
  const double negligible = 1e-9 * std::max(element.maxLeft, element.maxRight);
  // `cap`: at most this per sample (lowered where a try left the blob, below).
  auto profile = [&](const std::vector<double>& own, const std::vector<double>& room, const std::vector<double>& cap) {
    std::vector<double> raw(static_cast<std::size_t>(n));
    for (std::size_t i = 0; i < raw.size(); ++i)
      raw[i] = std::min(cap[i], own[i] > negligible ? std::clamp(room[i] / (frame.widthScale * own[i]), 1.0, maxWiden) : maxWiden);
    // The least of each sample and its neighbours (the LR functions sample the room coarsely),
    // then no steeper than kWidenSlope per sample either way, so the outline stays smooth.
    std::vector<double> out(raw.size());
    for (std::size_t i = 0; i < raw.size(); ++i)
      out[i] = std::min({raw[i], raw[i > 0 ? i - 1 : i], raw[std::min(i + 1, raw.size() - 1)]});
    constexpr double kWidenSlope = 0.03;
    for (std::size_t i = 1; i < out.size(); ++i) out[i] = std::min(out[i], out[i - 1] + kWidenSlope);
    for (std::size_t i = out.size() - 1; i-- > 0;) out[i] = std::min(out[i], out[i + 1] + kWidenSlope);
    return out;
  };
  std::vector<double> capLeft(static_cast<std::size_t>(n), maxWiden), capRight = capLeft;
  std::vector<double> left = profile(element.left, space.left, capLeft), right = profile(element.right, space.right, capRight);
  auto none = [](const std::vector<double>& w) { return std::all_of(w.begin(), w.end(), [](double x) { return x == 1.0; }); };
  if (none(left) && none(right)) return;

  StrokeFrame unit = frame;
  unit.widthScale = 1.0;
  const BentOutline bent(outline, StrokeMap(unit, streamline), maxEdge);
  Region trial;
  const double s0 = frame.widthScale;
  auto fits = [&](double t) {
    bent.build(trial, [&](const BentOutline::Ring& ring, std::size_t k) {
      return s0 * (1.0 + t * (widening(ring.left[k] ? left : right, ring.at[k]) - 1.0));
    });
    return containment.contains(trial);
  };
  // The LR functions miss the blob's corners between their samples: where an edge of the
  // widened outline leaves the blob, or a vertex is not inside it, the samples around do not
  // widen, a few times over; then the largest share t of what is left that fits, by bisection.
  constexpr int kRepairs = 4;
  bool whole = fits(1.0);  // the whole profile fits (`trial` holds it)
  for (int repair = 0; repair < kRepairs && !whole; ++repair) {
    bool lowered = false;
    for (std::size_t q = 0; q < bent.polygons.size(); ++q)
      for (std::size_t r = 0; r < bent.polygons[q].size(); ++r) {
        const BentOutline::Ring& ring = bent.polygons[q][r];
        const Ring& placed = r == 0 ? trial[q].outer : trial[q].holes[r - 1];
        auto hold = [&](std::size_t k) {  // the samples around vertex k do not widen
          std::vector<double>& cap = ring.left[k] ? capLeft : capRight;
          const int i = std::clamp(static_cast<int>(ring.at[k] * n), 0, n - 1);
          for (int j = std::max(0, i - 1); j <= std::min(n - 1, i + 1); ++j) cap[static_cast<std::size_t>(j)] = 1.0;
          lowered = true;
        };
        for (std::size_t k = 0, j = placed.size() - 1; k < placed.size(); j = k++) {
          if (containment.leaves(placed[j], placed[k])) hold(j), hold(k);
          else if (!pointInRegion(placed[k], containment.blob())) hold(k);
        }
      }
    if (!lowered) break;  // nothing to blame on a sample (a hole of the blob inside the element): bisect
    left = profile(element.left, space.left, capLeft);
    right = profile(element.right, space.right, capRight);
    whole = fits(1.0);
  }
  double lo = 1.0;
  if (!whole) {
    if (!fits(0.0)) return;  // the uniform width itself is on the edge: keep it
    double hi = 1.0;
    lo = 0.0;
    for (int round = 0; round < 7; ++round) {
      const double middle = 0.5 * (lo + hi);
      (fits(middle) ? lo : hi) = middle;
    }
  }
  if (lo <= 0.0 || (none(left) && none(right))) return;
  frame.widenLeft.resize(left.size()), frame.widenRight.resize(right.size());
  for (std::size_t i = 0; i < left.size(); ++i) frame.widenLeft[i] = 1.0 + lo * (left[i] - 1.0);
  for (std::size_t i = 0; i < right.size(); ++i) frame.widenRight[i] = 1.0 + lo * (right[i] - 1.0);
}

}  // namespace pak
