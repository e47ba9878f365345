#pragma once
// JSON files (animation scripts, --config files) that do not parse: the parser's own message
// names its library and error code; users see the file, line and what is wrong instead.
#include <string>

#include "pak/error.hpp"

namespace pak {

// From nlohmann::json's parse_error::what() (e.g. "[json.exception.parse_error.101] parse
// error at line 2, column 5: syntax error …"): InputError("FILE", "not valid JSON at line 2,
// column 5: syntax error …").
InputError jsonSyntaxError(const std::string& file, const std::string& parserMessage);

}  // namespace pak
