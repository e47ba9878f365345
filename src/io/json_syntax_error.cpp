#include "pak/io/json_syntax_error.hpp"

#include <cctype>
#include <string_view>

namespace pak {
namespace {

// Whether `text` starts with `prefix`; if so, drops it.
bool consume(std::string_view& text, std::string_view prefix) {
  if (text.substr(0, prefix.size()) != prefix) return false;
  text.remove_prefix(prefix.size());
  return true;
}

// The leading digits of `text`, dropped from it (empty when it starts with none).
std::string_view digits(std::string_view& text) {
  std::size_t n = 0;
  while (n < text.size() && std::isdigit(static_cast<unsigned char>(text[n]))) ++n;
  const std::string_view result = text.substr(0, n);
  text.remove_prefix(n);
  return result;
}

}  // namespace

// Read with plain prefix tests, not std::regex: libstdc++'s regex recurses once per character
// and overflows the stack on the long "last read" token of a long bad string.
InputError jsonSyntaxError(const std::string& file, const std::string& parserMessage) {
  std::string_view text = parserMessage;
  // "[json.exception.<kind>.<code>] "
  const std::size_t tagEnd = text.find("] ");
  if (!consume(text, "[json.exception.") || tagEnd == std::string_view::npos) return InputError(file, "not valid JSON");
  text = std::string_view(parserMessage).substr(tagEnd + 2);
  std::string_view located = text;
  consume(located, "parse error ");
  if (consume(located, "at line ")) {
    const std::string_view line = digits(located);
    std::string_view column;
    if (!line.empty() && consume(located, ", column ") && !(column = digits(located)).empty() && consume(located, ": "))
      return InputError(file, "not valid JSON at line " + std::string(line) + ", column " + std::string(column) + ": " +
                                  std::string(located));
  }
  consume(text, "parse error: ");
  return InputError(file, "not valid JSON: " + std::string(text));
}

}  // namespace pak
