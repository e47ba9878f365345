#pragma once
// `pak pack`'s options as the run uses them, shared by the command line and the Python module
// (whose keyword arguments are a --config object): preset, config, then the options given as text.
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "pack_arguments.hpp"

namespace pak::cli {

// `command` holds packOptions() (what it gave wins over `config`); `config`, when not null,
// is a --config object, its errors naming `configName`.
void resolvePackOptions(PackArguments& args, const CLI::App& command, const nlohmann::json* config,
                        const std::string& configName);

}  // namespace pak::cli
