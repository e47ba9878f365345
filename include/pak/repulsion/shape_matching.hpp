#pragma once
// Fit-guided placement at salient container corners (thesis 4.7): curvature-integral shape
// descriptors (eq. 4.8–4.9) on the container and the element skins, sharp convex container
// corners, the 10 nearest element descriptors from a k-d tree, the global fit score Q
// (eq. 4.10–4.11) over a signed distance field, and the element pose that aligns the matched
// descriptors. All lengths are in the frame of the container given (Pak: canonical units).
#include <vector>

#include "pak/geom/polygon.hpp"

namespace pak {

struct ShapeMatchingOptions {
  int steps = 5;                       // n of eq. 4.9: the descriptor has 2n arclengths
  double tauFraction = 0.001;          // τ_obj = tauFraction × L_s
  double spacingFraction = 0.002;      // δ = spacingFraction × L_s (sample spacing)
  double cornerTurn = 0.3;             // a salient corner turns by at least this (radians)
  double cornerSeparationFraction = 0.2;  // salient corners at least this × L_s apart
  int neighbours = 10;                 // candidates per corner from the k-d tree
  double alpha = 1.0;                  // α of eq. 4.10: penalty per unit outside
  double beta = 0.001;                 // β of eq. 4.10: reward for hugging the boundary
  int fieldResolution = 1000;          // signed distance grid cells along L_s (thesis 1000)
};

// A closed ring resampled at even arclength spacing with its curvature-integral descriptors.
struct RingDescriptors {
  Ring samples;                  // evenly spaced, `spacing` apart, in the ring's direction
  double spacing = 0.0;
  std::vector<double> curvature; // |κ| at each sample
  std::vector<double> cumulative;// τ from sample 0 to sample i (size samples + 1; last = total)
  int steps = 0;
  // 2n values per sample: (l_n … l_1, r_1 … r_n) of eq. 4.9.
  std::vector<double> values;
  const double* descriptor(int sample) const { return values.data() + static_cast<std::size_t>(sample) * 2 * steps; }
  // Σ l_k + r_k, the descriptor's total length (short: a sharp feature).
  double totalLength(int sample) const;
  // The point reached after walking `signedArclength` from the sample (negative: backward).
  Vec2 pointAt(int sample, double signedArclength) const;
  // The 2n + 1 points P(t_-n) … P(t_0) … P(t_n) the descriptor's arclengths end at.
  std::vector<Vec2> descriptorPoints(int sample) const;
};

// Resamples `ring` (either orientation) at about `spacing` and computes the descriptors with
// objective τ_obj = `tauObjective` and n = `steps`.
RingDescriptors describeRing(const Ring& ring, double spacing, double tauObjective, int steps);

struct SalientCorner {
  Vec2 position;
  Vec2 inward;       // unit bisector pointing into the container
  double turn = 0.0; // exterior angle (radians, > 0 convex)
  int ring = 0;      // which of the described rings
  int sample = 0;    // sample index on that ring
};

// Salient convex corners (4.7): samples taken in increasing order of descriptor total length,
// kept when the turn between the samples two either side is convex and at least `minTurn`,
// and at least `minSeparation` from every corner kept before. Rings must have the region's
// interior on their left (outer rings counter-clockwise, holes clockwise).
std::vector<SalientCorner> salientCorners(const std::vector<RingDescriptors>& rings, double minTurn,
                                          double minSeparation);

// An element's pose at a corner: x ↦ scale · R(angle) · x + translation maps the element's
// skin frame onto the container as the matched descriptors align.
struct CornerMatch {
  int corner = 0;         // index in ShapeMatch::corners
  int element = 0;        // index of the element skin
  int elementSample = 0;  // matched sample on the (scaled) element skin
  Vec2 elementTip;        // that sample in the element's frame, unscaled
  double angle = 0.0;
  double scale = 1.0;
  Vec2 translation;
  double quality = 0.0;   // Q of eq. 4.11
};

struct ShapeMatch {
  std::vector<SalientCorner> corners;
  std::vector<CornerMatch> matches;  // at most one per corner, in corner order
  double sideLength = 0.0;           // L_s
};

// Matches element skins (closed rings in their own frames) to the salient corners of
// `container`. Each skin is scaled by `elementScale` (the thesis sizes elements to area
// 0.6 A_c / n_e) before it is described and scored.
ShapeMatch matchCorners(const Region& container, const std::vector<Ring>& elementSkins, double elementScale,
                        const ShapeMatchingOptions& options = {});

// The salient corners of a container given in any units: detected with the container scaled
// so that L_s = `canonicalSide` (τ_obj = 0.001 L_s is not scale-free, so the thesis's values
// hold in its ~1000-unit frame, as in Pak's canonical frame), returned in the input's units.
std::vector<SalientCorner> salientContainerCorners(const Region& container, const ShapeMatchingOptions& options = {},
                                                   double canonicalSide = 1000.0);

// Eq. 4.10 for a signed distance d (negative inside) with μ the half diagonal.
double fitScore(double signedDistance, double alpha, double beta, double mu);

}  // namespace pak
