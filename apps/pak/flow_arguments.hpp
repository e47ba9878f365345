#pragma once
// What `pak flow` reads from its command line and --config file.
#include <string>
#include <vector>

#include "common_options.hpp"
#include "option_table.hpp"
#include "pak/flow/flow.hpp"

namespace pak::cli {

struct FlowArguments {
  CommonArguments common{.every = 1};
  std::string scene;  // -c/--container, or the first argument
  std::vector<std::string> elements;
  // Also --config keys and report parameters (flowOptions); --mirror is parsed into `options`.
  std::string mirror;  // x=VALUE, y=VALUE or X1,Y1,X2,Y2
  bool polyline = false;  // outlines as polygons, not fitted Béziers
  FlowOptions options;
};

const OptionTable<FlowArguments>& flowOptions();

}  // namespace pak::cli
