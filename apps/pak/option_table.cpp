#include "option_table.hpp"

#include "pak/io/text_file.hpp"

namespace pak::cli {

ConfigKey booleanKey(std::string name, bool& target) {
  return {name, [name, &target](const nlohmann::json& value, const std::string& file) {
            if (!value.is_boolean()) throw InputError(file, "\"" + name + "\" must be true or false");
            target = value.get<bool>();
          }};
}

ConfigKey stringKey(std::string name, std::string& target) {
  return {name, [name, &target](const nlohmann::json& value, const std::string& file) {
            if (!value.is_string()) throw InputError(file, "\"" + name + "\" must be a string");
            target = value.get<std::string>();
          }};
}

ConfigKey seedKey(std::string name, std::uint64_t& target) {
  return {name, [name, &target](const nlohmann::json& value, const std::string& file) {
            if (!value.is_number_unsigned()) throw InputError(file, "\"" + name + "\" must be a non-negative integer");
            target = value.get<std::uint64_t>();
          }};
}

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

}  // namespace pak::cli
