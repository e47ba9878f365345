#include "usage_error.hpp"

#include <cctype>
#include <sstream>
#include <string_view>

#include "pak/io/message_text.hpp"

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

// One word: not empty, no white space (an option's name as CLI11 prints it).
bool isWord(std::string_view text) {
  if (text.empty()) return false;
  for (char c : text)
    if (std::isspace(static_cast<unsigned char>(c))) return false;
  return true;
}

}  // namespace

std::string usageErrorMessage(const CLI::App& app, const CLI::ParseError& error) {
  std::string text = error.what();
  // A hidden option (an old spelling) has no name for CLI11 to put first.
  if (text.rfind(": ", 0) == 0) text.erase(0, 2);
  // Prefix and suffix tests (consumePrefix), not std::regex: an argument may be long.
  std::string_view rest = text;
  if (consumePrefix(rest, "Could not convert: ")) {
    const std::size_t equals = rest.find(" = ");
    const std::string_view name = rest.substr(0, equals);
    if (equals != std::string_view::npos && isWord(name)) {
      const CLI::Option* option = findOption(app, std::string(name));
      const std::string kind = kindOf(option ? option->get_type_name() : "");
      return std::string(name) + ": cannot read '" + std::string(rest.substr(equals + 3)) + "' as " + kind;
    }
  }
  constexpr std::string_view isRequired = " is required";
  if (rest = text; rest.ends_with(isRequired)) {
    rest.remove_suffix(isRequired.size());
    if (rest.size() > 1 && rest[0] == '-' && isWord(rest)) return std::string(rest) + ": is required";
  }
  constexpr std::string_view atMostOne = ": At Most 1 required but received ";
  if (const std::size_t at = text.find(atMostOne); at != std::string::npos) {
    const std::string_view name = std::string_view(text).substr(0, at);
    const std::string_view count = std::string_view(text).substr(at + atMostOne.size());
    if (isWord(name) && !count.empty() && count.find_first_not_of("0123456789") == std::string_view::npos)
      return std::string(name) + ": takes one value (given twice, or a value starting with '-')";
  }
  if (rest = text; consumePrefix(rest, "The following argument") &&
                   (consumePrefix(rest, " was") || consumePrefix(rest, "s were")) && consumePrefix(rest, " not expected: ")) {
    // CLI11 lists the leftover words: an unknown option and perhaps its value.
    std::istringstream words{std::string(rest)};
    for (std::string word; words >> word;)
      if (word.size() > 1 && word[0] == '-') return word + ": not an option of this command (see --help)";
    return "unexpected argument " + std::string(rest) + " (see --help)";
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
