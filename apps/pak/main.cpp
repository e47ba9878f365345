// The `pak` command-line tool: subcommands register themselves (see command.hpp).
#include <algorithm>
#include <cstdio>
#include <exception>
#include <new>
#include <iostream>
#include <string>
#include <vector>

#include "command.hpp"
#include "pak/error.hpp"
#include "pak/io/message_text.hpp"
#include "usage_error.hpp"

namespace pak::cli {
std::vector<Command>& commandRegistry() {
  static std::vector<Command> commands;
  return commands;
}
}  // namespace pak::cli

namespace {
// Every message pak prints is one line (pak/io/message_text.hpp): whatever a file or an
// argument holds, a newline in it is escaped and a long value cut.
void printError(const std::string& where, const std::string& what) {
  const std::string text = where.empty() ? what : where + ": " + what;
  std::fprintf(stderr, "pak: error: %s\n", pak::oneLine(text).c_str());
}

bool hasCommand(CLI::App& app, const std::string& name) {
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
    if (sub->get_name() == name) return true;
  return false;
}

// What is wrong with `pak help …`: a command it does not know (`name`), or more than one.
int helpError(CLI::App& app, const std::string& name) {
  if (name.empty())
    printError("", "help takes at most one command (see pak help)");
  else
    printError("help", "no command '" + name + "'; the commands are " + pak::cli::commandList(app));
  return 2;
}
}  // namespace

int main(int argc, char** argv) {
  using namespace pak::cli;
  CLI::App app{"Pak fills container shapes with deformable elements (RepulsionPak, FLOWPAK, "
               "AnimationPak) and measures packings.\nRun `pak help <command>` or `pak <command> --help` for details.",
               "pak"};  // named, so that usage lines say `pak`, not the path it was run by
  app.set_version_flag("-V,--version", std::string("pak ") + PAK_VERSION);
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
  // `pak help [COMMAND]` is `pak [COMMAND] --help`, parsed as such so the text is the same.
  std::vector<char*> arguments(argv, argv + argc);
  char helpFlag[] = "--help";
  if (argc >= 2 && std::string(argv[1]) == "help") {
    if (argc > 3 || (argc == 3 && !hasCommand(app, argv[2]))) return helpError(app, argc > 3 ? "" : argv[2]);
    arguments.erase(arguments.begin() + 1);
    arguments.push_back(helpFlag);
    argc = static_cast<int>(arguments.size());
    argv = arguments.data();
  }
  if (argc >= 2 && argv[1][0] != '-' && !hasCommand(app, argv[1])) {
    printError("", std::string("no command '") + argv[1] + "'; the commands are " + commandList(app) + " (see pak help)");
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    printError("", usageErrorMessage(app, e));
    return 2;
  }
  try {
    for (auto& [sub, action] : actions)
      if (sub && sub->parsed()) return action();
    return 2;
  } catch (const pak::InputError& e) {
    printError(e.where(), e.problem());
    return 2;
  } catch (const std::bad_alloc&) {
    // Every size an input or option sets is bounded; this is what is left (a machine short of memory).
    printError("", "out of memory");
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pak: internal error: %s\n", pak::oneLine(e.what()).c_str());
    return 1;
  }
}
