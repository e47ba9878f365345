#pragma once
// What `pak pack` reads from its command line and --config file.
#include <string>
#include <vector>

#include "common_options.hpp"
#include "option_table.hpp"
#include "pak/repulsion/repulsion.hpp"

namespace pak::cli {

struct PackArguments {
  CommonArguments common{.every = 500};
  std::string container;
  std::vector<std::string> elements, secondary;
  std::string tilePreview;  // --tile-preview FILE.png
  int tilePreviewRepeat = 3;
  int progressEvery = 0;
  // Also --config keys and report parameters (packOptions): the forms options take as text,
  // parsed into `options` by the run.
  std::string preset;
  bool rigid = false;
  std::string tile;  // W,H
  std::string orientation = "random", orientationField = "x:0:180", containerLayer = "container";
  bool polyline = false;  // outlines as polygons, not fitted Béziers
  RepulsionOptions options;
};

const OptionTable<PackArguments>& packOptions();

}  // namespace pak::cli
