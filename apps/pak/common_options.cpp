#include "common_options.hpp"

#include <type_traits>
#include <variant>

namespace pak::cli {
namespace {

struct Declaration {
  const char* names;
  std::variant<std::string CommonArguments::*, int CommonArguments::*, bool CommonArguments::*> member;
  const char* help;  // the shared wording
};

// Indexed by CommonOption.
const Declaration kDeclarations[] = {
    {"-o,--output", &CommonArguments::output, "output file"},
    {"--png", &CommonArguments::png, "also render a PNG preview to this file"},
    {"--png-width", &CommonArguments::pngWidth, "PNG width in pixels"},
    {"--config", &CommonArguments::config, "JSON file of option names to values (command-line flags win)"},
    {"--report", &CommonArguments::report, "write a JSON report of the run"},
    {"--snapshots", &CommonArguments::snapshots, "write intermediate SVGs into this folder"},
    {"--every", &CommonArguments::every, "snapshot interval in iterations"},
    {"--debug-layers", &CommonArguments::debugLayers, "add layers showing the simulation's state"},
    {"--quiet,-q", &CommonArguments::quiet, "no progress output"},
};

}  // namespace

void addCommonOptions(CLI::App& command, CommonArguments& arguments, std::initializer_list<CommonOptionUse> uses) {
  for (const CommonOptionUse& use : uses) {
    const Declaration& declaration = kDeclarations[static_cast<int>(use.option)];
    const std::string help = use.help ? use.help : declaration.help;
    CLI::Option* option = std::visit(
        [&](auto member) {
          auto& target = arguments.*member;
          using Value = std::remove_reference_t<decltype(target)>;
          if constexpr (std::is_same_v<Value, bool>) return command.add_flag(declaration.names, target, help);
          if constexpr (std::is_same_v<Value, int>)
            return command.add_option(declaration.names, target, help)->capture_default_str();
          if constexpr (std::is_same_v<Value, std::string>) return command.add_option(declaration.names, target, help);
        },
        declaration.member);
    if (use.option == CommonOption::Output) option->required();
  }
}

}  // namespace pak::cli
