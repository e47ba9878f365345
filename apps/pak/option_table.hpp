#pragma once
// A subcommand's tunable options, listed once: the same name is the command-line flag, the
// key in a --config file and the key in the report.
#include <functional>
#include <nlohmann/json.hpp>
#include <set>
#include <span>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "pak/error.hpp"

namespace pak::cli {

template <class Options>
struct NumberOption {
  const char* name;
  double Options::*field;
  const char* help;
};
template <class Options>
struct IntegerOption {
  const char* name;
  int Options::*field;
  const char* help;
};

template <class Options>
struct OptionTable {
  std::span<const NumberOption<Options>> numbers;
  std::span<const IntegerOption<Options>> integers;

  void addTo(CLI::App& command, Options& options) const {
    for (const auto& o : numbers) command.add_option(std::string("--") + o.name, options.*o.field, o.help)->capture_default_str();
    for (const auto& o : integers) command.add_option(std::string("--") + o.name, options.*o.field, o.help)->capture_default_str();
  }
  void report(nlohmann::json& parameters, const Options& options) const {
    for (const auto& o : numbers) parameters[o.name] = options.*o.field;
    for (const auto& o : integers) parameters[o.name] = options.*o.field;
  }
  // Copies into `options` what `from` holds for every option not in `keep`.
  template <class Keep>
  void copyUnless(Options& options, const Options& from, Keep&& keep) const {
    for (const auto& o : numbers)
      if (!keep(o.name)) options.*o.field = from.*o.field;
    for (const auto& o : integers)
      if (!keep(o.name)) options.*o.field = from.*o.field;
  }
};

// A --config key outside the table: its name and what sets it (throwing InputError, with the
// file's name, when the JSON value has the wrong type).
struct ConfigKey {
  std::string name;
  std::function<void(const nlohmann::json& value, const std::string& file)> set;
};
ConfigKey booleanKey(std::string name, bool& target);
ConfigKey stringKey(std::string name, std::string& target);
ConfigKey seedKey(std::string name, std::uint64_t& target);

// The options of a second table as extra --config keys (for a command whose options come in
// two structs).
template <class Options>
std::vector<ConfigKey> tableKeys(const OptionTable<Options>& table, Options& options) {
  std::vector<ConfigKey> keys;
  for (const auto& o : table.numbers)
    keys.push_back({o.name, [&options, o](const nlohmann::json& value, const std::string& file) {
                      if (!value.is_number()) throw InputError(file, std::string("\"") + o.name + "\" must be a number");
                      options.*o.field = value.template get<double>();
                    }});
  for (const auto& o : table.integers)
    keys.push_back({o.name, [&options, o](const nlohmann::json& value, const std::string& file) {
                      if (!value.is_number_integer()) throw InputError(file, std::string("\"") + o.name + "\" must be an integer");
                      options.*o.field = value.template get<int>();
                    }});
  return keys;
}

// Reads `file`, a JSON object of option names to values, into the table's options and the
// extra keys. Options given on the command line win: their keys are skipped. Returns the keys
// the file set. Unknown keys, wrong types and bad JSON are InputErrors.
nlohmann::json readConfigObject(const std::string& file);
template <class Options>
std::set<std::string> applyConfigFile(const std::string& file, const CLI::App& command, const OptionTable<Options>& table,
                                      Options& options, const std::vector<ConfigKey>& extra) {
  std::set<std::string> set;
  const nlohmann::json json = readConfigObject(file);
  for (auto& [key, value] : json.items()) {
    bool known = false;
    for (const auto& o : table.numbers) known |= key == o.name;
    for (const auto& o : table.integers) known |= key == o.name;
    for (const ConfigKey& k : extra) known |= key == k.name;
    if (!known) throw InputError(file, "unknown option \"" + key + "\"");
    if (command.count("--" + key) > 0) continue;  // the command line wins
    for (const auto& o : table.numbers)
      if (key == o.name) {
        if (!value.is_number()) throw InputError(file, "\"" + key + "\" must be a number");
        options.*o.field = value.template get<double>();
      }
    for (const auto& o : table.integers)
      if (key == o.name) {
        if (!value.is_number_integer()) throw InputError(file, "\"" + key + "\" must be an integer");
        options.*o.field = value.template get<int>();
      }
    for (const ConfigKey& k : extra)
      if (key == k.name) k.set(value, file);
    set.insert(key);
  }
  return set;
}

}  // namespace pak::cli
