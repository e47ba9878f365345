#include "animate_report.hpp"

#include <algorithm>

#include "art_check.hpp"
#include "pak/metrics/evenness.hpp"
#include "pak/metrics/packing_geometry.hpp"
#include "report_fields.hpp"

namespace pak::cli {

FrameAudit auditFrames(const std::vector<Packing>& frames, const std::vector<std::optional<PackingCheck>>& checks,
                       const std::vector<double>& times, const Region& container, int evennessFrames) {
  const double containerArea = area(container);
  const double frameCount = static_cast<double>(frames.size());
  FrameAudit audit;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const Packing& frame = frames[i];
    const std::vector<Region> outlines = checkedOutlines(frame);  // the fixed art last, if any
    for (const Region& r : outlines) audit.meanFill += area(r) / containerArea / frameCount;
    PackingCheck check;
    if (checks[i]) {
      check = *checks[i];
      checkSelfIntersections(artRings(frame), check);
    } else {
      check = checkArt(outlines, container, artRings(frame));
    }
    audit.framesSelfIntersecting += check.selfIntersecting > 0 ? 1 : 0;
    audit.framesWithOverlap += check.overlappingPairs > 0 ? 1 : 0;
    audit.framesOutside += check.elementsOutside > 0 ? 1 : 0;
    audit.worstPairs = std::max(audit.worstPairs, check.overlappingPairs);
    audit.worstOverlapArea = std::max(audit.worstOverlapArea, check.overlapArea / containerArea);
  }
  const int measured = std::min(evennessFrames, static_cast<int>(frames.size()));
  for (int k = 0; k < measured; ++k) {
    const std::size_t i = static_cast<std::size_t>(k) * frames.size() / static_cast<std::size_t>(measured);
    const Evenness evenness = measureEvenness(packingGeometry(frames[i]));
    audit.evennessTimes.push_back(times[i]);
    audit.negativeRatio.push_back(evenness.negativeRatio);
    audit.pocketShare2.push_back(evenness.pocketShare[1]);
  }
  return audit;
}

namespace {
double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const std::size_t mid = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid), values.end());
  const double upper = values[mid];
  if (values.size() % 2 == 1) return upper;
  return 0.5 * (upper + *std::max_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid)));
}
}  // namespace

nlohmann::json animateReport(const AnimateArguments& args, const AnimatedPacking& animation, int frameCount,
                             const FrameAudit& audit, const AnimateTimes& times) {
  nlohmann::json parameters;
  animateOptions().report(parameters, args);
  parameters["frames"] = frameCount;
  nlohmann::json report =
      reportWithParameters(parameters, "distances in canonical units: the container's bounding square is 1000 wide; t spans time-length", args.common.lengths);
  report["container"] = args.container;
  report["animation"] = args.animation;
  report["elements"] = animation.elements.size();
  report["vertices"] = animation.vertices;
  report["springs"] = animation.springs;
  report["envelope-triangles"] = animation.envelopeTriangles;
  report["slices"] = animation.slices;
  report["iterations"] = animation.iterations;
  report["settle-iterations"] = animation.settleIterations;
  report["stop-reason"] = toString(animation.stopReason);
  report["threads-used"] = animation.threads;
  report["skin-fill-mean-over-slices"] = animation.fill;
  report["art-fill-mean-over-frames"] = audit.meanFill;
  report["overlapping-slices-at-end"] = animation.overlappingSlices;
  report["unfolded-slices"] = animation.unfoldedSlices;
  report["frames-with-overlaps"] = audit.framesWithOverlap;
  report["frames-with-element-outside"] = audit.framesOutside;
  report["frames-with-self-intersecting-outline"] = audit.framesSelfIntersecting;
  report["most-overlapping-pairs-in-a-frame"] = audit.worstPairs;
  report["largest-overlap-area-fraction"] = audit.worstOverlapArea;
  // The counts above are of the frames as written, after the separation.
  report["frames-separated"] = audit.framesSeparated;
  report["smallest-separation-scale"] = audit.smallestSeparationScale;
  report["guided-smallest-separation-scale"] = audit.smallestGuidedSeparationScale;
  if (!audit.evennessTimes.empty()) {
    const auto worst = [](const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); };
    report["evenness-over-frames"] = {{"frames", audit.evennessTimes.size()},
                                      {"negative-ratio-median", median(audit.negativeRatio)},
                                      {"negative-ratio-worst", worst(audit.negativeRatio)},
                                      {"P2-median", median(audit.pocketShare2)},
                                      {"P2-worst", worst(audit.pocketShare2)},
                                      {"t", audit.evennessTimes},
                                      {"negative-ratio", audit.negativeRatio},
                                      {"P2", audit.pocketShare2}};
  }
  report["guided-growth-ratio"] = smallestGuidedGrowthRatio(animation);
  report["mean-centroid-acceleration"] = meanCentroidAcceleration(animation, frameCount);
  report["seconds"] = {{"setup", animation.setupSeconds},
                       {"simulation", animation.seconds - animation.setupSeconds - animation.separationSeconds},
                       {"frame-separation", animation.separationSeconds},
                       {"rendering", times.rendering},
                       {"wall", times.wall}};
  report["seconds-per-iteration"] =
      animation.iterations > 0
          ? (animation.seconds - animation.setupSeconds - animation.separationSeconds) / animation.iterations
          : 0.0;
  // What each count means, for a reader of the report without the docs at hand.
  report["legend"] = {
      {"skin-fill-mean-over-slices", "area of the elements' skins (art offset by half the gap) over the container's, mean over slices"},
      {"art-fill-mean-over-frames", "area painted by the elements' art and the fixed art over the container's, mean over the rendered frames"},
      {"iterations", "simulation steps, the settle's included"},
      {"settle-iterations", "steps of the settle after the stop, in which nothing grew (--settle-iterations)"},
      {"overlapping-slices-at-end", "slices with a vertex inside another element when the simulation ended, after the settle (before the frame separation)"},
      {"unfolded-slices", "slices relaxed toward their rest shape after the simulation, because their art crossed itself or did so between them and the next slice (a pair counts two)"},
      {"frames-with-overlaps", "rendered frames in which two elements' art overlaps by more than 1e-6 of the container's area"},
      {"frames-with-element-outside", "rendered frames with art outside the container by more than that"},
      {"frames-with-self-intersecting-outline", "rendered frames with an element whose art outline crosses itself"},
      {"most-overlapping-pairs-in-a-frame", "the largest number of overlapping pairs in one rendered frame"},
      {"largest-overlap-area-fraction", "the largest overlap area in one rendered frame, over the container's area"},
      {"frames-separated", "rendered frames in which the frame separation shrank an element"},
      {"smallest-separation-scale", "the smallest scale the frame separation gave an element in a rendered frame (1: none shrank)"},
      {"guided-smallest-separation-scale", "the same for the guided elements only (1: none shrank, or none is guided): with --guided-growth, a guided element's drawn size is its growth times this"},
      {"evenness-over-frames", "negative space and pocket share P2 (docs/metrics.md) of --evenness-frames frames spread over the animation: median, worst, and each"},
      {"mean-centroid-acceleration", "how frantically the unguided elements move (thesis Fig. 5.21): the mean over them and the rendered frames of the length of the centroid's second difference from frame to frame, canonical units per frame squared"},
      {"guided-growth-ratio", "the smallest, over guided elements and slices, of a guided slice's growth over the median growth of the unguided elements' slices at that t (1 when none is guided)"}};
  return report;
}

}  // namespace pak::cli
