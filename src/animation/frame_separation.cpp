// Frame separation: the slices are packed, but a frame between two slices interpolates them
// linearly, and two elements passing each other can overlap there by a sliver (thesis 5.8
// names continuous collision between slices as future work). The offending elements of such
// a frame are shrunk a little about their centres until it is clean; over the animation the
// shrinking is eased in and out, so that no element visibly pulses.
#include "animation/frame_separation.hpp"

#include <algorithm>
#include <cmath>

#include "pak/geom/clipping.hpp"
#include "pak/geom/verify.hpp"

namespace pak {

void scaleAboutCentre(PlacedElement& e, double factor) {
  if (factor == 1.0 || e.skin.empty()) return;
  Vec2 centre;
  for (Vec2 p : e.skin) centre += p;
  centre = centre / static_cast<double>(e.skin.size());
  auto scale = [&](Vec2& p) { p = centre + (p - centre) * factor; };
  for (Vec2& p : e.skin) scale(p);
  for (Vec2& p : e.meshVertices) scale(p);
  for (Shape& shape : e.art) {
    shape.strokeWidth *= factor;
    for (Subpath& sub : shape.subpaths)
      for (Vec2& p : sub.points) scale(p);
  }
}

double separationScaleAt(const AnimatedPacking& animation, std::size_t e, double t) {
  const std::vector<double>& times = animation.separationTimes;
  const std::vector<double>& scales = animation.elements[e].separationScale;
  if (times.empty() || scales.size() != times.size()) return 1.0;
  const std::size_t n = times.size();
  const auto after = static_cast<std::size_t>(std::upper_bound(times.begin(), times.end(), t) - times.begin());
  if (after == 0) return scales.front();
  if (after == n) {  // past the last sample: a loop comes back to the first one at t = 1
    if (!animation.loop || times.back() >= 1.0) return scales.back();
    const double w = (t - times.back()) / (1.0 - times.back());
    return scales.back() + (scales.front() - scales.back()) * std::clamp(w, 0.0, 1.0);
  }
  const double span = times[after] - times[after - 1];
  const double w = span > 0.0 ? (t - times[after - 1]) / span : 0.0;
  return scales[after - 1] + (scales[after] - scales[after - 1]) * std::clamp(w, 0.0, 1.0);
}

std::vector<Region> checkedOutlines(const Packing& frame) {
  std::vector<Region> outlines = artOutlines(frame);
  for (std::size_t e = 0; e < frame.elements.size(); ++e)  // outside, it takes no container space
    if (frame.elements[e].leavesContainer) outlines[e] = intersect(outlines[e], frame.container);
  if (!frame.fixedArt.empty()) outlines.push_back(frame.fixedArt);
  return outlines;
}

double separateFrame(Packing& frame, const FrameSeparationOptions& options, std::vector<double>* scales,
                     std::optional<PackingCheck>* check) {
  std::vector<double> scale(frame.elements.size(), 1.0);
  PackingCheckOptions tolerance;
  tolerance.areaTolerance = options.areaTolerance * area(frame.container);
  if (check) check->reset();
  for (int round = 0; round < options.rounds; ++round) {
    PackingCheck result = verifyPacking(checkedOutlines(frame), frame.container, tolerance);
    if (result.offending.empty()) {
      if (check) *check = std::move(result);
      break;
    }
    for (std::size_t e : result.offending) {
      if (e >= frame.elements.size()) continue;  // the fixed art: its neighbour shrinks
      scaleAboutCentre(frame.elements[e], options.step);
      scale[e] *= options.step;
    }
  }
  const double smallest = scale.empty() ? 1.0 : *std::min_element(scale.begin(), scale.end());
  if (scales) *scales = std::move(scale);
  return smallest;
}

void separateAnimation(AnimatedPacking& animation, const FrameSeparationOptions& options, int threads) {
  ThreadPool pool(threads);
  separateAnimation(animation, options, pool);
}

void separateAnimation(AnimatedPacking& animation, const FrameSeparationOptions& options, ThreadPool& pool) {
  animation.separationTimes.clear();
  for (AnimatedElement& e : animation.elements) e.separationScale.clear();
  if (options.rounds == 0 || animation.elements.empty()) return;
  const int n = options.samples > 0 ? options.samples : 2 * std::max(animation.slices, 2);
  std::vector<double> times(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) times[k] = animation.loop ? static_cast<double>(k) / n : static_cast<double>(k) / (n - 1);

  // Each shrinking eased in and out over `ramp` of t on both sides: the profile is the lowest
  // of the tents around the samples that need one.
  auto apart = [&](double a, double b) {
    const double d = std::abs(a - b);
    return animation.loop ? std::min(d, 1.0 - d) : d;
  };
  const std::size_t count = animation.elements.size();
  auto easedProfile = [&](const std::vector<std::vector<double>>& needed) {
    for (std::size_t e = 0; e < count; ++e) {
      std::vector<double>& profile = animation.elements[e].separationScale;
      profile.assign(static_cast<std::size_t>(n), 1.0);
      for (int j = 0; j < n; ++j) {
        const double shrink = 1.0 - needed[j][e];
        if (shrink <= 0.0) continue;
        for (int k = 0; k < n; ++k) {
          const double weight = options.ramp > 0.0 ? std::max(0.0, 1.0 - apart(times[k], times[j]) / options.ramp)
                                                   : (k == j ? 1.0 : 0.0);
          profile[k] = std::min(profile[k], 1.0 - shrink * weight);
        }
      }
    }
  };

  // What each sampled frame needs, element by element (frames are independent: in parallel).
  // The eased profile shrinks elements where they did not need it, and a curved one shrunk
  // about its centre can reach into a neighbour: the frames are checked again with it, and
  // what they still need is added, a few times.
  constexpr int kPasses = 3;
  std::vector<std::vector<double>> needed(static_cast<std::size_t>(n), std::vector<double>(count, 1.0));
  for (int pass = 0; pass < kPasses; ++pass) {
    std::vector<char> more(static_cast<std::size_t>(n), 0);
    if (pass > 0) animation.separationTimes = times;  // animationFrame applies the profile
    pool.parallelFor(static_cast<std::size_t>(n), 1, [&](std::size_t begin, std::size_t end) {
      std::vector<double> extra;
      for (std::size_t k = begin; k < end; ++k) {
        Packing frame = animationFrame(animation, times[k]);
        if (separateFrame(frame, options, &extra) == 1.0) continue;
        more[k] = 1;
        for (std::size_t e = 0; e < count; ++e)
          needed[k][e] = std::min(needed[k][e], (pass > 0 ? animation.elements[e].separationScale[k] : 1.0) * extra[e]);
      }
    });
    animation.separationTimes.clear();
    if (std::none_of(more.begin(), more.end(), [](char m) { return m != 0; })) break;
    easedProfile(needed);
  }
  if (std::all_of(animation.elements.begin(), animation.elements.end(),
                  [](const AnimatedElement& e) { return e.separationScale.empty(); }))
    return;  // every frame was clean
  animation.separationTimes = std::move(times);
}

}  // namespace pak
