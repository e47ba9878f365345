#include "pak/io/json_syntax_error.hpp"

#include <regex>

namespace pak {

InputError jsonSyntaxError(const std::string& file, const std::string& parserMessage) {
  static const std::regex located(R"(^\[json\.exception\.[a-z_]+\.\d+\] (?:parse error )?at line (\d+), column (\d+): (.*)$)");
  static const std::regex coded(R"(^\[json\.exception\.[a-z_]+\.\d+\] (?:parse error: )?(.*)$)");
  std::smatch match;
  if (std::regex_match(parserMessage, match, located))
    return InputError(file, "not valid JSON at line " + match[1].str() + ", column " + match[2].str() + ": " +
                                match[3].str());
  if (std::regex_match(parserMessage, match, coded)) return InputError(file, "not valid JSON: " + match[1].str());
  return InputError(file, "not valid JSON");
}

}  // namespace pak
