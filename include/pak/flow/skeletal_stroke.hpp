#pragma once
// Bending an element along a streamline as a skeletal stroke (thesis 3.3.5, [HLW93]).
#include <vector>

#include "pak/flow/lr_function.hpp"
#include "pak/geom/art.hpp"
#include "pak/geom/polygon.hpp"

namespace pak {

// How an element's frame maps onto a streamline. The element's coordinate along its spine
// line, from the outline's first to last extent (as in elementLRFunction), maps to the
// streamline's arclength from start to end; its signed distance from the spine (left
// positive) is multiplied by `widthScale` and laid along the streamline's left normal.
struct StrokeFrame {
  Vec2 spineStart, spineEnd;     // the element's spine line
  double alongMin = 0.0, alongMax = 1.0;  // the outline's extent along the spine, from spineStart
  Reflection reflection = Reflection::None;
  double rotation = 0.0;         // radians, the element turned about its spine's midpoint first
  double widthScale = 1.0;
  // Widening along the element (Pak; the thesis scales the width uniformly): factors of
  // widthScale on the streamline's left and right, at n points (i + 0.5) / n of the extent,
  // linear between; empty: 1 everywhere (fitWidening).
  std::vector<double> widenLeft, widenRight;
};

// The frame for an element outline: its spine line and its extent along it. With a
// rotation (the refinement's ±1…10°, 3.3.6) the extent is that of the rotated outline, so
// the rotated element still spans the whole streamline.
StrokeFrame strokeFrameFor(const Region& outline, Vec2 spineStart, Vec2 spineEnd, double rotation = 0.0);
// The outline turned by `frame.rotation` about the midpoint of frame.spineStart–spineEnd: the
// element as the bend sees it, e.g. for the rotated candidates' LR functions (3.3.6):
//   frame = strokeFrameFor(outline, s0, s1, r);
//   lr = elementLRFunction(rotatedElement(outline, frame), s0, s1, n);
Region rotatedElement(const Region& outline, const StrokeFrame& frame);

// Edges are subdivided to at most `maxEdge` (in the element's units, before mapping) so that
// they follow the curve. A map with one reflection reverses orientation: the bent rings are
// then reversed so that counter-clockwise rings stay counter-clockwise (bendRegion also
// re-normalises). Points beyond the frame's extent continue straight past the streamline's
// ends. Bad input (maxEdge <= 0, a degenerate frame or streamline, widthScale < 0) throws
// InputError.
Ring bendRing(const Ring& ring, const StrokeFrame& frame, const Polyline& streamline, double maxEdge);
Region bendRegion(const Region& region, const StrokeFrame& frame, const Polyline& streamline, double maxEdge);
// The element's art with paint kept; stroke widths are scaled by the geometric mean
// sqrt(lengthScale * widthScale) of the two scales (lengthScale = streamline length / frame
// extent), which keeps a stroke's painted area in proportion to the element's.
std::vector<Shape> bendShapes(const std::vector<Shape>& shapes, const StrokeFrame& frame,
                              const Polyline& streamline, double maxEdge);

// The largest widthScale (at most `maxScale`) for which the bent outline stays inside `blob`,
// to a relative precision of 1e-3; 0 when even a sliver (1e-6 maxScale) does not fit.
// `frame.widthScale` is ignored. Starts from the LR functions' estimate and bisects with a
// grid-based containment test (no Clipper).
double fitWidthScale(const Region& outline, StrokeFrame frame, const Polyline& streamline,
                     const Region& blob, double maxEdge, double maxScale);
// After fitWidthScale: widens each side of the element, part by part, where the blob leaves
// room farther than `margin` from its edge (along the streamline's normals), by at most
// `maxWiden` × the uniform width, smoothly (the profile changes by at most
// 3 % of the width per 32nd of the length), so that a teardrop's thin end or a leaf in an
// uneven blob fills more of it. Sets frame.widenLeft/Right (cleared: none; maxWiden ≤ 1
// leaves them empty). The largest share of the profile that keeps the outline in the blob is
// kept, to 1/128.
void fitWidening(const Region& outline, StrokeFrame& frame, const Polyline& streamline, const Region& blob,
                 double margin, double maxEdge, double maxWiden);

}  // namespace pak
