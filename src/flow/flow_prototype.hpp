#pragma once
// A library element made ready for FLOWPAK: its spine line, and its LR functions for every
// rotation the refinement may try (thesis 3.3.2, and "Element Placement" in 3.3.6).
#include <vector>

#include "pak/flow/lr_function.hpp"
#include "pak/flow/skeletal_stroke.hpp"
#include "pak/geom/scene.hpp"

namespace pak {

struct FlowPrototype {
  const ElementArt* art = nullptr;
  Region outline;
  Vec2 spineStart, spineEnd;
  std::vector<double> rotations;  // radians: 0, +1°, −1°, +2°, −2° … (index 0 is unrotated)
  std::vector<LRFunction> lr;     // per rotation, measured against the unrotated spine line
  std::vector<StrokeFrame> frames;  // per rotation: the spine line, extent and rotation
};

// The element's own spine if the file gives one, else its principal axis: the line through
// the outline's centroid along the larger eigenvector of its second moments of area.
std::array<Vec2, 2> elementSpine(const ElementArt& element);

FlowPrototype flowPrototype(const ElementArt& element, int maxRotationDegrees, int lrSamples);

}  // namespace pak
