#include "option_table.hpp"


#include "pak/io/text_file.hpp"

namespace pak::cli {

nlohmann::json readConfigObject(const std::string& file) {
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(readTextFile(file));
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(file, std::string("not valid JSON: ") + e.what());
  }
  if (!json.is_object()) throw InputError(file, "expected a JSON object of option names to values");
  return json;
}

void assignConfigValue(double& target, const nlohmann::json& value, const std::string& key, const std::string& file) {
  if (!value.is_number()) throw InputError(file, "\"" + key + "\" must be a number");
  target = value.get<double>();
}

void assignConfigValue(int& target, const nlohmann::json& value, const std::string& key, const std::string& file) {
  if (!value.is_number_integer()) throw InputError(file, "\"" + key + "\" must be an integer");
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
