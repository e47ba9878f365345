#pragma once
// Source markup an output copies as it is (a scene's `fixed` layer, its other layers): Pak
// never re-formats it.
#include <string>
#include <utility>
#include <vector>

namespace pak {

// Well-formed XML elements, with the definitions they reference and the namespaces their
// names use.
struct RawMarkup {
  std::string content;  // elements, byte for byte from the input
  // The gradients, clip paths, symbols … the content references and does not hold, each one
  // element byte for byte, so that outputs copying several markups from one file write each once.
  std::vector<std::string> definitions;
  std::vector<std::pair<std::string, std::string>> namespaces;  // prefix, URI (for xmlns:prefix)
  bool empty() const { return content.empty(); }
  friend bool operator==(const RawMarkup&, const RawMarkup&) = default;
};

}  // namespace pak
