#pragma once
// What `pak animate` measures on its rendered frames, and the JSON report (--report) of a run.
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "animate_arguments.hpp"

namespace pak::cli {

// Overlaps between rendered frames (thesis 5.6 warns of brief ones between slices): measured
// on every frame, reported, never hidden.
struct FrameAudit {
  int framesWithOverlap = 0, framesOutside = 0, framesSelfIntersecting = 0, worstPairs = 0;
  double worstOverlapArea = 0.0;  // fraction of the container
  double meanFill = 0.0;          // art fill, mean over frames
  // Frame separation (FrameSeparationOptions): frames it changed, the smallest scale it gave.
  int framesSeparated = 0;
  double smallestSeparationScale = 1.0;
  double smallestGuidedSeparationScale = 1.0;  // of a guided element
  // Evenness (measureEvenness) of `evennessFrames` frames spread evenly over the animation.
  std::vector<double> evennessTimes, negativeRatio, pocketShare2;
};
// `times[i]` is the t of frames[i]; `checks[i]`, when set, is frames[i]'s verifyPacking at
// kArtAreaTolerance, already made (by separateFrame).
FrameAudit auditFrames(const std::vector<Packing>& frames, const std::vector<std::optional<PackingCheck>>& checks,
                       const std::vector<double>& times, const Region& container, int evennessFrames);

struct AnimateTimes {
  double simulation = 0.0, rendering = 0.0, wall = 0.0;  // seconds
};

nlohmann::json animateReport(const AnimateArguments& args, const AnimatedPacking& animation, int frameCount,
                             const FrameAudit& audit, const AnimateTimes& times);

}  // namespace pak::cli
