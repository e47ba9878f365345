#pragma once
// The options several subcommands take, declared once: the same name means the same thing in
// each. A subcommand picks the ones it uses and may word the help of what it writes.
#include <initializer_list>
#include <string>

#include <CLI/CLI.hpp>

#include "length_units.hpp"

namespace pak::cli {

enum class CommonOption { Output, Png, PngWidth, Config, Report, Snapshots, Every, DebugLayers, Quiet };

// The strings' `{}` lets a subcommand set its own defaults with designated initializers.
struct CommonArguments {
  std::string output{};     // -o: the result (a file, or animate's folder); required
  std::string png{};        // a PNG preview of the result
  int pngWidth = 1200;
  std::string config{};     // JSON file of option values; the command line wins
  std::string report{};     // JSON report of the run
  std::string snapshots{};  // folder for intermediate results
  int every = 1;            // iterations between snapshots (animate: checkpoints)
  bool debugLayers = false;
  bool quiet = false;
  GivenLengths lengths{};   // length options given with a unit (OptionTable::resolveLengths)
};

struct CommonOptionUse {
  CommonOption option;
  const char* help = nullptr;  // nullptr: the shared wording
};

void addCommonOptions(CLI::App& command, CommonArguments& arguments, std::initializer_list<CommonOptionUse> uses);

}  // namespace pak::cli
