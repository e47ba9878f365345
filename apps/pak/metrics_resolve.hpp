#pragma once
// `pak metrics`'s options as the run uses them, shared by the command line and pak.metrics
// (whose keyword arguments are a --config object).
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "metrics_arguments.hpp"

namespace pak::cli {

// `command` holds metricsOptions() (what it gave wins over `config`); `config`, when not
// null, is a --config object, its errors naming `configName`. Returns whether the command
// or the config gave the gap (even 0, "estimate it"): else a report's d_gap is used.
bool resolveMetricsOptions(MetricsArguments& args, const CLI::App& command, const nlohmann::json* config,
                           const std::string& configName);

}  // namespace pak::cli
