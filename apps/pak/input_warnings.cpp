#include "input_warnings.hpp"

#include <cstdio>
#include <set>
#include <string>
#include <utility>

#include "pak/io/message_text.hpp"

namespace pak::cli {

void printInputWarnings(const std::vector<Warning>& sceneWarnings,
                        std::initializer_list<const std::vector<LoadedElement>*> elements) {
  // An element carries its document's warnings, so the elements of one file repeat them.
  std::set<std::pair<std::string, std::string>> printed;
  auto print = [&](const std::vector<Warning>& warnings) {
    for (const Warning& w : warnings)
      if (printed.emplace(w.where, w.message).second)
        std::fprintf(stderr, "pak: warning: %s\n", oneLine(w.where.empty() ? w.message : w.where + ": " + w.message).c_str());
  };
  print(sceneWarnings);
  for (const std::vector<LoadedElement>* list : elements)
    for (const LoadedElement& element : *list) print(element.warnings);
}

}  // namespace pak::cli
