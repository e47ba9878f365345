#pragma once
// `pak flow`'s options as the run uses them, shared by the command line and pak.flow (whose
// keyword arguments are a --config object).
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "flow_arguments.hpp"

namespace pak::cli {

// `command` holds flowOptions() (what it gave wins over `config`); `config`, when not null,
// is a --config object, its errors naming `configName`.
void resolveFlowOptions(FlowArguments& args, const CLI::App& command, const nlohmann::json* config,
                        const std::string& configName);

}  // namespace pak::cli
