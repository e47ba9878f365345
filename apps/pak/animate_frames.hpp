#pragma once
// The frames `pak animate` renders from a simulated animation (thesis 5.6), shared with
// pak.animate: each at its t, separated where it still overlaps, drawn on the scene's layout.
#include <optional>
#include <vector>

#include "animate_arguments.hpp"
#include "animate_report.hpp"
#include "pak/animation/animation_script.hpp"
#include "pak/io/animation_output.hpp"
#include "pak/io/drawing.hpp"
#include "pak/io/scene_layout.hpp"

namespace pak::cli {

// The smallest scale the frame separation gave any element, and a guided one.
struct FrameShrink {
  double any = 1.0, guided = 1.0;
};

class AnimationFrames {
 public:
  // Keeps references: all three outlive it.
  AnimationFrames(const AnimatedPacking& animation, const SceneLayout& layout, const AnimationScript& script,
                  const FrameSeparationOptions& separation)
      : animation_(animation), layout_(layout), script_(script), separation_(separation) {}

  // The t of frame i of `count` evenly spaced: a loop's last frame would repeat the first.
  double time(int i, int count) const;
  // packAnimation separated the frames at its samples (an eased scale per element over t); a
  // frame that still overlaps is separated on its own. `check`, when given, gets the frame's
  // verifyPacking if the separation made it.
  Packing packingAt(double t, FrameShrink& shrink, std::optional<PackingCheck>* check = nullptr) const;
  Drawing drawingAt(double t) const;
  Drawing draw(const Packing& frame) const;
  // `count` frames' drawings, evenly spaced in t (the animated SVG's keyframes, the sheet).
  std::vector<Drawing> drawings(int count) const;

 private:
  const AnimatedPacking& animation_;
  const SceneLayout& layout_;
  const AnimationScript& script_;
  const FrameSeparationOptions& separation_;
};

// The `count` frames rendered, each packing once: it is drawn, and checked by the audit.
struct RenderedFrames {
  std::vector<double> times;
  std::vector<Packing> packings;
  std::vector<Drawing> drawings;
  std::vector<std::optional<PackingCheck>> checks;
  int separated = 0;  // frames the separation changed
  FrameShrink smallest;
};
RenderedFrames renderFrames(const AnimationFrames& frames, int count);

// The report's audit of the rendered frames (evenness on `evennessFrames` of them).
FrameAudit auditRenderedFrames(const RenderedFrames& rendered, const AnimatedPacking& animation,
                               const FrameSeparationOptions& separation, int evennessFrames);

// What the animation outputs (GIF, animated SVG …) are written with.
AnimationOutputOptions animationOutputOptions(const AnimateArguments& args, const AnimationScript& script,
                                              const AnimatedPacking& animation);

}  // namespace pak::cli
