#include "io/xml_nesting.hpp"

#include <algorithm>
#include <string>

#include "pak/error.hpp"

namespace pak {

void checkXmlNesting(std::string_view text, const std::string& file, int maxDepth) {
  int depth = 0;
  std::size_t at = 0;
  // Past `end`, searched from `from`; the end of the text when it is missing.
  auto skipPast = [&](std::size_t from, std::string_view end) {
    const std::size_t found = text.find(end, from);
    return found == std::string_view::npos ? text.size() : found + end.size();
  };
  while ((at = text.find('<', at)) != std::string_view::npos) {
    const std::string_view rest = text.substr(at);
    if (rest.starts_with("<!--")) { at = skipPast(at + 4, "-->"); continue; }
    if (rest.starts_with("<![CDATA[")) { at = skipPast(at + 9, "]]>"); continue; }
    if (rest.starts_with("<?")) { at = skipPast(at + 2, "?>"); continue; }
    // The tag's end: the first '>' outside quotes (and, for <!DOCTYPE, outside its [ ] subset).
    char quote = 0;
    int brackets = 0;
    std::size_t end = at + 1;
    for (; end < text.size(); ++end) {
      const char c = text[end];
      if (quote) { if (c == quote) quote = 0; }
      else if (c == '"' || c == '\'') quote = c;
      else if (c == '[') ++brackets;
      else if (c == ']') --brackets;
      else if (c == '>' && brackets <= 0) break;
    }
    if (rest.starts_with("</")) {
      depth = std::max(0, depth - 1);
    } else if (!rest.starts_with("<!")) {
      // An empty element (<rect/>) is as deep as one with children: counted the same way as
      // the check after <use> expansion counts it, so both limits agree.
      if (depth + 1 > maxDepth) {
        const auto line = std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n') + 1;
        throw InputError(file + ":" + std::to_string(line),
                         "elements nested more than " + std::to_string(maxDepth) + " deep; flatten the groups");
      }
      if (!(end < text.size() && text[end - 1] == '/')) ++depth;
    }
    at = end;
  }
}

}  // namespace pak
