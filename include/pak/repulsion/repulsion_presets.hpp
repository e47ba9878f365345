#pragma once
// Named sets of RepulsionPak force strengths (thesis 4.5, 4.8 and 6.4): the ratios between
// repulsion, overlap, boundary and edge forces decide how much elements bend to even out the
// negative space. docs/secondary-fixed-rigid.md shows what each gives.
#include <string>
#include <vector>

#include "pak/repulsion/repulsion_options.hpp"

namespace pak {

struct RepulsionPreset {
  std::string name;
  std::string description;  // one line for --help
  SimulationParameters simulation;
  RepulsionStopRule stop;
};

// default, soft, rigid — in that order.
const std::vector<RepulsionPreset>& repulsionPresets();

// Sets options.simulation and options.stop to those of preset `name`, leaving every other
// option as it is. Throws InputError for an unknown name.
void applyRepulsionPreset(const std::string& name, RepulsionOptions& options);

}  // namespace pak
