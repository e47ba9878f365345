// The `pak` command-line tool: subcommands register themselves (see command.hpp).
#include <algorithm>
#include <cstdio>
#include <exception>
#include <iostream>

#include "command.hpp"
#include "pak/error.hpp"
#include "usage_error.hpp"

namespace pak::cli {
std::vector<Command>& commandRegistry() {
  static std::vector<Command> commands;
  return commands;
}
}  // namespace pak::cli

int main(int argc, char** argv) {
  using namespace pak::cli;
  CLI::App app{"Pak fills container shapes with deformable elements (RepulsionPak, FLOWPAK, "
               "AnimationPak) and measures packings.\nRun `pak <command> --help` for details."};
  app.set_version_flag("--version", std::string("pak ") + PAK_VERSION);
  app.require_subcommand(1);
  // Static registration order is unspecified across files; sort for a stable --help.
  auto& commands = commandRegistry();
  std::sort(commands.begin(), commands.end(), [](const Command& a, const Command& b) { return a.name < b.name; });
  std::vector<std::pair<CLI::App*, std::function<int()>>> actions;
  for (auto& command : commands) {
    CLI::App* before = nullptr;
    auto action = command.install(app);
    for (auto* sub : app.get_subcommands([](CLI::App*) { return true; }))
      if (sub->get_name() == command.name) before = sub;
    actions.emplace_back(before, std::move(action));
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "pak: error: %s\n", usageErrorMessage(app, e).c_str());
    return 2;
  }
  try {
    for (auto& [sub, action] : actions)
      if (sub && sub->parsed()) return action();
    return 2;
  } catch (const pak::InputError& e) {
    if (e.where().empty())
      std::fprintf(stderr, "pak: error: %s\n", e.problem().c_str());
    else
      std::fprintf(stderr, "pak: error: %s: %s\n", e.where().c_str(), e.problem().c_str());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pak: internal error: %s\n", e.what());
    return 1;
  }
}
