#pragma once
// LR functions (thesis 3.3.2): how far a shape extends to the left and to the right of a
// spine, sampled at n_f points along it, and the least-squares matching of eq. 3.1.
#include <vector>

#include "pak/geom/polygon.hpp"

namespace pak {

// Raw extents in the shape's units; `normalisedLeft/Right` divide them by the largest
// extent on either side, so domain and range are [0, 1] (the scale-invariant function the
// thesis matches).
struct LRFunction {
  std::vector<double> left, right;  // extents at samples (i + 0.5) / n along the spine
  std::vector<double> normalisedLeft, normalisedRight;
  double length = 0.0;              // length of the spine the samples run along
  double maxLeft = 0.0, maxRight = 0.0;
};

// Left is the side of the counter-clockwise normal perp(end - start) (y up).
// An element's spine is a line: the samples run over the outline's whole extent along it,
// from the projection of its first point to that of its last, so `spineStart`/`spineEnd`
// give only the line's position and direction.
LRFunction elementLRFunction(const Region& outline, Vec2 spineStart, Vec2 spineEnd, int samples = 100);
// For a blob the spine is its (curved) streamline: extents are measured along the
// streamline's normals, from the start of the streamline to its end: the distance to the
// first crossing of the blob's boundary, 0 where the streamline point is outside the blob.
// Normals are those the skeletal stroke bends along (averaged at vertices, interpolated).
// Bad input (samples < 1, an empty outline, a degenerate spine/streamline) throws InputError.
LRFunction blobLRFunction(const Region& blob, const Polyline& streamline, int samples = 100);

// The four ways to lay an element on a streamline (3.3.2): reflect across the spine (swap L
// and R), along it (reverse L and R), or both.
enum class Reflection { None, AcrossSpine, AlongSpine, Both };

// The element's function as it reads after the reflection (AcrossSpine swaps L and R,
// AlongSpine reverses both, Both does both).
LRFunction reflected(const LRFunction& function, Reflection reflection);

// Eq. 3.1 between the element's normalised function, reflected, and the blob's. When the
// sample counts differ, the element's function is resampled (linearly, at the blob's sample
// positions) so the sum runs over the blob's samples.
double matchCost(const LRFunction& element, Reflection reflection, const LRFunction& blob);

struct LRMatch {
  int candidate = -1;  // index into the candidates
  Reflection reflection = Reflection::None;
  double cost = 0.0;
};
// The candidate and reflection of least cost; ties go to the lower index, then the order of
// the enum (deterministic). No candidates: candidate stays -1.
LRMatch bestMatch(const std::vector<LRFunction>& candidates, const LRFunction& blob);

}  // namespace pak
