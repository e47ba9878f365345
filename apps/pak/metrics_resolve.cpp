#include "metrics_resolve.hpp"

#include <set>

#include "metrics_measure.hpp"

namespace pak::cli {

void resolveMetricsOptions(MetricsArguments& args, const CLI::App& command, const nlohmann::json* config,
                           const std::string& configName, const nlohmann::json* report, const std::string& reportName) {
  const OptionTable<MetricsArguments>& table = metricsOptions();
  std::set<std::string> configured;
  if (config) configured = table.applyConfigObject(*config, configName, command, args);
  // A gap given (even 0, "estimate it") wins over the report's.
  const bool gapGiven = command.count("--gap") > 0 || configured.count("gap") > 0;
  if (report && !gapGiven) args.metrics.gap = gapFromReport(*report, reportName);
}

}  // namespace pak::cli
