// packFlow: FLOWPAK's pipeline (thesis 3.3): field and streamlines per container, blobs,
// initial placement, then the iterative refinement of Algorithm 2 over all containers.
#include "pak/flow/flow.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>

#include "flow/blobs.hpp"
#include "flow/flow_density.hpp"
#include "flow/flow_prototype.hpp"
#include "flow/streamline_shift.hpp"
#include "flow/streamlines.hpp"
#include "pak/error.hpp"
#include "pak/limits.hpp"
#include "pak/geom/clipping.hpp"
#include "pak/geom/closest_point.hpp"
#include "pak/geom/resample.hpp"
#include "pak/geom/simplify.hpp"
#include "pak/geom/verify.hpp"
#include "pak/sim/packing.hpp"
#include "sim/deadline.hpp"
#include "sim/packing_setup.hpp"
#include "sim/parallel.hpp"

namespace pak {
namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// The thesis lets the width grow "as wide as possible"; a cap on how much wider than the
// length scale an element may become keeps a lone element in a wide blob recognisable.
constexpr double kMaxWidthOverLengthScale = 2.5;
// A skin is grown from its outline simplified within this share of the spacing (skinOf).
constexpr double kSkinTolerance = 0.1;

// Each error names the option as `pak flow` spells it (the flag is also the --config key).
void validate(const FlowOptions& o) {
  auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  auto automaticOrPositive = [](double v) { return std::isfinite(v) && v >= 0.0; };  // 0: automatic
  if (o.count < 1 || o.count > 100000) throw InputError("--count", "must be 1 to 100000");
  if (!automaticOrPositive(o.gap)) throw InputError("--gap", "must be a positive number (0: automatic)");
  if (!(o.stopRatio > 0.0 && o.stopRatio <= 1.0)) throw InputError("--stop-ratio", "must be in (0, 1]");
  if (!automaticOrPositive(o.minLength)) throw InputError("--min-length", "must be a positive number (0: automatic)");
  if (!automaticOrPositive(o.maxLength) || (o.maxLength > 0.0 && o.minLength > o.maxLength))
    throw InputError("--max-length", "must be a positive number (0: automatic), at least --min-length");
  if (!positive(o.sampleSpacing)) throw InputError("--sample-spacing", "must be a positive number");
  if (o.sampleSpacing < limits::kMinSampleSpacing)
    throw InputError("--sample-spacing", "must be at least " + messageNumber(limits::kMinSampleSpacing) + " canonical units");
  if (o.gap != 0.0 && o.gap < limits::kMinFlowGap)
    throw InputError("--gap", "must be 0 (automatic) or at least " + messageNumber(limits::kMinFlowGap) + " canonical unit");
  checkRunOptions(o.run);
  if (o.fieldResolution < 8 || o.fieldResolution > 4096) throw InputError("--field-resolution", "must be 8 to 4096");
  if (o.blobResolution < 16 || o.blobResolution > 4096) throw InputError("--blob-resolution", "must be 16 to 4096");
  if (o.lrSamples < 4 || o.lrSamples > 10000) throw InputError("--lr-samples", "must be 4 to 10000");
  if (!std::isfinite(o.spacing)) throw InputError("--spacing", "must be a number (≥ 0; negative: automatic)");
  if (o.iterations < 0 || o.iterations > 10000) throw InputError("--iterations", "must be 0 to 10000");
  if (!(std::isfinite(o.timeLimit) && o.timeLimit >= 0.0)) throw InputError("--time-limit", "must be a number of seconds ≥ 0 (0: none)");
  if (!(std::isfinite(o.widen) && o.widen >= 1.0 && o.widen <= 3.0)) throw InputError("--widen", "must be 1 to 3 (1: uniform width, as in the thesis)");
  if (!(std::isfinite(o.widenMargin) && o.widenMargin >= 0.0 && o.widenMargin <= 10.0)) throw InputError("--widen-margin", "must be 0 to 10 (spacings)");
  if (!(o.growthTolerance > 0.0 && o.growthTolerance <= 1.0)) throw InputError("--growth-tolerance", "must be in (0, 1]");
  if (!positive(o.growthLimit)) throw InputError("--growth-limit", "must be a positive number");
  if (o.maxRotationDegrees < 0 || o.maxRotationDegrees > 45) throw InputError("--max-rotation", "must be 0 to 45 degrees");
  if (o.infillEvery < 0) throw InputError("--infill-every", "must be ≥ 0 (0: no infill)");
  if (!(std::isfinite(o.infillWidth) && o.infillWidth > 0.0 && o.infillWidth <= 10.0)) throw InputError("--infill-width", "must be in (0, 10] (gaps)");
  if (!(std::isfinite(o.infillMinArea) && o.infillMinArea >= 0.0 && o.infillMinArea <= 10.0)) throw InputError("--infill-min-area", "must be 0 to 10 (shares of the median element)");
  if (!(std::isfinite(o.fillGapsInset) && o.fillGapsInset >= 0.0)) throw InputError("--fill-gaps-inset", "must be ≥ 0");
  if (o.mirror && !(std::isfinite(o.mirror->from.x) && std::isfinite(o.mirror->from.y) && std::isfinite(o.mirror->to.x) &&
                    std::isfinite(o.mirror->to.y) && o.mirror->from != o.mirror->to))
    throw InputError("--mirror", "needs two different points with finite coordinates");
}

// Whether most of the line's samples lie in the region or within `reach` of its boundary
// (boundary-following guides run along the container's edge, half in and half out).
bool mostlyIn(const Polyline& line, const Region& region, double reach, double spacing) {
  Polyline samples = resamplePolyline(line, spacing);
  int near = 0;
  for (Vec2 p : samples)
    if (pointInRegion(p, region) || closestPointOnBoundary(p, region).distance <= reach) ++near;
  return 2 * near >= static_cast<int>(samples.size());
}

// The longest run of the streamline inside `space` (sampled at `step`).
Polyline longestRunInside(const Polyline& line, const Region& space, double step) {
  Polyline samples = resamplePolyline(line, step);
  Polyline best, run;
  for (Vec2 p : samples) {
    if (pointInRegion(p, space)) {
      run.push_back(p);
      if (run.size() > best.size()) best = run;
    } else {
      run.clear();
    }
  }
  return best;
}

// The polygons of `space` that the streamline's samples fall in most.
Region partAround(const Region& space, const Polyline& line) {
  if (space.size() <= 1) return space;
  std::vector<int> hits(space.size(), 0);
  for (Vec2 p : line)
    for (std::size_t k = 0; k < space.size(); ++k)
      if (pointInPolygon(p, space[k])) ++hits[k];
  auto best = std::max_element(hits.begin(), hits.end()) - hits.begin();
  return Region{space[static_cast<std::size_t>(best)]};
}

struct Placement {
  bool ok = false;
  int type = -1;
  StrokeFrame frame;
  Polyline streamline;
  Region outline;
  std::vector<Shape> art;  // bent, paint kept
  double area = 0.0;
};

class FlowPacker {
 public:
  FlowPacker(const Scene& scene, const Library& library, const FlowOptions& options, const FlowCallbacks& callbacks)
      : scene_(scene), library_(library), options_(options), callbacks_(callbacks) {}

  FlowPacking run();

 private:
  void setUp();
  void packContainer(int k);
  Placement place(const FlowElement& e, const Region& blob, const Polyline& streamline, bool allowRotation) const;
  Region othersNear(std::size_t i, const Box& box) const;
  Region placementSpace(std::size_t i, const Region& blob) const;
  Region placementSpace(const Region& blob, const Region& othersSkins) const;
  Region skinOf(const Region& outline) const;
  void accept(std::size_t i, const Placement& p);
  // One element's refinement step, proposed from the current state (see refine).
  struct Step {
    Placement placement;
    Region blob;       // the grown blob (growing)
    bool tried = false;
  };
  Box stepReach(std::size_t i) const;
  std::vector<std::vector<std::size_t>> waves(const std::vector<std::size_t>& order) const;
  Step proposeShift(std::size_t i) const;
  Step proposeGrowth(std::size_t i) const;
  ShiftOptions shiftOptions() const;
  void refine();
  int infill();
  void fillGaps();
  void mirror();
  void report(const std::string& phase, int iteration);
  double totalArea() const;

  const Scene& scene_;
  const Library& library_;
  FlowOptions options_;
  const FlowCallbacks& callbacks_;
  PackingSetup setup_;              // the frame, the separate containers and the fixed art
  const Library* types_ = nullptr;  // every library the containers use
  std::vector<FlowPrototype> prototypes_;
  double unit_ = 1.0;  // input units per canonical unit
  Region freeShrunk_;  // free space inset by spacing / 2: where element art may go
  std::vector<Region> skins_;  // each element's outline grown by `spacing`
  FlowPacking packing_;
  Deadline deadline_{Clock::now(), 0.0};  // set when the run starts
};

FlowPacking FlowPacker::run() {
  deadline_ = Deadline(Clock::now(), options_.timeLimit, options_.run.stopRequest);
  setUp();
  auto t = Clock::now();
  for (int k = 0; k < static_cast<int>(packing_.containers.size()); ++k) packContainer(k);
  packing_.areaPerIteration.push_back(totalArea());
  report("placement", 0);
  if (callbacks_.onIteration) callbacks_.onIteration(packing_, 0);
  packing_.seconds.placement += secondsSince(t);
  t = Clock::now();
  refine();
  packing_.seconds.refinement = secondsSince(t);
  t = Clock::now();
  if (options_.fillGaps) fillGaps();
  if (options_.mirror) mirror();
  packing_.seconds.extras = secondsSince(t);
  return std::move(packing_);
}

void FlowPacker::setUp() {
  // l_canvas (3.3.1) spans the containers and the fixed elements; FLOWPAK works in input
  // units, its canonical distances scaled by l_canvas / 1000.
  // Its booleans all run at Clipper's default precision.
  setup_ = preparePacking(scene_, library_, {.frameSpansFixed = true, .clip = ClipOptions{}});
  types_ = &setup_.types(library_);
  if (types_->empty()) throw InputError("--elements", "the element library is empty");
  const Box box = setup_.frameBox;
  const double lCanvas = setup_.side;
  unit_ = lCanvas / 1000.0;
  packing_.canonicalScale = 1.0 / unit_;

  std::vector<Region> regions = setup_.containers.regions;
  if (options_.mirror) {  // a square reaching past the containers on the packed side
    const Vec2 centre = (box.min + box.max) * 0.5;
    const double reach = length(box.max - box.min) + distance(centre, options_.mirror->reflect(centre)) + lCanvas;
    Region side{options_.mirror->packedSide(centre, reach)};
    normalizeOrientation(side);
    for (Region& r : regions) r = intersect(r, side);
    if (std::all_of(regions.begin(), regions.end(), [](const Region& r) { return r.empty(); }))
      throw InputError("--mirror", "the line leaves no part of the containers on its packed side (the left of x=…, "
                                   "above y=…, or left of the walk from the first point to the second)");
  }
  packing_.fixedArt = setup_.fixedPainted;
  packing_.containers = regions;
  packing_.container = unite(regions);
  packing_.freeSpace = subtract(packing_.container, packing_.fixedArt);
  if (area(packing_.freeSpace) <= 0.0) throw InputError(scene_.source, "the fixed elements leave no free space");

  std::vector<double> aspects;
  for (const ElementArt& e : *types_) {
    const FlowPrototype& p = prototypes_.emplace_back(flowPrototype(e, options_.maxRotationDegrees, options_.lrSamples));
    aspects.push_back(p.lr[0].length / (p.lr[0].maxLeft + p.lr[0].maxRight));
  }
  packing_.density = resolveDensity(options_, area(packing_.freeSpace) / (unit_ * unit_), medianAspect(aspects));
  options_.gap = packing_.density.gap;
  options_.minLength = packing_.density.minLength;
  options_.maxLength = packing_.density.maxLength;
  options_.spacing = packing_.density.spacing;
  // Distances in input units from here on.
  for (double* d : {&options_.gap, &options_.minLength, &options_.maxLength, &options_.sampleSpacing,
                    &options_.spacing, &options_.growthLimit, &options_.fillGapsInset})
    *d *= unit_;
  freeShrunk_ = options_.spacing > 0.0 ? offset(packing_.freeSpace, -0.5 * options_.spacing) : packing_.freeSpace;
}

void FlowPacker::report(const std::string& phase, int iteration) {
  if (!callbacks_.onProgress) return;
  FlowProgress p;
  p.phase = phase;
  p.iteration = iteration;
  p.iterations = options_.iterations;
  p.elements = static_cast<int>(packing_.elements.size());
  p.elementArea = totalArea() / std::max(1e-300, area(packing_.freeSpace));
  callbacks_.onProgress(p);
}

double FlowPacker::totalArea() const {
  double a = 0.0;
  for (const FlowElement& e : packing_.elements) a += e.area;
  return a;
}

void FlowPacker::packContainer(int k) {
  const Region& region = packing_.containers[static_cast<std::size_t>(k)];
  if (region.empty()) {  // a container wholly on the mirrored side
    packing_.fields.emplace_back();
    return;
  }
  const double reach = 2.0 * options_.sampleSpacing;
  std::vector<Polyline> guides, spines;
  for (const Polyline& g : scene_.guides)
    if (mostlyIn(g, region, reach, options_.sampleSpacing)) guides.push_back(g);
  for (const Polyline& s : scene_.spines)
    if (mostlyIn(s, region, 0.0, options_.sampleSpacing)) spines.push_back(s);
  if (guides.empty())
    throw InputError(scene_.source, "container " + std::to_string(k + 1) +
                                        " has no direction guide: draw at least one stroke in the `guides` layer over it");

  auto t = Clock::now();
  report("field", 0);
  VectorFieldOptions fieldOptions;
  fieldOptions.sampleSpacing = options_.sampleSpacing;
  fieldOptions.resolution = options_.fieldResolution;
  packing_.fields.push_back(buildVectorField(region, guides, fieldOptions));
  const VectorField& field = packing_.fields.back();
  packing_.seconds.field += secondsSince(t);

  t = Clock::now();
  report("streamlines", 0);
  StreamlineOptions lineOptions;
  // A container's own `data-gap` sets its density (thesis Fig. 3.16: sparse and dense regions).
  const double ownGap = scene_.containers.empty() ? 0.0 : scene_.containers[static_cast<std::size_t>(k)].gap;
  lineOptions.gap = ownGap > 0.0 ? ownGap * unit_ : options_.gap;
  lineOptions.stopRatio = options_.stopRatio;
  lineOptions.minLength = options_.minLength;
  lineOptions.maxLength = options_.maxLength;
  lineOptions.sampleSpacing = options_.sampleSpacing;
  lineOptions.seed = options_.run.seed + static_cast<std::uint64_t>(k);
  // Streamlines run where art may go (the free space inset by spacing / 2), so those seeded on
  // the boundary, which line the container, can carry an element.
  StreamlineInput input;
  input.container = intersect(region, freeShrunk_);
  input.guides = guides;
  input.fixedStreamlines = spines;
  std::vector<Polyline> lines = traceStreamlines(field, input, lineOptions);
  packing_.streamlines.insert(packing_.streamlines.end(), lines.begin(), lines.end());
  packing_.seconds.streamlines += secondsSince(t);

  t = Clock::now();
  report("blobs", 0);
  std::vector<Polyline> all = spines;  // fixed spines first, then the traced ones
  all.insert(all.end(), lines.begin(), lines.end());
  BlobOptions blobOptions;
  blobOptions.resolution = options_.blobResolution;
  std::vector<Region> blobs = computeBlobs(intersect(region, packing_.freeSpace), all, blobOptions);
  packing_.seconds.blobs += secondsSince(t);

  t = Clock::now();
  report("placement", 0);
  for (std::size_t j = 0; j < all.size(); ++j) {
    FlowElement e;
    e.container = k;
    e.fixedSpine = j < spines.size();
    e.blob = blobs[j];
    e.streamline = e.fixedSpine ? all[j] : extendToBlob(all[j], blobs[j], field, 0.5 * options_.sampleSpacing);
    packing_.elements.push_back(std::move(e));
    skins_.emplace_back();
    std::size_t i = packing_.elements.size() - 1;
    Placement p = place(packing_.elements[i], placementSpace(i, packing_.elements[i].blob),
                        packing_.elements[i].streamline, false);
    if (p.ok) {
      accept(i, p);
    } else {
      packing_.elements.pop_back();
      skins_.pop_back();
    }
  }
  packing_.seconds.placement += secondsSince(t);
}

// The other elements' skins whose bounds meet `box`, as one region.
Region FlowPacker::othersNear(std::size_t i, const Box& box) const {
  std::vector<Region> near;
  for (std::size_t j = 0; j < packing_.elements.size(); ++j)
    if (j != i && !skins_[j].empty() && bounds(skins_[j]).overlaps(box)) near.push_back(skins_[j]);
  return unite(near);
}

// Where element i's art may go inside `blob`: the inset free space, away from the others by
// `spacing`.
Region FlowPacker::placementSpace(std::size_t i, const Region& blob) const {
  Region space = intersect(blob, freeShrunk_);
  if (space.empty()) return space;
  return subtract(space, othersNear(i, bounds(space)));
}

// The same, given the others' skins around the whole blob (gathered once per step).
Region FlowPacker::placementSpace(const Region& blob, const Region& othersSkins) const {
  Region space = intersect(blob, freeShrunk_);
  return space.empty() ? space : subtract(space, othersSkins);
}

namespace {
// A fold: a ring of `bent` crosses itself where the same ring of `drawn` does not (as the
// report counts them, checkSelfIntersections).
bool foldsOverItself(const std::vector<Ring>& bent, const std::vector<Ring>& drawn) {
  for (std::size_t k = 0; k < bent.size() && k < drawn.size(); ++k)
    if (ringSelfIntersects(bent[k]) && !ringSelfIntersects(drawn[k])) return true;
  return false;
}

std::vector<Ring> ringsOf(const Region& region) {
  std::vector<Ring> rings;
  for (const Polygon& polygon : region) {
    rings.push_back(polygon.outer);
    rings.insert(rings.end(), polygon.holes.begin(), polygon.holes.end());
  }
  return rings;
}

// The longer of the two parts of `line` on either side of its sharpest turn: the vertex where
// the direction over `reach` of arclength before it and after it turns the most.
Polyline longerSideOfSharpestTurn(const Polyline& line, double reach) {
  const std::size_t n = line.size();
  if (n < 3) return line;
  std::vector<double> along(n, 0.0);
  for (std::size_t k = 1; k < n; ++k) along[k] = along[k - 1] + distance(line[k - 1], line[k]);
  std::size_t sharpest = 0, before = 0, after = 0;
  double most = -1.0;
  for (std::size_t k = 1; k + 1 < n; ++k) {
    while (along[k] - along[before] > reach) ++before;
    while (after + 1 < n && (after <= k || along[after] - along[k] < reach)) ++after;
    const Vec2 in = line[k] - line[before], out = line[after] - line[k];
    if (lengthSquared(in) == 0.0 || lengthSquared(out) == 0.0) continue;
    const double turn = std::abs(std::atan2(cross(in, out), dot(in, out)));
    if (turn > most) most = turn, sharpest = k;
  }
  if (most < 0.0) return line;
  const bool head = along[sharpest] >= along[n - 1] - along[sharpest];
  return head ? Polyline(line.begin(), line.begin() + static_cast<std::ptrdiff_t>(sharpest) + 1)
              : Polyline(line.begin() + static_cast<std::ptrdiff_t>(sharpest), line.end());
}
}  // namespace

// Thesis 3.3.5: the element and reflection whose LR function is closest to the blob's
// (eq. 3.1), rotations ±1…max° too during refinement, bent along the streamline and made as
// wide as fits.
Placement FlowPacker::place(const FlowElement& e, const Region& spaceAll, const Polyline& streamline,
                            bool allowRotation) const {
  Placement best;
  if (spaceAll.empty() || streamline.size() < 2) return best;
  Region space = partAround(spaceAll, streamline);
  Polyline spine = e.fixedSpine ? streamline
                                : extendToBlob(longestRunInside(streamline, space, 0.25 * options_.sampleSpacing), space,
                                               packing_.fields[static_cast<std::size_t>(e.container)],
                                               0.25 * options_.sampleSpacing);
  const std::vector<int>& types = setup_.containers.typesOf[static_cast<std::size_t>(e.container)];
  std::vector<LRFunction> candidates;
  std::vector<std::pair<int, int>> which;  // (type, rotation)
  for (int type : types) {
    const FlowPrototype& p = prototypes_[static_cast<std::size_t>(type)];
    int rotations = allowRotation ? static_cast<int>(p.rotations.size()) : 1;
    for (int r = 0; r < rotations; ++r) {
      candidates.push_back(p.lr[static_cast<std::size_t>(r)]);
      which.emplace_back(type, r);
    }
  }
  // A turn sharper than the element is wide folds it over itself (thesis 3.5): the spine is
  // cut at its sharpest turn and the longer part tried, a few times, else no placement here
  // (narrowing the element or trying the next best instead fill no more: docs/flowpak.md).
  constexpr int kCuts = 4;
  for (int cut = 0;; ++cut) {
    if (spine.size() < 2 || polylineLength(spine) < 0.25 * options_.minLength) return best;
    LRFunction blobLR = blobLRFunction(space, spine, options_.lrSamples);
    LRMatch match = bestMatch(candidates, blobLR);
    if (match.candidate < 0) return best;
    auto [type, rotation] = which[static_cast<std::size_t>(match.candidate)];
    const FlowPrototype& p = prototypes_[static_cast<std::size_t>(type)];
    StrokeFrame frame = p.frames[static_cast<std::size_t>(rotation)];
    frame.reflection = match.reflection;
    const double extent = frame.alongMax - frame.alongMin;
    const double lengthScale = polylineLength(spine) / extent;
    const double maxEdge = extent / 100.0;
    frame.widthScale = fitWidthScale(p.outline, frame, spine, space, maxEdge, kMaxWidthOverLengthScale * lengthScale);
    if (!(frame.widthScale > 0.0)) return best;
    fitWidening(p.outline, frame, spine, space, options_.widenMargin * options_.spacing, maxEdge, options_.widen);
    Region outline = bendRegion(p.outline, frame, spine, maxEdge);
    std::vector<Shape> art = bendShapes(p.art->shapes, frame, spine, maxEdge);
    // The outline, and the art: the outline alone can miss a fold of a part inside it.
    if (!options_.keepFolds && (foldsOverItself(ringsOf(outline), ringsOf(p.outline)) ||
                                foldsOverItself(artRings(art), artRings(p.art->shapes)))) {
      if (cut == kCuts || e.fixedSpine) return best;
      spine = longerSideOfSharpestTurn(spine, 2.0 * options_.sampleSpacing);
      continue;
    }
    best.ok = true;
    best.type = type;
    best.frame = frame;
    best.streamline = spine;
    best.outline = std::move(outline);
    best.art = std::move(art);
    best.area = area(best.outline);
    return best;
  }
}

// The outline grown by `spacing`: what the other elements keep out of. Grown from the outline
// simplified within a tenth of the spacing, and by that much more, it holds the exact offset
// with about a tenth of the vertices (every boolean near the element reads it).
Region FlowPacker::skinOf(const Region& outline) const {
  if (!(options_.spacing > 0.0)) return outline;
  const double tolerance = kSkinTolerance * options_.spacing;
  return offset(simplifyRegion(outline, tolerance), options_.spacing + tolerance);
}

void FlowPacker::accept(std::size_t i, const Placement& p) {
  FlowElement& e = packing_.elements[i];
  const FlowPrototype& proto = prototypes_[static_cast<std::size_t>(p.type)];
  e.libraryIndex = p.type;
  e.source = proto.art->source;
  e.frame = p.frame;
  e.streamline = p.streamline;
  e.outline = p.outline;
  e.area = p.area;
  e.art = p.art;
  skins_[i] = skinOf(e.outline);
}

// Algorithm 2: each iteration shifts every streamline, then grows every blob, smallest
// elements first, keeping a new placement when its area is at least α times the old one.
//
// In parallel, with the sequential result: a phase's steps run in waves. A step joins the
// first wave after those of every earlier step (in the sequential order) whose reach meets
// its own; the steps of a wave are proposed together from the state the waves before left,
// then taken. Each step thus sees exactly what the sequential loop would show it, so the
// result does not depend on the thread count, and no work is thrown away.
void FlowPacker::refine() {
  ThreadPool pool(options_.run.threads);
  auto smallestFirst = [&] {
    std::vector<std::size_t> order(packing_.elements.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return packing_.elements[a].area < packing_.elements[b].area; });
    return order;
  };
  std::vector<Step> steps;
  // Whether the phase ran to its end (the deadline stops it between waves).
  auto phase = [&](bool shifting) {
    steps.assign(packing_.elements.size(), Step{});
    for (const std::vector<std::size_t>& wave : waves(smallestFirst())) {
      if (deadline_.passed()) return false;
      pool.parallelFor(wave.size(), 1, [&](std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k)
          steps[wave[k]] = shifting ? proposeShift(wave[k]) : proposeGrowth(wave[k]);
      });
      for (std::size_t i : wave) {
        Step& step = steps[i];
        FlowElement& e = packing_.elements[i];
        if (!shifting) e.blob = std::move(step.blob);  // kept grown whether or not the element is
        if (!step.tried) continue;
        ++packing_.placementsTried;
        if (step.placement.ok && step.placement.area >= options_.growthTolerance * e.area) {
          accept(i, step.placement);
          ++packing_.placementsAccepted;
        }
      }
    }
    return true;
  };
  for (int iteration = 1; iteration <= options_.iterations; ++iteration) {
    // Shifting streamlines (fixed spines stay where the artist drew them), then growing blobs.
    if (!phase(true) || !phase(false)) {
      packing_.stopReason = deadline_.requested() ? StopReason::Interrupted : StopReason::TimeLimit;
      break;  // the waves done are kept: each accepted step left the packing clean
    }
    if (options_.infillEvery > 0 && iteration % options_.infillEvery == 0) packing_.infilled += infill();
    packing_.iterations = iteration;
    packing_.areaPerIteration.push_back(totalArea());
    report("refinement", iteration);
    if (callbacks_.onIteration) callbacks_.onIteration(packing_, iteration);
  }
}

// Everything a step of element i reads (the others' skins whose bounds meet this box) or
// changes (its blob, its skin before and after) lies in this box: the new outline stays in the
// blob grown by at most g_limit, and its skin reaches spacing and twice the simplification
// tolerance beyond.
Box FlowPacker::stepReach(std::size_t i) const {
  Box box = bounds(packing_.elements[i].blob);
  if (!skins_[i].empty()) box.add(bounds(skins_[i]));
  if (box.empty()) return box;
  const double margin = options_.spacing * (1.0 + 2.0 * kSkinTolerance) + 2.0 * options_.growthLimit;
  box.min -= Vec2{margin, margin};
  box.max += Vec2{margin, margin};
  return box;
}

// The steps of `order` in waves: each step one wave after the latest earlier step whose reach
// meets its own (steps of one wave are independent of each other and of every later wave's
// earlier-ordered steps).
std::vector<std::vector<std::size_t>> FlowPacker::waves(const std::vector<std::size_t>& order) const {
  std::vector<Box> reach(order.size());
  std::vector<std::size_t> wave(order.size(), 0);
  std::vector<std::vector<std::size_t>> out;
  for (std::size_t k = 0; k < order.size(); ++k) {
    reach[k] = stepReach(order[k]);
    for (std::size_t j = 0; j < k; ++j)
      if (reach[j].overlaps(reach[k])) wave[k] = std::max(wave[k], wave[j] + 1);
    if (wave[k] == out.size()) out.emplace_back();
    out[wave[k]].push_back(order[k]);
  }
  return out;
}

// Element i's streamline shifted (eq. 3.2) and the element placed on it again.
FlowPacker::Step FlowPacker::proposeShift(std::size_t i) const {
  Step step;
  const FlowElement& e = packing_.elements[i];
  if (e.fixedSpine) return step;
  const VectorField& field = packing_.fields[static_cast<std::size_t>(e.container)];
  // The placement space reads within the blob, the shifted path's lattice spans the blob's
  // widths: the others further off than the step's reach do not bear on it.
  const Region occupied = othersNear(i, stepReach(i));
  LRFunction widths = blobLRFunction(e.blob, e.streamline, options_.lrSamples);
  Polyline shifted = shiftStreamline(e.streamline, field, occupied, packing_.freeSpace, widths.maxLeft, widths.maxRight,
                                     shiftOptions());
  shifted = extendToBlob(shifted, e.blob, field, 0.5 * options_.sampleSpacing);
  step.placement = place(e, placementSpace(e.blob, occupied), shifted, true);
  step.tried = true;
  return step;
}

// Element i's blob grown by g_limit and the element placed in it again.
FlowPacker::Step FlowPacker::proposeGrowth(std::size_t i) const {
  Step step;
  const FlowElement& e = packing_.elements[i];
  const VectorField& field = packing_.fields[static_cast<std::size_t>(e.container)];
  // Grown up to the others' skins, not their outlines: a blob that crept through the channels
  // between them would wrap around its neighbours, as large as no element can use and slower
  // with every iteration (docs/flowpak.md, "Speed").
  const Region occupied = othersNear(i, stepReach(i));
  step.blob = growBlob(e.blob, occupied, packing_.freeSpace, options_.growthLimit);
  Polyline extended = e.fixedSpine ? e.streamline : extendToBlob(e.streamline, step.blob, field, 0.5 * options_.sampleSpacing);
  step.placement = place(e, placementSpace(step.blob, occupied), extended, true);
  step.tried = true;
  return step;
}

ShiftOptions FlowPacker::shiftOptions() const {
  ShiftOptions shift;
  shift.limit = options_.growthLimit;
  shift.fieldWeight = options_.shiftFieldWeight;
  shift.distanceWeight = options_.shiftDistanceWeight;
  shift.fieldPower = options_.shiftFieldPower;
  shift.neighbours = options_.shiftNeighbours;
  return shift;
}

// Each piece of room (the free space at least `spacing` from every element) wide enough for
// an element: a streamline traced along the field through the middle of its widest part, and
// the element that fits there (FlowOptions::infillEvery). Returns how many were kept.
int FlowPacker::infill() {
  if (packing_.elements.empty()) return 0;
  const Region room = subtract(freeShrunk_, unite(skins_));
  const Region cores = offset(room, -0.5 * options_.infillWidth * options_.gap);
  std::vector<double> areas;
  for (const FlowElement& e : packing_.elements) areas.push_back(e.area);
  std::nth_element(areas.begin(), areas.begin() + static_cast<std::ptrdiff_t>(areas.size() / 2), areas.end());
  const double minArea = options_.infillMinArea * areas[areas.size() / 2];
  const double step = 0.5 * options_.sampleSpacing;
  int added = 0;
  for (const Polygon& core : cores) {
    // The core's centroid, or for a bent core its vertex nearest the centroid (still a core
    // width deep in the room).
    const Vec2 c = centroid(core.outer);
    Vec2 seed = c;
    if (!pointInPolygon(c, core))
      seed = *std::min_element(core.outer.begin(), core.outer.end(),
                               [&](Vec2 a, Vec2 b) { return distance(a, c) < distance(b, c); });
    const auto k = std::find_if(packing_.containers.begin(), packing_.containers.end(),
                                [&](const Region& r) { return pointInRegion(seed, r); }) - packing_.containers.begin();
    const auto piece = std::find_if(room.begin(), room.end(), [&](const Polygon& p) { return pointInPolygon(seed, p); });
    if (k == static_cast<std::ptrdiff_t>(packing_.containers.size()) || piece == room.end()) continue;
    const VectorField& field = packing_.fields[static_cast<std::size_t>(k)];
    const Vec2 along = field.values.empty() ? Vec2{} : field.at(seed);
    if (!(length(along) > 0.0)) continue;
    FlowElement e;
    e.container = static_cast<int>(k);
    e.blob = Region{*piece};
    e.streamline = extendToBlob({seed - along * (0.5 * step), seed + along * (0.5 * step)}, e.blob, field, step);
    packing_.elements.push_back(std::move(e));
    skins_.emplace_back();
    const std::size_t i = packing_.elements.size() - 1;
    const Placement p = place(packing_.elements[i], placementSpace(i, packing_.elements[i].blob),
                              packing_.elements[i].streamline, true);
    if (p.ok && p.area >= minArea) {
      accept(i, p);
      ++added;
    } else {
      packing_.elements.pop_back();
      skins_.pop_back();
    }
  }
  return added;
}

// Figure 3.15: new shapes made from the negative space between the placed elements, inset
// from them and rounded by an opening so slivers vanish.
void FlowPacker::fillGaps() {
  const double inset = options_.fillGapsInset > 0.0 ? options_.fillGapsInset : 0.5 * options_.spacing;
  std::vector<Region> grown;
  for (const FlowElement& e : packing_.elements) grown.push_back(offset(e.outline, options_.spacing + inset));
  Region gaps = subtract(offset(packing_.freeSpace, -(0.5 * options_.spacing + inset)), unite(grown));
  const double round = 0.5 * options_.gap * 0.25;
  gaps = offset(offset(gaps, -round), round);
  const double minimumArea = 0.05 * options_.gap * options_.gap;
  for (const Polygon& polygon : gaps) {
    Region piece{polygon};
    double a = area(piece);
    if (a < minimumArea) continue;
    FlowElement e;
    e.source = "negative-space";
    e.outline = piece;
    e.area = a;
    Shape shape;
    shape.subpaths.push_back({polygon.outer, true});
    for (const Ring& h : polygon.holes) shape.subpaths.push_back({h, true});
    shape.fill = Color{140, 100, 70, 1.0};
    shape.stroke.reset();
    e.art.push_back(std::move(shape));
    packing_.gapElements.push_back(std::move(e));
  }
}

// Figure 3.13: the packed half reflected across the mirror line.
void FlowPacker::mirror() {
  const MirrorLine line = *options_.mirror;
  auto reflect = [&line](Vec2 p) { return line.reflect(p); };
  auto reflectRegion = [&](Region r) {
    for (Polygon& p : r) {
      for (Vec2& v : p.outer) v = reflect(v);
      for (Ring& h : p.holes)
        for (Vec2& v : h) v = reflect(v);
    }
    normalizeOrientation(r);
    return r;
  };
  packing_.infilled *= 2;
  for (auto* list : {&packing_.elements, &packing_.gapElements}) {
    const std::size_t n = list->size();
    for (std::size_t i = 0; i < n; ++i) {
      FlowElement e = (*list)[i];
      for (Shape& s : e.art)
        for (Subpath& sub : s.subpaths)
          for (Vec2& v : sub.points) v = reflect(v);
      e.outline = reflectRegion(e.outline);
      e.blob = reflectRegion(e.blob);
      for (Vec2& v : e.streamline) v = reflect(v);
      list->push_back(std::move(e));
    }
  }
  // The container as the artist drew it: both halves.
  packing_.containers = setup_.containers.regions;
  packing_.container = scene_.container;
  packing_.freeSpace = subtract(packing_.container, packing_.fixedArt);
}

}  // namespace

FlowPacking packFlow(const Scene& scene, const Library& library, const FlowOptions& options,
                     const FlowCallbacks& callbacks) try {
  validate(options);
  FlowPacker packer(scene, library, options, callbacks);
  return packer.run();
} catch (const InputError& error) {
  throw attributed(error, scene.source);
}

double flowFill(const FlowPacking& packing) {
  double a = 0.0;
  for (const FlowElement& e : packing.elements) a += e.area;
  for (const FlowElement& e : packing.gapElements) a += e.area;
  double free = area(packing.freeSpace);
  return free > 0.0 ? a / free : 0.0;
}

}  // namespace pak
