#include "option_table.hpp"

#include <charconv>
#include <cstdint>
#include <limits>

#include "pak/io/json_syntax_error.hpp"
#include "pak/io/text_file.hpp"

namespace pak::cli {

std::string nonNegativeInteger(const std::string& text) {
  std::uint64_t value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (error == std::errc::result_out_of_range) return "must be at most " + std::to_string(UINT64_MAX);
  if (error != std::errc() || stop != end) return "must be a non-negative integer";
  return "";
}

nlohmann::json readConfigObject(const std::string& file) {
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(readTextFile(file));
  } catch (const nlohmann::json::exception& e) {
    throw jsonSyntaxError(file, e.what());
  }
  if (!json.is_object()) throw InputError(file, "expected a JSON object of option names to values");
  return json;
}

void assignConfigValue(double& target, const nlohmann::json& value, const std::string& key, const std::string& file) {
  if (!value.is_number()) throw InputError(file, "\"" + key + "\" must be a number");
  target = value.get<double>();
}

namespace {

// Sets `target` from a length's text and records a unit in `given`; "" or what is wrong.
std::string takeLength(double& target, GivenLengths* given, const std::string& name, const std::string& text) {
  std::string problem;
  const std::optional<ParsedLength> length = parseLength(text, problem);
  if (!length) return problem;
  target = length->number;
  if (given && length->unit.empty()) given->erase(name);
  else if (given) (*given)[name] = text;
  return "";
}

}  // namespace

void assignConfigLength(double& target, GivenLengths* given, const std::string& name, const nlohmann::json& value,
                        const std::string& key, const std::string& file) {
  if (value.is_number()) {
    target = value.get<double>();
    if (given) given->erase(name);
    return;
  }
  if (!value.is_string()) throw InputError(file, "\"" + key + "\" must be a length: a number, or a string such as \"2mm\"");
  if (const std::string problem = takeLength(target, given, name, value.get<std::string>()); !problem.empty())
    throw InputError(file, "\"" + key + "\": " + problem);
}

void setLength(double& target, GivenLengths* given, const std::string& name, const std::string& text) {
  if (const std::string problem = takeLength(target, given, name, text); !problem.empty())
    throw CLI::ValidationError("--" + name, problem);
}

void assignConfigValue(int& target, const nlohmann::json& value, const std::string& key, const std::string& file) {
  if (!value.is_number_integer()) throw InputError(file, "\"" + key + "\" must be an integer");
  constexpr std::int64_t low = std::numeric_limits<int>::min(), high = std::numeric_limits<int>::max();
  const bool fits = value.is_number_unsigned() ? value.get<std::uint64_t>() <= static_cast<std::uint64_t>(high)
                                               : value.get<std::int64_t>() >= low && value.get<std::int64_t>() <= high;
  if (!fits) throw InputError(file, "\"" + key + "\" is out of range for an integer option");
  target = value.get<int>();
}

void assignConfigValue(bool& target, const nlohmann::json& value, const std::string& key, const std::string& file) {
  if (!value.is_boolean()) throw InputError(file, "\"" + key + "\" must be true or false");
  target = value.get<bool>();
}

void assignConfigValue(std::string& target, const nlohmann::json& value, const std::string& key,
                       const std::string& file) {
  if (!value.is_string()) throw InputError(file, "\"" + key + "\" must be a string");
  target = value.get<std::string>();
}

void assignConfigValue(std::uint64_t& target, const nlohmann::json& value, const std::string& key,
                       const std::string& file) {
  if (!value.is_number_unsigned()) throw InputError(file, "\"" + key + "\" must be a non-negative integer");
  target = value.get<std::uint64_t>();
}

}  // namespace pak::cli
