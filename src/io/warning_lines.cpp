#include "pak/io/warning_lines.hpp"

#include <set>
#include <utility>

#include "pak/io/message_text.hpp"

namespace pak {

std::vector<std::string> warningLines(const std::vector<Warning>& warnings) {
  std::set<std::pair<std::string, std::string>> said;
  std::vector<std::string> lines;
  for (const Warning& w : warnings)
    if (said.emplace(w.where, w.message).second)
      lines.push_back(oneLine(w.where.empty() ? w.message : w.where + ": " + w.message));
  return lines;
}

}  // namespace pak
