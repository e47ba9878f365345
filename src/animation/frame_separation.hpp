#pragma once
// Frame separation's pieces shared with animationFrame (see FrameSeparationOptions).
#include "pak/animation/animation.hpp"
#include "sim/parallel.hpp"

namespace pak {

// Scales the placed element (mesh, skin, art and strokes) about its skin's centre.
void scaleAboutCentre(PlacedElement& element, double factor);
// Moves the placed element (mesh, skin, art) by `by`.
void translateElement(PlacedElement& element, Vec2 by);
// separateAnimation on the caller's pool (packAnimation's, once the simulation is done).
void separateAnimation(AnimatedPacking& animation, const FrameSeparationOptions& options, ThreadPool& pool);

}  // namespace pak
