#pragma once
// Shared internals of the metrics: the packing's frame (clipping precision, arc tolerance),
// input checks, and the exact area measures every metric is built from. Not installed.
#include <functional>
#include <vector>

#include "pak/geom/clipping.hpp"
#include "pak/metrics/metrics.hpp"

namespace pak::metrics_internal {

struct Frame {
  Box box;                     // of the container
  double side = 0.0;           // of the container's bounding square
  double containerArea = 0.0;
  ClipOptions clip;
  OffsetOptions offset;
};

// Throws InputError for an empty container, no elements, or an element outside the container.
Frame makeFrame(const PackingGeometry& packing, double arcTolerance);
// Container minus the union of the element outlines.
Region negativeSpace(const PackingGeometry& packing, const Frame& frame);

// The packing with its element outlines simplified (Douglas–Peucker) to within the frame's
// arc tolerance, for every offset by r > 0: on dense real-world outlines Clipper spends most
// of an offset in the loops of tiny concave features, and the arc tolerance already bounds
// the error of each offset. The negative space at r = 0 uses the outlines as they are.
PackingGeometry simplifiedForOffsets(const PackingGeometry& packing, const Frame& frame);

// The union of `parts` as an operand of a boolean operation, without computing it: Clipper
// fills operands by non-zero winding with outer rings positive and holes negative, so listing
// the parts together covers exactly their union (a hole cancels only its own outer ring).
// Not a clean Region: use only as an operand.
Region unionOperand(std::vector<Region>&& parts, const Frame& frame);

// Area of the negative space eroded by a disc of radius r, over the container area.
double erodedRatio(const PackingGeometry& packing, const Region& negative, double r,
                   const Frame& frame);
// Largest r with a non-empty erosion, by bisection to ~1e-7 relative, starting from the
// bracket [guess - slack, guess + slack] when it holds.
double largestEmptyRadius(const PackingGeometry& packing, const Region& negative,
                          const Frame& frame, double guess = 0.0, double slack = 0.0);
// Four times the radius where the sampled Q falls to Q(0)/2 (Q(d_gap/4) = Q(0)/2 for stripes).
double gapFromCurve(const Curve& q);
// Runs body(k) for k in [0, count) on up to hardware_concurrency threads; each k is
// independent (Clipper instances are per call).
void parallelFor(int count, const std::function<void(int)>& body);

// The element pairs that can overlap once grown by up to `maxRadius`, with the distance
// between their outlines (0 where they already overlap): grown by r, a pair overlaps iff
// 2r > distance. Without `measureDistance` every distance is 0 (intersect them all).
struct ElementPair {
  int i = 0, j = 0;
  double distance = 0.0;
};
std::vector<ElementPair> nearPairs(const PackingGeometry& packing, double maxRadius,
                                   bool measureDistance = true);
// O(r) from those pairs.
double overlapRatio(const PackingGeometry& packing, const std::vector<ElementPair>& pairs,
                    double r, const Frame& frame);

// Q at `count` radii evenly spaced on [0, largest], the radii spread over the cores.
Curve contactCurve(const PackingGeometry& packing, const Region& negative, const Frame& frame,
                   double largest, int count);
// O at `count` radii evenly spaced on [0, maxRadius], likewise.
Curve overlapCurve(const PackingGeometry& packing, const std::vector<ElementPair>& pairs,
                   const Frame& frame, double maxRadius, int count);
// Distance from every free cell centre (in the negative space) to the nearest occupied cell,
// in the packing's units, and how many cell centres lie in the container.
struct GridDistances {
  std::vector<double> freeDistances;  // sorted ascending
  long long containerCells = 0;
  double cell = 0.0;
};
GridDistances gridDistances(const PackingGeometry& packing, const Region& negative,
                            const Frame& frame, int resolution);

}  // namespace pak::metrics_internal
