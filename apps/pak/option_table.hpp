#pragma once
// A subcommand's tunable options, each declared once: its flag (and hidden old spellings), the
// member it sets, and from that the --config key and the report's "parameters" key, which
// are the flag's name without "--".
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <sstream>
#include <set>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "length_units.hpp"
#include "pak/error.hpp"

namespace pak::cli {

// A member of Root, reached through member pointers: field(&A::b, &B::c) reaches a.b.c.
template <class Root, class Value>
struct Field {
  std::function<Value&(Root&)> get;
  std::function<const Value&(const Root&)> read;
};

namespace detail {
template <class T>
T& follow(T& value) {
  return value;
}
template <class T, class Class, class Member, class... Rest>
auto& follow(T& value, Member Class::*member, Rest... rest) {
  return follow(value.*member, rest...);
}
}  // namespace detail

template <class Root, class Member, class... Rest>
auto field(Member Root::*first, Rest... rest) {
  using Value = std::remove_reference_t<decltype(detail::follow(std::declval<Root&>(), first, rest...))>;
  return Field<Root, Value>{[=](Root& root) -> Value& { return detail::follow(root, first, rest...); },
                            [=](const Root& root) -> const Value& { return detail::follow(root, first, rest...); }};
}

// `inner` of the member `outer` reaches.
template <class Root, class Middle, class Value>
Field<Root, Value> nested(const Field<Root, Middle>& outer, const Field<Middle, Value>& inner) {
  return {[=](Root& root) -> Value& { return inner.get(outer.get(root)); },
          [=](const Root& root) -> const Value& { return inner.read(outer.read(root)); }};
}

// A length option (a double in canonical units): given as a bare number, or with a unit
// (length_units.hpp) that OptionTable::resolveLengths turns into canonical units.
template <class Root>
struct LengthField {
  Field<Root, double> value;
};

template <class Root, class Member, class... Rest>
LengthField<Root> length(Member Root::*first, Rest... rest) {
  return {field(first, rest...)};
}

template <class Root, class Middle>
LengthField<Root> nested(const Field<Root, Middle>& outer, const LengthField<Middle>& inner) {
  return {nested(outer, inner.value)};
}

// The member a binding sets, whatever kind of option it is.
template <class Root, class Value>
const Field<Root, Value>& valueField(const Field<Root, Value>& f) {
  return f;
}
template <class Root>
const Field<Root, double>& valueField(const LengthField<Root>& f) {
  return f.value;
}

template <class Root>
struct Option {
  using Binding = std::variant<Field<Root, double>, Field<Root, int>, Field<Root, bool>, Field<Root, std::string>,
                               Field<Root, std::uint64_t>, LengthField<Root>>;
  std::string name;  // without "--"
  Binding field;
  std::string help;
  std::vector<std::string> aliases = {};  // old names, accepted on the command line and in --config, not shown
};

// "" for the text of an integer from 0 to 2^64 − 1 (CLI11 reads "-1" as 2^64 − 1 and
// saturates larger numbers), else what is wrong.
std::string nonNegativeInteger(const std::string& text);

// Reads `file`: a JSON object, else an InputError naming the file (and line).
nlohmann::json readConfigObject(const std::string& file);
// Sets `target` from a --config value, or throws InputError naming the file and key.
void assignConfigValue(double& target, const nlohmann::json& value, const std::string& key, const std::string& file);
void assignConfigValue(int& target, const nlohmann::json& value, const std::string& key, const std::string& file);
void assignConfigValue(bool& target, const nlohmann::json& value, const std::string& key, const std::string& file);
void assignConfigValue(std::string& target, const nlohmann::json& value, const std::string& key,
                       const std::string& file);
void assignConfigValue(std::uint64_t& target, const nlohmann::json& value, const std::string& key,
                       const std::string& file);
// A length: a number, or a string with a unit, recorded in `given` under `name`.
void assignConfigLength(double& target, GivenLengths* given, const std::string& name, const nlohmann::json& value,
                        const std::string& key, const std::string& file);
// Parses a length option's value into `target`, recording a unit in `given` (CLI11 callback).
void setLength(double& target, GivenLengths* given, const std::string& name, const std::string& text);

template <class Root>
class OptionTable {
 public:
  OptionTable(std::initializer_list<Option<Root>> options) : options_(options) {}
  explicit OptionTable(std::vector<Option<Root>> options) : options_(std::move(options)) {}

  const std::vector<Option<Root>>& options() const { return options_; }

  OptionTable operator+(const OptionTable& more) const {
    std::vector<Option<Root>> all = options_;
    all.insert(all.end(), more.options_.begin(), more.options_.end());
    return OptionTable(std::move(all));
  }

  // Every option as a CLI11 option (a flag for bool) bound to its member of `root`; length
  // options given with a unit are recorded in `given` (see resolveLengths).
  void addTo(CLI::App& command, Root& root, GivenLengths* lengths = nullptr) const {
    for (const Option<Root>& o : options_)
      std::visit(
          [&](const auto& f) {
            if constexpr (std::is_same_v<std::decay_t<decltype(f)>, LengthField<Root>>)
              addLengthOption(command, o, f.value.get(root), lengths);
            else
              addOption(command, o, f.get(root));
          },
          o.field);
  }

  // Turns the lengths given with a unit into canonical units, once the scene is known.
  void resolveLengths(Root& root, const GivenLengths& lengths, const LengthScale& scale) const {
    for (const Option<Root>& o : options_)
      if (const auto* f = std::get_if<LengthField<Root>>(&o.field); f && lengths.count(o.name)) {
        std::string problem;
        if (const std::optional<ParsedLength> length = parseLength(lengths.at(o.name), problem))
          f->value.get(root) = toCanonical(*length, scale);
      }
  }

  // Whether the command line gave the option, under its name or an alias.
  bool given(const CLI::App& command, const Option<Root>& o) const {
    if (command.count("--" + o.name) > 0) return true;
    for (const std::string& alias : o.aliases)
      if (command.count("--" + alias) > 0) return true;
    return false;
  }

  // Reads the --config `file` into `root`, except the options the command line gave (it wins).
  // Returns the names of the options the file set. Unknown keys, a key given twice (as a name
  // and an alias) and values of the wrong type are InputErrors naming the file.
  std::set<std::string> applyConfig(const std::string& file, const CLI::App& command, Root& root,
                                    GivenLengths* lengths = nullptr) const {
    return applyConfigObject(readConfigObject(file), file, command, root, lengths);
  }

  // As applyConfig, from a JSON object already read (the Python module's keyword arguments);
  // errors name `file`, where the object came from.
  std::set<std::string> applyConfigObject(const nlohmann::json& json, const std::string& file, const CLI::App& command,
                                          Root& root, GivenLengths* lengths = nullptr) const {
    std::map<std::string, std::string> keyOf;  // option name → the key that set it
    for (const auto& item : json.items()) {
      // Named, not a structured binding: the visitor captures them (clang 14 cannot capture one).
      const std::string& key = item.key();
      const nlohmann::json& value = item.value();
      const Option<Root>* o = find(key);
      if (!o) throw InputError(file, "unknown option \"" + key + "\"");
      if (given(command, *o)) continue;
      if (const auto [at, fresh] = keyOf.emplace(o->name, key); !fresh)
        throw InputError(file, "\"" + at->second + "\" and \"" + key + "\" are the same option");
      std::visit(
          [&](const auto& f) {
            if constexpr (std::is_same_v<std::decay_t<decltype(f)>, LengthField<Root>>)
              assignConfigLength(f.value.get(root), lengths, o->name, value, key, file);
            else
              assignConfigValue(f.get(root), value, key, file);
          },
          o->field);
    }
    std::set<std::string> set;
    for (const auto& entry : keyOf) set.insert(entry.first);
    return set;
  }

  // The report's "parameters": every option's name and value.
  void report(nlohmann::json& parameters, const Root& root) const {
    for (const Option<Root>& o : options_)
      std::visit([&](const auto& f) { parameters[o.name] = valueField(f).read(root); }, o.field);
  }

  // Copies each option's value from `from` into `to`, except where keep(option) holds.
  template <class Keep>
  void copyUnless(Root& to, const Root& from, const Keep& keep) const {
    for (const Option<Root>& o : options_)
      if (!keep(o)) std::visit([&](const auto& f) { valueField(f).get(to) = valueField(f).read(from); }, o.field);
  }

 private:
  template <class Value>
  static void addOption(CLI::App& command, const Option<Root>& o, Value& target) {
    auto add = [&](const std::string& name, const std::string& help) {
      if constexpr (std::is_same_v<Value, bool>)
        return command.add_flag("--" + name, target, help);
      else
        return command.add_option("--" + name, target, help)->capture_default_str();
    };
    CLI::Option* primary = add(o.name, o.help);
    if constexpr (std::is_same_v<Value, std::uint64_t>) primary->check(CLI::Validator(nonNegativeInteger, ""));
    addAliases(o, primary, add);
  }

  static void addLengthOption(CLI::App& command, const Option<Root>& o, double& target, GivenLengths* lengths) {
    std::ostringstream shown;
    shown << target;
    auto add = [&](const std::string& name, const std::string& help) {
      return command
          .add_option_function<std::string>(
              "--" + name, [&target, lengths, key = o.name](const std::string& text) { setLength(target, lengths, key, text); },
              help)
          ->type_name("LENGTH")
          ->default_str(shown.str());
    };
    addAliases(o, add(o.name, o.help), add);
  }

  // Hidden, and checked here rather than with CLI11's excludes(), which would print the
  // alias's (hidden) name in the primary's help.
  template <class Add>
  static void addAliases(const Option<Root>& o, CLI::Option* primary, const Add& add) {
    for (const std::string& alias : o.aliases)
      add(alias, "old name of --" + o.name)->group("")->check(CLI::Validator(
          [primary, alias](const std::string&) {
            return primary->count() > 0 ? "--" + alias + ": the same option as " + primary->get_name() + ", given too"
                                        : std::string();
          },
          ""));
  }

  const Option<Root>* find(const std::string& key) const {
    for (const Option<Root>& o : options_) {
      if (o.name == key) return &o;
      for (const std::string& alias : o.aliases)
        if (alias == key) return &o;
    }
    return nullptr;
  }

  std::vector<Option<Root>> options_;
};

// The options of `table`, on the member `at` of Root.
template <class Root, class Sub>
OptionTable<Root> mounted(const OptionTable<Sub>& table, const Field<Root, Sub>& at) {
  std::vector<Option<Root>> options;
  for (const Option<Sub>& o : table.options()) {
    auto binding = [&](const auto& f) -> typename Option<Root>::Binding { return nested(at, f); };
    options.push_back({o.name, std::visit(binding, o.field), o.help, o.aliases});
  }
  return OptionTable<Root>(std::move(options));
}

}  // namespace pak::cli
