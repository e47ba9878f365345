#include "animate_frames.hpp"

#include <algorithm>

#include "art_check.hpp"
#include "outline_output.hpp"
#include "pak/io/packing_drawing.hpp"

namespace pak::cli {

double AnimationFrames::time(int i, int count) const {
  return script_.loop ? static_cast<double>(i) / count : (count > 1 ? static_cast<double>(i) / (count - 1) : 0.0);
}

Packing AnimationFrames::packingAt(double t, FrameShrink& shrink, std::optional<PackingCheck>* check) const {
  Packing frame = animationFrame(animation_, t);
  std::vector<double> own;
  separateFrame(frame, separation_, &own, check);
  shrink = {};
  for (std::size_t e = 0; e < own.size(); ++e) {
    // A loop's copies and a mirror's twins come after the elements; each names its own.
    const auto source = static_cast<std::size_t>(frame.elements[e].libraryIndex);
    const double scale = separationScaleAt(animation_, source, t) * own[e];
    shrink.any = std::min(shrink.any, scale);
    if (frame.elements[e].guided) shrink.guided = std::min(shrink.guided, scale);
  }
  return frame;
}

Drawing AnimationFrames::drawingAt(double t) const {
  FrameShrink shrink;
  return draw(packingAt(t, shrink));
}

Drawing AnimationFrames::draw(const Packing& frame) const { return packingDrawing(layout_, frame); }

std::vector<Drawing> AnimationFrames::drawings(int count) const {
  std::vector<Drawing> all;
  for (int i = 0; i < count; ++i) all.push_back(drawingAt(time(i, count)));
  return all;
}

RenderedFrames renderFrames(const AnimationFrames& frames, int count) {
  RenderedFrames r;
  r.checks.resize(static_cast<std::size_t>(count));
  r.packings.reserve(count);
  r.drawings.reserve(count);
  for (int i = 0; i < count; ++i) {
    FrameShrink shrink;
    r.times.push_back(frames.time(i, count));
    r.packings.push_back(frames.packingAt(r.times.back(), shrink, &r.checks[i]));
    r.drawings.push_back(frames.draw(r.packings.back()));
    r.separated += shrink.any < 1.0 ? 1 : 0;
    r.smallest.any = std::min(r.smallest.any, shrink.any);
    r.smallest.guided = std::min(r.smallest.guided, shrink.guided);
  }
  return r;
}

FrameAudit auditRenderedFrames(const RenderedFrames& rendered, const AnimatedPacking& animation,
                               const FrameSeparationOptions& separation, int evennessFrames) {
  std::vector<std::optional<PackingCheck>> checks = rendered.checks;
  // The separation's checks are the audit's own when they used its tolerance.
  if (separation.areaTolerance != kArtAreaTolerance) checks.assign(checks.size(), std::nullopt);
  FrameAudit audit = auditFrames(rendered.packings, checks, rendered.times, animation.container, evennessFrames);
  audit.framesSeparated = rendered.separated;
  audit.smallestSeparationScale = rendered.smallest.any;
  audit.smallestGuidedSeparationScale = rendered.smallest.guided;
  return audit;
}

AnimationOutputOptions animationOutputOptions(const AnimateArguments& args, const AnimationScript& script,
                                              const AnimatedPacking& animation) {
  AnimationOutputOptions output;
  output.duration = script.duration;
  output.loop = script.loop;
  output.width = args.width;
  output.svgCurveTolerance = outlineWriteOptions(args.polyline, kMeshCurveTolerance, animation.canonicalScale).curveTolerance;
  return output;
}

}  // namespace pak::cli
