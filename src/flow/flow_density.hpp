#pragma once
// FLOWPAK's automatic density: the streamline gap, the element lengths and the spacing a run
// uses when the options leave them to Pak (issue 16: a first run is ornament, not a few long
// strokes). In canonical units.
#include <vector>

#include "pak/flow/flow.hpp"

namespace pak {

// Each element's proportions: its spine's length over its widest extent across it.
double medianAspect(const std::vector<double>& aspects);

// The options' gap, lengths and spacing, each worked out when left automatic (0, or a negative
// spacing): the gap that puts about `count` elements of the library's median aspect in
// `freeArea` (canonical units²; the packed side only under a mirror, which doubles the count),
// lengths that keep that aspect, and a spacing in proportion to the gap.
FlowDensity resolveDensity(const FlowOptions& options, double freeArea, double aspect);

}  // namespace pak
