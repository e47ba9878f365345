#pragma once
// What `pak metrics` reads from its command line and --config file.
#include <optional>
#include <string>
#include <vector>

#include "option_table.hpp"
#include "pak/io/packing_reader.hpp"
#include "pak/metrics/metrics.hpp"

namespace pak::cli {

struct MetricsArguments {
  std::vector<std::string> files;
  std::string config, report;
  // Also --config keys (metricsOptions): what is measured and how the files are read.
  MetricsOptions metrics;
  bool calibrate = false;
  PackingReadOptions layers;
  // What it writes.
  std::string csv, json, plot;
  std::optional<double> visualize;
  std::string visualizeOut, distanceMap, evennessMap;
};

const OptionTable<MetricsArguments>& metricsOptions();

}  // namespace pak::cli
