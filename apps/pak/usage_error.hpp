#pragma once
// CLI11's parse errors in pak's "<where>: <what>" form.
#include <string>

#include <CLI/CLI.hpp>

namespace pak::cli {

// The message for `error`, raised while `app` parsed the command line: "--count: cannot read
// 'abc' as an integer" for CLI11's "Could not convert: --count = abc", CLI11's own text else.
std::string usageErrorMessage(const CLI::App& app, const CLI::ParseError& error);

// The commands of `app`, "animate, flow … or render".
std::string commandList(const CLI::App& app);

}  // namespace pak::cli
