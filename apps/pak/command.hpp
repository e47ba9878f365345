#pragma once
// Each subcommand lives in its own file and registers itself here.
#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace pak::cli {

struct Command {
  std::string name;
  // Adds the subcommand and its options to `app`; returns the action to run when chosen.
  std::function<std::function<int()>(CLI::App& app)> install;
};

std::vector<Command>& commandRegistry();

struct CommandRegistrar {
  explicit CommandRegistrar(Command command) { commandRegistry().push_back(std::move(command)); }
};

}  // namespace pak::cli
