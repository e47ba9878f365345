// Fuzz target: `--config FILE.json`, read as `pak pack`, `pak flow` and `pak animate` read it
// (their option tables: known keys, types, lengths with units), then the values the commands
// parse further (preset, orientation, mirror line, lengths in canonical units).
// The reader takes a path, so each input goes through one temporary file per process.
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "animate_arguments.hpp"
#include "flow_arguments.hpp"
#include "fuzz_input.hpp"
#include "mirror_option.hpp"
#include "pack_arguments.hpp"
#include "pak/repulsion/orientation.hpp"
#include "pak/repulsion/repulsion_presets.hpp"

namespace {

using namespace pak::cli;

// Removed when the fuzzer or the replay exits.
class ConfigFile {
 public:
  ConfigFile()
      : path_((std::filesystem::temp_directory_path() / ("pak-fuzz-config-" + std::to_string(getpid()) + ".json"))
                  .string()) {}
  ~ConfigFile() {
    std::error_code ignored;
    std::filesystem::remove(path_, ignored);
  }
  const std::string& write(const std::string& text) {
    std::ofstream(path_, std::ios::binary | std::ios::trunc) << text;
    return path_;
  }

 private:
  std::string path_;
};

// A command's arguments and its options bound to them, made once: building the CLI11 options
// anew for every input would take most of the fuzzer's time.
template <class Arguments>
struct Command {
  explicit Command(const OptionTable<Arguments>& table) : table(table) {
    table.addTo(command, args, &args.common.lengths);
  }
  const OptionTable<Arguments>& table;
  Arguments args;
  CLI::App command;
};

// The table's keys from `file` into fresh arguments, as the command does before its run (no
// flag given: the file sets everything it names).
template <class Arguments>
const Arguments& configured(Command<Arguments>& command, const std::string& file) {
  command.args = Arguments{};  // the defaults, in place: the options stay bound to them
  command.table.applyConfig(file, command.command, command.args, &command.args.common.lengths);
  command.table.resolveLengths(command.args, command.args.common.lengths, LengthScale{});
  return command.args;
}

void readAsPack(const std::string& file) {
  static Command<PackArguments> pack(packOptions());
  const PackArguments& args = configured(pack, file);
  if (!args.preset.empty()) {
    pak::RepulsionOptions preset = args.options;
    pak::applyRepulsionPreset(args.preset, preset);
  }
  pak::parseOrientationMode(args.orientation);
  pak::parseOrientationField(args.orientationField);
}

void readAsFlow(const std::string& file) {
  static Command<FlowArguments> flow(flowOptions());
  const FlowArguments& args = configured(flow, file);
  if (!args.mirror.empty()) parseMirror(args.mirror);
}

void readAsAnimate(const std::string& file) {
  static Command<AnimateArguments> animate(animateOptions());
  const AnimateArguments& args = configured(animate, file);
  if (!args.mirror.empty()) parseMirror(args.mirror);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static ConfigFile config;
  const std::string& file = config.write(pak::fuzz::textOf(data, size));
  // Each command on its own: a key one of them does not know ends only that one's reading.
  pak::fuzz::readAcceptingInputErrors([&] { readAsPack(file); });
  pak::fuzz::readAcceptingInputErrors([&] { readAsFlow(file); });
  return pak::fuzz::readAcceptingInputErrors([&] { readAsAnimate(file); });
}
