#include "input_warnings.hpp"

#include <cstdio>
#include <set>
#include <string>
#include <utility>

namespace pak::cli {

void printInputWarnings(const Scene& scene, std::initializer_list<const Library*> libraries) {
  // An element carries its document's warnings, so the elements of one file repeat them.
  std::set<std::pair<std::string, std::string>> printed;
  auto print = [&](const std::vector<Warning>& warnings) {
    for (const Warning& w : warnings)
      if (printed.emplace(w.where, w.message).second)
        std::fprintf(stderr, "pak: warning: %s%s%s\n", w.where.c_str(), w.where.empty() ? "" : ": ", w.message.c_str());
  };
  auto printLibrary = [&](const Library& library) {
    for (const ElementArt& element : library) print(element.warnings);
  };
  print(scene.warnings);
  for (const Library* library : libraries) printLibrary(*library);
  for (const ContainerPart& part : scene.containers) printLibrary(part.library);
}

}  // namespace pak::cli
