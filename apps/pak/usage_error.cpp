#include "usage_error.hpp"

#include <regex>
#include <sstream>

namespace pak::cli {
namespace {

// What an option of CLI11's type name holds, for "cannot read … as …".
std::string kindOf(const std::string& typeName) {
  if (typeName == "INT") return "an integer";
  if (typeName == "UINT") return "a non-negative integer";
  if (typeName == "FLOAT") return "a number";
  return typeName.empty() ? "the option's value" : typeName;
}

const CLI::Option* findOption(const CLI::App& app, const std::string& name) {
  if (const CLI::Option* option = app.get_option_no_throw(name)) return option;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    if (const CLI::Option* option = findOption(*sub, name)) return option;
  return nullptr;
}

}  // namespace

std::string usageErrorMessage(const CLI::App& app, const CLI::ParseError& error) {
  std::string text = error.what();
  // A hidden option (an old spelling) has no name for CLI11 to put first.
  if (text.rfind(": ", 0) == 0) text.erase(0, 2);
  static const std::regex conversion(R"(^Could not convert: (\S+) = (.*)$)");
  static const std::regex required(R"(^(-\S+) is required$)");
  static const std::regex repeated(R"(^(\S+): At Most 1 required but received \d+$)");
  static const std::regex unexpected(R"(^The following arguments? (?:was|were) not expected: (.*)$)");
  std::smatch match;
  if (std::regex_match(text, match, conversion)) {
    const CLI::Option* option = findOption(app, match[1].str());
    const std::string kind = kindOf(option ? option->get_type_name() : "");
    return match[1].str() + ": cannot read '" + match[2].str() + "' as " + kind;
  }
  if (std::regex_match(text, match, required)) return match[1].str() + ": is required";
  if (std::regex_match(text, match, repeated))
    return match[1].str() + ": takes one value (given twice, or a value starting with '-')";
  if (std::regex_match(text, match, unexpected)) {
    // CLI11 lists the leftover words: an unknown option and perhaps its value.
    std::istringstream words(match[1].str());
    for (std::string word; words >> word;)
      if (word.size() > 1 && word[0] == '-') return word + ": not an option of this command (see --help)";
    return "unexpected argument " + match[1].str() + " (see --help)";
  }
  if (text == "A subcommand is required") return "expected a command: " + commandList(app) + " (see pak help)";
  return text;
}

std::string commandList(const CLI::App& app) {
  std::string names;
  const auto commands = app.get_subcommands([](const CLI::App*) { return true; });
  for (std::size_t i = 0; i < commands.size(); ++i)
    names += (i == 0 ? "" : i + 1 == commands.size() ? " or " : ", ") + commands[i]->get_name();
  return names;
}

}  // namespace pak::cli
