#include "metrics_resolve.hpp"

#include <set>


namespace pak::cli {

bool resolveMetricsOptions(MetricsArguments& args, const CLI::App& command, const nlohmann::json* config,
                           const std::string& configName) {
  std::set<std::string> configured;
  if (config) configured = metricsOptions().applyConfigObject(*config, configName, command, args);
  return command.count("--gap") > 0 || configured.count("gap") > 0;
}

}  // namespace pak::cli
