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

namespace {
// An element in a guided one's way moves up to this many times `rounds`, by (1 − step) of its
// radius each time: at the defaults 0.4 of its radius. Half as many left the chase's bird
// drawn at 0.71 of its size on seed 1 (docs/animationpak.md, sixth round).
constexpr int kMovesPerRound = 2;

Vec2 skinCentre(const PlacedElement& e) {
  Vec2 centre;
  for (Vec2 p : e.skin) centre += p;
  return e.skin.empty() ? centre : centre / static_cast<double>(e.skin.size());
}

// The root mean square distance of the skin from its centre: how far a round moves an element.
double skinRadius(const PlacedElement& e) {
  const Vec2 centre = skinCentre(e);
  double sum = 0.0;
  for (Vec2 p : e.skin) sum += lengthSquared(p - centre);
  return e.skin.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(e.skin.size()));
}

// A profile sampled at `times` at t: linear between samples, the first before them and the last
// after them, except that a loop comes back to the first at t = 1.
template <class T>
T profileAt(const std::vector<double>& times, const std::vector<T>& values, bool loop, double t, T none) {
  if (times.empty() || values.size() != times.size()) return none;
  const std::size_t n = times.size();
  const auto after = static_cast<std::size_t>(std::upper_bound(times.begin(), times.end(), t) - times.begin());
  if (after == 0) return values.front();
  if (after == n) {
    if (!loop || times.back() >= 1.0) return values.back();
    const double w = (t - times.back()) / (1.0 - times.back());
    return values.back() + (values.front() - values.back()) * std::clamp(w, 0.0, 1.0);
  }
  const double span = times[after] - times[after - 1];
  const double w = span > 0.0 ? (t - times[after - 1]) / span : 0.0;
  return values[after - 1] + (values[after] - values[after - 1]) * std::clamp(w, 0.0, 1.0);
}

}  // namespace

void scaleAboutCentre(PlacedElement& e, double factor) {
  if (factor == 1.0 || e.skin.empty()) return;
  const Vec2 centre = skinCentre(e);
  auto scale = [&](Vec2& p) { p = centre + (p - centre) * factor; };
  for (Vec2& p : e.skin) scale(p);
  for (Vec2& p : e.meshVertices) scale(p);
  for (Shape& shape : e.art) {
    scaleStroke(shape, factor);
    for (Subpath& sub : shape.subpaths)
      for (Vec2& p : sub.points) scale(p);
  }
}

void translateElement(PlacedElement& e, Vec2 by) {
  if (by.x == 0.0 && by.y == 0.0) return;
  for (Vec2& p : e.skin) p += by;
  for (Vec2& p : e.meshVertices) p += by;
  for (Shape& shape : e.art)
    for (Subpath& sub : shape.subpaths)
      for (Vec2& p : sub.points) p += by;
}

double separationScaleAt(const AnimatedPacking& animation, std::size_t e, double t) {
  return profileAt(animation.separationTimes, animation.elements[e].separationScale, animation.loop, t, 1.0);
}

Vec2 separationShiftAt(const AnimatedPacking& animation, std::size_t e, double t) {
  return profileAt(animation.separationTimes, animation.elements[e].separationShift, animation.loop, t, Vec2{});
}

std::vector<Region> checkedOutlines(const Packing& frame) {
  std::vector<Region> outlines = artOutlines(frame);
  for (std::size_t e = 0; e < frame.elements.size(); ++e)  // outside, it takes no container space
    if (frame.elements[e].leavesContainer) outlines[e] = intersect(outlines[e], frame.container);
  if (!frame.fixedArt.empty()) outlines.push_back(frame.fixedArt);
  return outlines;
}

double separateFrame(Packing& frame, const FrameSeparationOptions& options, std::vector<double>* scales,
                     std::optional<PackingCheck>* check, std::vector<Vec2>* shifts) {
  const std::size_t count = frame.elements.size();
  std::vector<double> scale(count, 1.0);
  std::vector<Vec2> shift(count), away(count);
  std::vector<int> moves(count, 0);
  std::vector<char> shrink(count, 0);
  PackingCheckOptions tolerance;
  tolerance.areaTolerance = options.areaTolerance * area(frame.container);
  if (check) check->reset();
  // Which of an overlapping pair may move instead of shrinking: an unguided element with moves
  // left (a guided one is held on its path); of two unguided ones, only without shrinkPairs.
  // Each that may goes away from the centroid of their overlap; false when neither may.
  auto movePair = [&](std::size_t a, std::size_t b, const std::vector<Region>& outlines) {
    const bool guidedA = frame.elements[a].guided, guidedB = frame.elements[b].guided;
    if (guidedA == guidedB && (guidedA || options.shrinkPairs)) return false;
    const int limit = kMovesPerRound * options.rounds;
    const bool moveA = !guidedA && moves[a] < limit, moveB = !guidedB && moves[b] < limit;
    if (!moveA && !moveB) return false;
    const Region shared = intersect(outlines[a], outlines[b]);
    const Vec2 centreA = skinCentre(frame.elements[a]), centreB = skinCentre(frame.elements[b]);
    // With no overlap area to go by, away from the midpoint: for a guided pair, the same
    // direction as away from the guided element.
    const Vec2 from = shared.empty() ? (centreA + centreB) * 0.5 : centroid(shared);
    bool any = false;
    auto push = [&](std::size_t e, Vec2 centre) {
      if (const Vec2 direction = centre - from; lengthSquared(direction) > 0.0) away[e] += normalized(direction), any = true;
    };
    if (moveA) push(a, centreA);
    if (moveB) push(b, centreB);
    return any;
  };
  // Each round shrinks the elements of every overlapping pair and those outside, except that
  // the unguided ones of a pair move away from their overlap instead, while they have moves
  // left. A round that only moves does not count against `rounds`.
  for (int round = 0, shrinking = 0; shrinking < options.rounds && round < (1 + kMovesPerRound) * options.rounds; ++round) {
    const std::vector<Region> outlines = checkedOutlines(frame);
    PackingCheck result = verifyPacking(outlines, frame.container, tolerance);
    if (result.offending.empty()) {
      if (check) *check = std::move(result);
      break;
    }
    std::fill(shrink.begin(), shrink.end(), 0);
    std::fill(away.begin(), away.end(), Vec2{});
    auto mark = [&](std::size_t e) {
      if (e < count) shrink[e] = 1;  // past the elements: the fixed art, which its neighbour leaves
    };
    for (const auto& [a, b] : result.overlapping) {
      if (!options.shrinkOnly && a < count && b < count && movePair(a, b, outlines)) continue;
      mark(a), mark(b);
    }
    for (std::size_t e : result.outside) mark(e);
    bool shrank = false, moved = false;
    for (std::size_t e = 0; e < count; ++e) {
      if (lengthSquared(away[e]) > 0.0) {
        const Vec2 by = normalized(away[e]) * ((1.0 - options.step) * skinRadius(frame.elements[e]));
        translateElement(frame.elements[e], by);
        shift[e] += by;
        ++moves[e];
        moved = true;
      }
      if (shrink[e]) {
        scaleAboutCentre(frame.elements[e], options.step);
        scale[e] *= options.step;
        shrank = true;
      }
    }
    if (shrank) ++shrinking;
    if (!shrank && !moved) break;
  }
  const double smallest = scale.empty() ? 1.0 : *std::min_element(scale.begin(), scale.end());
  if (scales) *scales = std::move(scale);
  if (shifts) *shifts = std::move(shift);
  return smallest;
}

void separateAnimation(AnimatedPacking& animation, const FrameSeparationOptions& options, int threads) {
  ThreadPool pool(threads);
  separateAnimation(animation, options, pool);
}

void separateAnimation(AnimatedPacking& animation, const FrameSeparationOptions& options, ThreadPool& pool) {
  animation.separationTimes.clear();
  for (AnimatedElement& e : animation.elements) e.separationScale.clear(), e.separationShift.clear();
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
  auto weight = [&](int k, int j) {
    return options.ramp > 0.0 ? std::max(0.0, 1.0 - apart(times[k], times[j]) / options.ramp) : (k == j ? 1.0 : 0.0);
  };
  auto easeScales = [&](const std::vector<std::vector<double>>& needed) {
    for (std::size_t e = 0; e < count; ++e) {
      std::vector<double>& profile = animation.elements[e].separationScale;
      profile.assign(static_cast<std::size_t>(n), 1.0);
      for (int j = 0; j < n; ++j) {
        const double shrink = 1.0 - needed[j][e];
        if (shrink <= 0.0) continue;
        for (int k = 0; k < n; ++k) profile[k] = std::min(profile[k], 1.0 - shrink * weight(k, j));
      }
    }
  };
  // A shift is eased the same way, but where the tents of several samples overlap it is their
  // weighted mean (a lowest shift has no meaning): a sample's own need where it stands alone,
  // tapering to none over `ramp`.
  auto easeShifts = [&](const std::vector<std::vector<Vec2>>& moved) {
    for (std::size_t e = 0; e < count; ++e) {
      std::vector<Vec2>& shifts = animation.elements[e].separationShift;
      shifts.clear();
      for (int j = 0; j < n && shifts.empty(); ++j)
        if (lengthSquared(moved[j][e]) > 0.0) shifts.assign(static_cast<std::size_t>(n), Vec2{});
      if (shifts.empty()) continue;
      for (int k = 0; k < n; ++k) {
        Vec2 sum;
        double weights = 0.0;
        for (int j = 0; j < n; ++j)
          if (const double w = weight(k, j); w > 0.0 && lengthSquared(moved[j][e]) > 0.0) sum += moved[j][e] * w, weights += w;
        shifts[k] = weights > 1.0 ? sum / weights : sum;
      }
    }
  };
  auto shiftOf = [&](std::size_t e, int k) {
    const std::vector<Vec2>& shifts = animation.elements[e].separationShift;
    return shifts.empty() ? Vec2{} : shifts[static_cast<std::size_t>(k)];
  };

  // What each sampled frame needs, element by element (frames are independent: in parallel).
  // The eased profile shrinks elements where they did not need it, and a curved one shrunk
  // about its centre can reach into a neighbour: the frames are checked again with it, and
  // what they still need is added, a few times. Eased shifts are means, which can fall short
  // of a sample's own need, so the last pass only shrinks, on the shifts as they stand: a
  // shrinking profile is the lowest of its tents, and meets every sample's need.
  constexpr int kPasses = 4;
  FrameSeparationOptions shrinking = options;
  shrinking.shrinkOnly = true;
  std::vector<std::vector<double>> needed(static_cast<std::size_t>(n), std::vector<double>(count, 1.0));
  std::vector<std::vector<Vec2>> moved(static_cast<std::size_t>(n), std::vector<Vec2>(count));
  for (int pass = 0; pass < kPasses; ++pass) {
    const bool last = pass == kPasses - 1;
    std::vector<char> more(static_cast<std::size_t>(n), 0);
    if (pass > 0) animation.separationTimes = times;  // animationFrame applies the profile
    pool.parallelFor(static_cast<std::size_t>(n), 1, [&](std::size_t begin, std::size_t end) {
      std::vector<double> extra;
      std::vector<Vec2> extraShift;
      for (std::size_t k = begin; k < end; ++k) {
        Packing frame = animationFrame(animation, times[k]);
        const double smallest = separateFrame(frame, last ? shrinking : options, &extra, nullptr, &extraShift);
        if (smallest == 1.0 && std::all_of(extraShift.begin(), extraShift.end(), [](Vec2 v) { return lengthSquared(v) == 0.0; }))
          continue;
        more[k] = 1;
        for (std::size_t e = 0; e < count; ++e) {
          needed[k][e] = std::min(needed[k][e], (pass > 0 ? animation.elements[e].separationScale[k] : 1.0) * extra[e]);
          moved[k][e] = (pass > 0 ? shiftOf(e, static_cast<int>(k)) : Vec2{}) + extraShift[e];
        }
      }
    });
    animation.separationTimes.clear();
    if (std::none_of(more.begin(), more.end(), [](char m) { return m != 0; })) break;
    easeScales(needed);
    if (!last) easeShifts(moved);
  }
  if (std::all_of(animation.elements.begin(), animation.elements.end(),
                  [](const AnimatedElement& e) { return e.separationScale.empty(); }))
    return;  // every frame was clean
  animation.separationTimes = std::move(times);
}

}  // namespace pak
