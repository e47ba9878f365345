#pragma once
// What pak.animate returns: the simulated animation and its frames as `pak animate` renders
// them (at evenly spaced t), the animated SVG it writes (OUT/animation.svg) and its --report.
// Any other t can be drawn from the animation too.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

#include "animate_arguments.hpp"
#include "animate_frames.hpp"
#include "pak/animation/animation_script.hpp"
#include "pak/io/scene_layout.hpp"

namespace pak::python {

namespace py = pybind11;

struct AnimationResult {
  cli::AnimateArguments args;  // as resolved (the outputs' width, keyframes …)
  AnimationScript script;
  SceneLayout layout;
  FrameSeparationOptions separation;
  AnimatedPacking animation;
  cli::RenderedFrames frames;
  std::string svg;  // the animated SVG
  nlohmann::json report;

  // Renders any t as `pak animate` renders its frames; refers to this result's members.
  cli::AnimationFrames render() const { return {animation, layout, script, separation}; }
};

// Registers pak.AnimationResult.
void bindAnimationResult(py::module_& m);

}  // namespace pak::python
