#include "pak/io/json_syntax_error.hpp"

#include <cctype>
#include <string_view>

#include "pak/io/message_text.hpp"

namespace pak {
namespace {

// The leading digits of `text`, dropped from it (empty when it starts with none).
std::string_view digits(std::string_view& text) {
  std::size_t n = 0;
  while (n < text.size() && std::isdigit(static_cast<unsigned char>(text[n]))) ++n;
  const std::string_view result = text.substr(0, n);
  text.remove_prefix(n);
  return result;
}

}  // namespace

// Read with prefix tests (consumePrefix): the "last read" token of a long bad string is long.
InputError jsonSyntaxError(const std::string& file, const std::string& parserMessage) {
  std::string_view text = parserMessage;
  // "[json.exception.<kind>.<code>] "
  const std::size_t tagEnd = text.find("] ");
  if (!text.starts_with("[json.exception.") || tagEnd == std::string_view::npos) return InputError(file, "not valid JSON");
  text.remove_prefix(tagEnd + 2);
  std::string_view located = text;
  consumePrefix(located, "parse error ");
  if (consumePrefix(located, "at line ")) {
    const std::string_view line = digits(located);
    std::string_view column;
    if (!line.empty() && consumePrefix(located, ", column ") && !(column = digits(located)).empty() &&
        consumePrefix(located, ": "))
      return InputError(file, "not valid JSON at line " + std::string(line) + ", column " + std::string(column) + ": " +
                                  std::string(located));
  }
  consumePrefix(text, "parse error: ");
  return InputError(file, "not valid JSON: " + std::string(text));
}

}  // namespace pak
