#include "pak/repulsion/shape_matching.hpp"

#include <algorithm>
#include <cmath>
#include <nanoflann.hpp>
#include <numeric>

#include "pak/error.hpp"
#include "pak/geom/distance_field.hpp"
#include "pak/geom/resample.hpp"

namespace pak {

namespace {

// Signed turning angle at b of the path a → b → c (positive: left turn).
double turnAngle(Vec2 a, Vec2 b, Vec2 c) {
  Vec2 in = b - a, out = c - b;
  return std::atan2(cross(in, out), dot(in, out));
}

// The arclength along the ring where the cumulative τ first reaches `value` (forward) or last
// equals it (backward). τ is extended periodically: τ(s + P) = τ(s) + T.
double arclengthOfTau(const RingDescriptors& d, double value, bool forward) {
  const double total = d.cumulative.back();
  const double perimeter = d.spacing * static_cast<double>(d.samples.size());
  double laps = std::floor(value / total);
  double r = value - laps * total;
  if (r >= total) {  // rounding
    r = 0.0;
    laps += 1.0;
  }
  const auto begin = d.cumulative.begin(), end = d.cumulative.end();
  // Forward: first knot with C ≥ r; backward: first knot with C > r. Either way C is linear
  // between knot k - 1 and k (the trapezoid rule with linear interpolation inside a step).
  auto it = forward ? std::lower_bound(begin, end, r) : std::upper_bound(begin, end, r);
  std::size_t k = static_cast<std::size_t>(it - begin);
  double s = 0.0;
  if (k > 0 && k < d.cumulative.size()) {
    const double c0 = d.cumulative[k - 1], c1 = d.cumulative[k];
    s = d.spacing * (static_cast<double>(k - 1) + (c1 > c0 ? (r - c0) / (c1 - c0) : 0.0));
  } else if (k >= d.cumulative.size()) {
    s = perimeter;
  }
  return laps * perimeter + s;
}

// The similarity of 4.7's alignment: rotation and scale turn the chord between the element
// descriptor's endpoints onto the container's, and the matched centre points coincide.
struct Similarity {
  double angle = 0.0, scale = 1.0;
  Vec2 translation;
  Vec2 apply(Vec2 p) const { return rotated(p, angle) * scale + translation; }
};

Similarity alignDescriptors(const std::vector<Vec2>& element, const std::vector<Vec2>& container) {
  const Vec2 from = element.back() - element.front(), to = container.back() - container.front();
  const std::size_t centre = element.size() / 2;
  Similarity t;
  if (length(from) > 0.0 && length(to) > 0.0) {
    t.angle = std::atan2(cross(from, to), dot(from, to));
    // Elements were already sized for the packing: the fit may only nudge the size.
    t.scale = std::clamp(length(to) / length(from), 2.0 / 3.0, 1.5);
  }
  t.translation = container[centre] - rotated(element[centre], t.angle) * t.scale;
  return t;
}

// nanoflann's view of the element descriptors: point i has `dims` coordinates at data[i·dims].
struct DescriptorCloud {
  const std::vector<double>* data = nullptr;
  std::size_t dims = 0;
  std::size_t kdtree_get_point_count() const { return dims ? data->size() / dims : 0; }
  double kdtree_get_pt(std::size_t i, std::size_t d) const { return (*data)[i * dims + d]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const { return false; }
};
using DescriptorTree =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, DescriptorCloud>, DescriptorCloud, -1,
                                        std::size_t>;

}  // namespace

namespace {

// Every ring of a normalized region (outer rings, then their holes), interior on the left;
// degenerate rings (fewer than 3 distinct vertices) have no corners and are skipped.
std::vector<RingDescriptors> describeRegion(const Region& region, double spacing, double tau, int steps) {
  std::vector<RingDescriptors> rings;
  auto add = [&](const Ring& ring) {
    if (cleanRing(ring).size() >= 3 && std::abs(signedArea(ring)) > 0.0)
      rings.push_back(describeRing(ring, spacing, tau, steps));
  };
  for (const Polygon& p : region) {
    add(p.outer);
    for (const Ring& h : p.holes) add(h);
  }
  return rings;
}

}  // namespace

double RingDescriptors::totalLength(int sample) const {
  const double* v = descriptor(sample);
  return std::accumulate(v, v + 2 * steps, 0.0);
}

Vec2 RingDescriptors::pointAt(int sample, double signedArclength) const {
  const std::size_t n = samples.size();
  const double perimeter = spacing * static_cast<double>(n);
  double s = std::fmod(sample * spacing + signedArclength, perimeter);
  if (s < 0.0) s += perimeter;
  const double u = s / spacing;
  std::size_t k = std::min(static_cast<std::size_t>(u), n - 1);
  const double t = u - static_cast<double>(k);
  return samples[k] + (samples[(k + 1) % n] - samples[k]) * t;
}

std::vector<Vec2> RingDescriptors::descriptorPoints(int sample) const {
  const double* v = descriptor(sample);
  std::vector<Vec2> points(static_cast<std::size_t>(2 * steps + 1));
  points[steps] = samples[sample];
  double back = 0.0, ahead = 0.0;
  for (int k = 1; k <= steps; ++k) {
    back += v[steps - k];     // l_k
    ahead += v[steps + k - 1];  // r_k
    points[steps - k] = pointAt(sample, -back);
    points[steps + k] = pointAt(sample, ahead);
  }
  return points;
}

RingDescriptors describeRing(const Ring& input, double spacing, double tauObjective, int steps) {
  if (!(spacing > 0.0) || !(tauObjective > 0.0) || steps < 1)
    throw InputError("", "shape descriptors need a positive spacing, objective and step count");
  Ring ring = cleanRing(input);
  if (ring.size() < 3) throw InputError("", "shape descriptors need a ring of at least 3 vertices");
  RingDescriptors d;
  d.samples = resampleRing(ring, spacing);
  const std::size_t n = d.samples.size();
  d.spacing = perimeter(ring) / static_cast<double>(n);
  d.steps = steps;

  // |κ| at each sample: the turning angle over the sample's share δ of arclength (the
  // discrete curvature of the sampled polyline; it integrates to the exact total turn).
  d.curvature.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    d.curvature[i] = std::abs(turnAngle(d.samples[(i + n - 1) % n], d.samples[i], d.samples[(i + 1) % n])) / d.spacing;
  // Eq. 4.8 by the trapezoid rule between consecutive samples.
  d.cumulative.assign(n + 1, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    d.cumulative[i + 1] = d.cumulative[i] + 0.5 * d.spacing * (d.curvature[i] + d.curvature[(i + 1) % n]);
  if (!(d.cumulative.back() > 0.0)) throw InputError("", "shape descriptors need a curved ring");

  // Eq. 4.9: walk both ways in steps of τ_obj and record the arclengths walked.
  d.values.resize(n * 2 * static_cast<std::size_t>(steps));
  for (std::size_t i = 0; i < n; ++i) {
    double* v = d.values.data() + i * 2 * steps;
    const double s0 = static_cast<double>(i) * d.spacing, c0 = d.cumulative[i];
    double previousAhead = s0, previousBack = s0;
    for (int k = 1; k <= steps; ++k) {
      double ahead = arclengthOfTau(d, c0 + k * tauObjective, true);
      double back = arclengthOfTau(d, c0 - k * tauObjective, false);
      v[steps + k - 1] = std::max(0.0, ahead - previousAhead);  // r_k
      v[steps - k] = std::max(0.0, previousBack - back);        // l_k
      previousAhead = std::max(previousAhead, ahead);
      previousBack = std::min(previousBack, back);
    }
  }
  return d;
}

std::vector<SalientCorner> salientCorners(const std::vector<RingDescriptors>& rings, double minTurn,
                                          double minSeparation) {
  struct Candidate { double total; int ring, sample; };
  std::vector<Candidate> candidates;
  for (std::size_t r = 0; r < rings.size(); ++r)
    for (std::size_t i = 0; i < rings[r].samples.size(); ++i)
      candidates.push_back({rings[r].totalLength(static_cast<int>(i)), static_cast<int>(r), static_cast<int>(i)});
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& a, const Candidate& b) { return a.total < b.total; });
  std::vector<SalientCorner> corners;
  const double separation2 = minSeparation * minSeparation;
  for (const Candidate& c : candidates) {
    const Ring& s = rings[c.ring].samples;
    const std::size_t n = s.size();
    const Vec2 before = s[(c.sample + n - 2) % n], here = s[c.sample], after = s[(c.sample + 2) % n];
    // The angle with two samples to either side; convex (a left turn, interior on the left).
    const double turn = turnAngle(before, here, after);
    if (turn < minTurn) continue;
    bool farEnough = true;
    for (const SalientCorner& k : corners) farEnough &= lengthSquared(k.position - here) >= separation2;
    if (!farEnough) continue;
    Vec2 in = normalized(here - before), out = normalized(after - here);
    Vec2 inward = out - in;
    inward = lengthSquared(inward) > 1e-24 ? normalized(inward) : perp(in);
    corners.push_back({here, inward, turn, c.ring, c.sample});
  }
  return corners;
}

double fitScore(double d, double alpha, double beta, double mu) {
  if (d > 0.0) return -alpha * d;
  if (d == 0.0) return 1.0;
  return std::exp(-d * d / (mu * mu * beta));
}

std::vector<SalientCorner> salientContainerCorners(const Region& input, const ShapeMatchingOptions& o,
                                                   double canonicalSide) {
  const Box box = bounds(input);
  const double side = std::max(box.width(), box.height());
  if (!(side > 0.0)) return {};
  const double scale = canonicalSide / side;
  Region container = transformed(input, scale, -box.min * scale);
  normalizeOrientation(container);
  std::vector<RingDescriptors> rings = describeRegion(
      container, o.spacingFraction * canonicalSide, o.tauFraction * canonicalSide, o.steps);
  std::vector<SalientCorner> corners = salientCorners(rings, o.cornerTurn, o.cornerSeparationFraction * canonicalSide);
  for (SalientCorner& c : corners) c.position = c.position / scale + box.min;
  return corners;
}

ShapeMatch matchCorners(const Region& input, const std::vector<Ring>& elementSkins, double elementScale,
                        const ShapeMatchingOptions& o) {
  if (o.steps < 1 || o.neighbours < 1 || o.fieldResolution < 8 || !(o.tauFraction > 0.0) ||
      !(o.spacingFraction > 0.0) || !(o.cornerTurn >= 0.0) || !(o.cornerSeparationFraction >= 0.0) ||
      !(o.alpha >= 0.0) || !(o.beta > 0.0) || !(elementScale > 0.0))
    throw InputError("", "bad shape matching options");
  Region container = input;
  normalizeOrientation(container);
  const Box box = bounds(container);
  ShapeMatch result;
  result.sideLength = std::max(box.width(), box.height());
  const double ls = result.sideLength;
  if (!(ls > 0.0) || elementSkins.empty()) return result;
  const double delta = o.spacingFraction * ls, tau = o.tauFraction * ls;

  std::vector<RingDescriptors> rings = describeRegion(container, delta, tau, o.steps);
  result.corners = salientCorners(rings, o.cornerTurn, o.cornerSeparationFraction * ls);
  if (result.corners.empty()) return result;

  // Element descriptors at the packing's rough final size, all in one k-d tree.
  std::vector<RingDescriptors> elements;
  std::vector<double> points;
  std::vector<std::pair<int, int>> owner;  // (element, sample) of each tree point
  for (std::size_t e = 0; e < elementSkins.size(); ++e) {
    Ring skin = transformed(elementSkins[e], elementScale, {});
    if (signedArea(skin) < 0.0) std::reverse(skin.begin(), skin.end());
    elements.push_back(describeRing(skin, delta, tau, o.steps));
    const RingDescriptors& d = elements.back();
    points.insert(points.end(), d.values.begin(), d.values.end());
    for (std::size_t i = 0; i < d.samples.size(); ++i) owner.emplace_back(static_cast<int>(e), static_cast<int>(i));
  }
  const std::size_t dims = static_cast<std::size_t>(2 * o.steps);
  DescriptorCloud cloud{&points, dims};
  DescriptorTree tree(dims, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));

  // Eq. 4.10's d(x) with the thesis's grid cell (L_s / 1000), computed per corner only over
  // the window its candidates cover: the values read are those of the full grid.
  const double cell = ls / o.fieldResolution;
  const double mu = 0.5 * std::sqrt(2.0) * ls;

  const std::size_t k = std::min<std::size_t>(static_cast<std::size_t>(o.neighbours), owner.size());
  std::vector<std::size_t> found(k);
  std::vector<double> found2(k);
  for (std::size_t c = 0; c < result.corners.size(); ++c) {
    const SalientCorner& corner = result.corners[c];
    const RingDescriptors& ring = rings[corner.ring];
    const std::size_t got = tree.knnSearch(ring.descriptor(corner.sample), k, found.data(), found2.data());
    const std::vector<Vec2> target = ring.descriptorPoints(corner.sample);
    // Place each candidate by aligning the matched descriptors' points (ends included).
    std::vector<Similarity> poses(got);
    Box window;
    for (std::size_t f = 0; f < got; ++f) {
      auto [e, sample] = owner[found[f]];
      poses[f] = alignDescriptors(elements[e].descriptorPoints(sample), target);
      for (Vec2 p : elements[e].samples) window.add(poses[f].apply(p));
    }
    // Beyond the container's bounding square (plus a margin) the grid's border value stands in
    // for the distance: such a sample is outside and penalised either way.
    const double margin = 0.05 * ls;
    window = {Vec2{std::max(window.min.x, box.min.x - margin), std::max(window.min.y, box.min.y - margin)},
              Vec2{std::min(window.max.x, box.max.x + margin), std::min(window.max.y, box.max.y + margin)}};
    window.add(window.min - Vec2{2 * cell, 2 * cell});
    window.add(window.max + Vec2{2 * cell, 2 * cell});
    const DistanceGrid sdf = signedDistanceField(
        container, window, static_cast<int>(std::ceil(std::max(window.width(), window.height()) / cell)));
    CornerMatch best;
    bool any = false;
    for (std::size_t f = 0; f < got; ++f) {
      auto [e, sample] = owner[found[f]];
      const RingDescriptors& element = elements[e];
      const Similarity& t = poses[f];
      double q = 0.0;  // eq. 4.11
      for (Vec2 p : element.samples) q += fitScore(sdf.sample(t.apply(p)), o.alpha, o.beta, mu);
      if (!any || q > best.quality) {
        any = true;
        best.corner = static_cast<int>(c);
        best.element = e;
        best.elementSample = sample;
        best.elementTip = element.samples[sample] / elementScale;
        best.angle = t.angle;
        best.scale = t.scale * elementScale;
        best.translation = t.translation;
        best.quality = q;
      }
    }
    if (any) result.matches.push_back(best);
  }
  return result;
}

}  // namespace pak
