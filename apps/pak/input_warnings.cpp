#include "input_warnings.hpp"

#include <cstdio>
#include <string>

#include "pak/io/warning_lines.hpp"

namespace pak::cli {

void printInputWarnings(const std::vector<Warning>& sceneWarnings,
                        std::initializer_list<const std::vector<LoadedElement>*> elements) {
  std::vector<Warning> all = sceneWarnings;
  for (const std::vector<LoadedElement>* list : elements)
    for (const LoadedElement& element : *list) all.insert(all.end(), element.warnings.begin(), element.warnings.end());
  for (const std::string& line : warningLines(all)) std::fprintf(stderr, "pak: warning: %s\n", line.c_str());
}

}  // namespace pak::cli
