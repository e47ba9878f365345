#pragma once
// Each subcommand lives in its own file and registers itself here.
#include <functional>
#include <memory>
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

// A subcommand whose options fill an Arguments struct: `declare` adds them to the command,
// `run` runs with them parsed (the command tells which options the command line gave).
template <class Arguments>
Command subcommand(std::string name, std::string description, void (*declare)(CLI::App&, Arguments&),
                   int (*run)(Arguments&, const CLI::App&)) {
  return {name, [=](CLI::App& app) -> std::function<int()> {
            auto arguments = std::make_shared<Arguments>();
            CLI::App* command = app.add_subcommand(name, description);
            declare(*command, *arguments);
            return [=] { return run(*arguments, *command); };
          }};
}

}  // namespace pak::cli
